// Contact and sensor events: raised while step() runs, buffered without allocating once the
// buffers have grown, and read after the step through spans (Box2D v3's model).
#include <algorithm>

#include "core/world_impl.hpp"

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

// Called at the start of step(): the last step's events go; end events raised since (a shape or
// body destroyed between steps) stay, so they are reported by this step.
void World::Impl::beginEvents() {
    contactBeginEvents.clear();
    contactHitEvents.clear();
    jointBreakEvents.clear();
    sensorBeginEvents.clear();
    contactEndEvents.erase(contactEndEvents.begin(), contactEndEvents.begin() + static_cast<std::ptrdiff_t>(contactEndReported));
    sensorEndEvents.erase(sensorEndEvents.begin(), sensorEndEvents.begin() + static_cast<std::ptrdiff_t>(sensorEndReported));
}

void World::Impl::reportTouch(const Contact& c, bool begin) {
    const ShapeData& sa = shapes[c.a.shape];
    const ShapeData& sb = shapes[c.b.shape];
    const ShapeId a = shapeId(c.a.shape), b = shapeId(c.b.shape);
    if (c.sensor) {
        const ShapeId sensor = sa.sensor ? a : b, visitor = sa.sensor ? b : a;
        if (begin) sensorBeginEvents.push_back({sensor, visitor});
        else sensorEndEvents.push_back({sensor, visitor});
    } else if (sa.enableContactEvents || sb.enableContactEvents) {
        if (begin) contactBeginEvents.push_back({a, b});
        else contactEndEvents.push_back({a, b});
    }
}

// After the solve: a hit for every touching contact with hit events whose fastest point
// approached faster than the threshold and actually pushed (λn > 0 at some substep).
void reportHitEvents(World::Impl& w) {
    if (!w.shapes.anyHitEvents) return;
    for (const ContactConstraint& c : w.scratch.constraints) {
        const Contact& contact = w.contactCache.contacts[c.contact];
        if (!w.shapes[contact.a.shape].enableHitEvents && !w.shapes[contact.b.shape].enableHitEvents) continue;
        ContactHitEvent event{w.shapeId(contact.a.shape), w.shapeId(contact.b.shape), {}, c.normal, w.def.hitEventThreshold};
        bool hit = false;
        for (int i = 0; i < c.pointCount; ++i) {
            const float approachSpeed = -c.points[i].relativeVelocity;
            if (approachSpeed > event.approachSpeed && contact.points[i].maxNormalImpulse > 0.0f) {
                event.approachSpeed = approachSpeed;
                event.point = contact.points[i].point;
                hit = true;
            }
        }
        if (hit) w.contactHitEvents.push_back(event);
    }
}

ContactEvents World::contactEvents() const {
    return {impl_->contactBeginEvents, impl_->contactEndEvents, impl_->contactHitEvents};
}

SensorEvents World::sensorEvents() const { return {impl_->sensorBeginEvents, impl_->sensorEndEvents}; }

JointEvents World::jointEvents() const { return {impl_->jointBreakEvents}; }

void World::setPreSolve(PreSolveFn callback) {
    impl_->checkUnlocked("setPreSolve");
    impl_->preSolve = std::move(callback);
}

}  // namespace perpdot
