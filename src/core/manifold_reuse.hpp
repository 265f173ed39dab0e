// Persistent manifolds: a touching contact whose two bodies have barely moved relative to each
// other since its last narrowphase keeps that manifold — its normal and anchors — and only its
// separations follow the motion, as they do between substeps:
//   s = s₀ + ((cB − cA) + R(ΔθB) rB − R(ΔθA) rA) · n
// A manifold rebuilt every step follows every small tilt of the bodies: the normal turns with one
// body and the points move with the other's corners, and in a tall stack that feedback grows
// into a bending mode that topples it (docs/stress.md, "Why tall stacks fell"). Box2D v3.2
// keeps manifolds the same way ("contact recycling").
#pragma once

#include "core/world_impl.hpp"

namespace perpdot {

// Updates `c`'s separations and points from the bodies' motion and returns true when the relative
// pose changed by less than `tolerance` (m of travel of the farthest anchor) since the manifold
// was built; false (and `c` untouched) when it needs a new narrowphase.
bool reuseManifold(Contact& c, const Body& a, const Body& b, float tolerance);

// Remembers the bodies' pose and each point's separation for the new manifold of `c`; `keepable`
// false (a round surface takes part: its contact point is no point of the body) never keeps it.
void rememberManifoldPose(Contact& c, const Body& a, const Body& b, bool keepable);

}  // namespace perpdot
