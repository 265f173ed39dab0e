// Persistent manifolds: a contact whose two bodies have barely moved relative to each other since
// its last narrowphase keeps that manifold — its normal and anchors — and only its
// separations follow the motion, as they do between substeps:
//   s = s₀ + ((cB − cA) + R(ΔθB) rB − R(ΔθA) rA) · n
// A manifold rebuilt every step follows every small tilt of the bodies: the normal turns with one
// body and the points move with the other's corners, and in a tall stack that feedback grows
// into a bending mode that topples it (docs/stress.md, "Why tall stacks fell"). Box2D v3.2
// keeps manifolds the same way ("contact recycling").
#pragma once

#include "core/bodies/body_store.hpp"
#include "core/contacts/contact_cache.hpp"

namespace perpdot {

// What may be kept, for one pair.
struct ReuseLimits {
    float distance = 0.0f;     // WorldDef::contactReuseDistance: travel of the farthest anchor
    float reach = 0.0f;        // of the two shapes from their bodies' origins, for a contact without points
    float margin = 0.0f;       // the collision skins: collide() reports points this far before the shapes touch
    float skinOffset = 0.0f;   // what collide() adds to Box2D's separations (0 on Box2D's skin)
};

// Updates `c`'s separations and points from the bodies' motion and returns true when the relative
// pose changed by less than the limits since the manifold was built — a contact without points
// then stays without, skipping the narrowphase; false (and `c` untouched) when it needs one.
bool reuseManifold(Contact& c, const Body& a, const Body& b, const ReuseLimits& limits);

// Remembers the bodies' pose and each point's separation for the new manifold of `c`; `keepable`
// false (a round surface takes part: its contact point is no point of the body) keeps it only
// while it has no points.
void rememberManifoldPose(Contact& c, const Body& a, const Body& b, bool keepable);

// R(θ₀) of the remembered angles, which a kept manifold turns its anchors back by, after a
// snapshot is read (the rotations are not saved; rememberManifoldPose copies the bodies' R(θ)).
inline void rememberReuseRotations(Contact& c) {
    c.reuseRotA = Rot::fromAngle(c.reuseAngleA);
    c.reuseRotB = Rot::fromAngle(c.reuseAngleB);
}

}  // namespace perpdot
