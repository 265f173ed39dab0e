// Contact, sensor and hit events raised by the step into the world's EventBuffers
// (event_buffers.hpp), and read after it through spans.
#include <algorithm>
#include <cstddef>

#include "core/solver/contact_solver.hpp"
#include "core/world/world_impl.hpp"

namespace perpdot {

ContactData World::Impl::contactData(const Contact& c) const {
    ContactData d;
    d.shapeA = shapeId(c.a.shape);
    d.shapeB = shapeId(c.b.shape);
    d.normal = c.normal;
    d.pointCount = c.pointCount;
    for (int i = 0; i < c.pointCount; ++i) {
        const ContactPointState& p = c.points[i];
        d.points[i] = {p.point, p.separation, p.normalImpulse, p.tangentImpulse, p.id};
    }
    return d;
}

void World::Impl::reportTouch(const Contact& c, bool begin) {
    const ShapeData& sa = shapes[c.a.shape];
    const ShapeData& sb = shapes[c.b.shape];
    const ShapeId a = shapeId(c.a.shape), b = shapeId(c.b.shape);
    if (c.sensor) {
        const ShapeId sensor = sa.sensor ? a : b, visitor = sa.sensor ? b : a;
        if (begin) events.sensorBegin.push_back({sensor, visitor});
        else events.sensorEnd.push_back({sensor, visitor});
    } else if (sa.enableContactEvents || sb.enableContactEvents) {
        if (begin) events.contactBegin.push_back({a, b});
        else events.contactEnd.push_back({a, b});
    }
}

// After the solve: a hit for every touching contact with hit events whose fastest point
// approached faster than the threshold and actually pushed (λn > 0 at some substep), or took an
// impact before the substeps (impact_propagation.cpp; its approach is then gone from the rows).
void reportHitEvents(World::Impl& w) {
    if (!w.shapes.anyHitEvents) return;
    locateContactRows(w.scratch.contacts);
    const std::vector<ImpactPoint>& impacts = w.scratch.contacts.impacts.points;  // in constraint order
    size_t impact = 0;
    for (int k = 0; k < static_cast<int>(w.scratch.contacts.constraints.size()); ++k) {
        while (impact < impacts.size() && impacts[impact].constraint < k) ++impact;
        const ContactConstraint& c = w.scratch.contacts.constraints[k];
        const Contact& contact = w.contactCache.contacts[c.contact];
        if (!w.shapes[contact.a.shape].enableHitEvents && !w.shapes[contact.b.shape].enableHitEvents) continue;
        ContactHitEvent event{w.shapeId(contact.a.shape), w.shapeId(contact.b.shape), {}, contact.normal, w.def.hitEventThreshold};
        bool hit = false;
        for (int i = 0; i < c.pointCount; ++i) {
            const float approachSpeed = -contactRowField(w.scratch.contacts, k, offsetof(ContactRows<float>, relativeVelocity) / sizeof(float) + static_cast<std::size_t>(i));
            if (approachSpeed > event.approachSpeed && contact.points[i].maxNormalImpulse > 0.0f) {
                event.approachSpeed = approachSpeed;
                event.point = contact.points[i].point;
                hit = true;
            }
        }
        for (; impact < impacts.size() && impacts[impact].constraint == k; ++impact) {
            const ImpactPoint& p = impacts[impact];
            if (p.impactSpeed > event.approachSpeed) {
                event.approachSpeed = p.impactSpeed;
                event.point = contact.points[p.point].point;
                hit = true;
            }
        }
        if (hit) w.events.contactHit.push_back(event);
    }
}

ContactEvents World::contactEvents() const {
    return {impl_->events.contactBegin, impl_->events.contactEnd, impl_->events.contactHit};
}

SensorEvents World::sensorEvents() const { return {impl_->events.sensorBegin, impl_->events.sensorEnd}; }

JointEvents World::jointEvents() const { return {impl_->events.jointBreak}; }

void World::setPreSolve(PreSolveFn callback) {
    checkUnlocked(impl_->locked, "setPreSolve");
    impl_->preSolve = std::move(callback);
}

}  // namespace perpdot
