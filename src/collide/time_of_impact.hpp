// Time of impact by conservative advancement on b2Distance — perpdot's replacement for
// b2TimeOfImpact, whose b2SeparationFunction asserts (and aborts the process) when b2Distance
// returns a non-finite distance, which degenerate or extreme sweeps can cause.
#pragma once

#include <box2d/b2_distance.h>

#include "collide/collision.hpp"

namespace perpdot::collide {

// Fraction t in [0, 1] of the first time the cores of a and b (proxies in their body frames) come
// within Box2D's TOI target separation; 0 if they already are at the start, 1 if they never do or
// if the distance is not finite (a state the world freezes anyway).
float advanceToImpact(const b2DistanceProxy& a, const Sweep& sweepA, const b2DistanceProxy& b, const Sweep& sweepB);

}  // namespace perpdot::collide
