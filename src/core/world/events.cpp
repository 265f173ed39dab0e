// Contact, sensor and hit events raised by the step into the world's EventBuffers
// (event_buffers.hpp), which the World's calls read after it through spans (world.cpp).
#include <algorithm>
#include <cstddef>

#include "core/contacts/contact_cache.hpp"
#include "core/shapes/shape_store.hpp"
#include "core/solver/contact_solver.hpp"
#include "core/world/event_buffers.hpp"
#include "core/world/events.hpp"
#include "core/world/handle_check.hpp"
#include "core/world/step_scratch.hpp"

namespace perpdot {

ContactData contactData(const ShapeStore& shapes, const WorldIdentity& identity, const Contact& c) {
    ContactData d;
    d.shapeA = handleAt<ShapeId>(shapes, c.a.shape, identity);
    d.shapeB = handleAt<ShapeId>(shapes, c.b.shape, identity);
    d.normal = c.normal;
    d.pointCount = c.pointCount;
    for (int i = 0; i < c.pointCount; ++i) {
        const ContactPointState& p = c.points[i];
        d.points[i] = {p.point, p.separation, p.normalImpulse, p.tangentImpulse, p.id};
    }
    return d;
}

void reportTouch(EventBuffers& events, const ShapeStore& shapes, const WorldIdentity& identity, const Contact& c, bool begin) {
    const ShapeData& sa = shapes[c.a.shape];
    const ShapeData& sb = shapes[c.b.shape];
    const ShapeId a = handleAt<ShapeId>(shapes, c.a.shape, identity), b = handleAt<ShapeId>(shapes, c.b.shape, identity);
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
void reportHitEvents(EventBuffers& events, ContactScratch& rows, const ContactCache& cache, const ShapeStore& shapes,
                     const WorldIdentity& identity, float threshold) {
    if (!shapes.anyHitEvents) return;
    locateContactRows(rows);
    const std::vector<ImpactPoint>& impacts = rows.impacts.points;  // in constraint order
    size_t impact = 0;
    for (int k = 0; k < static_cast<int>(rows.constraints.size()); ++k) {
        while (impact < impacts.size() && impacts[impact].constraint < k) ++impact;
        const ContactConstraint& c = rows.constraints[k];
        const Contact& contact = cache.contacts[c.contact];
        if (!shapes[contact.a.shape].enableHitEvents && !shapes[contact.b.shape].enableHitEvents) continue;
        ContactHitEvent event{handleAt<ShapeId>(shapes, contact.a.shape, identity), handleAt<ShapeId>(shapes, contact.b.shape, identity), {},
                              contact.normal, threshold};
        bool hit = false;
        for (int i = 0; i < c.pointCount; ++i) {
            const float approachSpeed = -contactRowField(rows, k, offsetof(ContactRows<float>, relativeVelocity) / sizeof(float) + static_cast<std::size_t>(i));
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
        if (hit) events.contactHit.push_back(event);
    }
}

}  // namespace perpdot
