// A body's box room: at pose (center, q) every box of the body lay inside its fat AABB with `room`
// to spare on every side. Until its proxies, shapes or centre of mass change, its boxes at any pose
// that strays less than that from it are inside too: a point at ℓ from the centre of mass moves by
// Δc + (q₁ − q₀)ℓ between two poses (q as the complex number c + i s), so by at most
// |Δc| + |q₁ − q₀|·reach, where reach is the farthest such point that places a box (a circle's
// centre, a vertex: CollisionSystem::turningReach). One measurement spares the boxes of many steps while a body rests or
// drifts (refit_ahead.cpp).
#pragma once

#include <cmath>

#include "perpdot/math.hpp"

namespace perpdot {

struct BoxRoom {
    Vec2 center;
    Rot q;
    float reach = -1;  // of its shapes' box-placing points about the centre of mass; negative: not known
    float room = -1;   // negative: not measured

    // Whether the boxes at pose (c, r) are inside by this bound. The sums of the components' sizes
    // bound the lengths; 1e-5 of the coordinates covers the rounding of the boxes' float operations.
    bool holds(Vec2 c, Rot r) const {
        if (room < 0.0f) return false;  // (then reach may be unknown too: negative)
        const float stray = std::fabs(c.x - center.x) + std::fabs(c.y - center.y) +
                            reach * (std::fabs(r.c - q.c) + std::fabs(r.s - q.s));
        const float rounding = 1e-5f * (1.0f + std::fabs(c.x) + std::fabs(c.y) + reach);
        return stray + rounding <= room;
    }
};

}  // namespace perpdot
