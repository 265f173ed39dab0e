// A body's box room: at pose (center, q) every box of the body lay inside its fat AABB, with room
// to spare below and above it on each axis (the least over its boxes). Until its proxies, shapes or
// centre of mass change, its boxes at another pose are inside too while they stray less than that:
// a point at ℓ from the centre of mass moves by Δc + (q₁ − q₀)ℓ between two poses (q as the
// complex number c + i s), so each coordinate by Δc's plus at most |q₁ − q₀|·reach, where reach is
// the farthest point that places a box (a circle's centre, a vertex: CollisionSystem::turningReach).
// A fat AABB is longest ahead of a moving body, and the room on each side is counted apart. One
// measurement spares the boxes of many steps while a body rests or drifts (refit_ahead.cpp).
#pragma once

#include <cmath>

#include "perpdot/math.hpp"

namespace perpdot {

struct BoxRoom {
    Vec2 center;
    Rot q;
    float reach = -1;           // of its shapes' box-placing points about the centre of mass; negative: not known
    Vec2 below{-1.0f, -1.0f};   // room under the boxes' lower sides (x, y); negative: not measured
    Vec2 above{-1.0f, -1.0f};   // room over their upper sides
    // Known with reach, what continuous collision asks of the same shapes (isFast): a step's move
    // longer than fastTravel may tunnel (half the least extent of its swept shapes; infinite when
    // none sweeps), and no point of a swept shape lies farther than sweepRadius from the centre of mass.
    float fastTravel = 0, sweepRadius = 0;

    // Whether the boxes at pose (c, r) are inside by this bound. The sum of the components' sizes
    // bounds |q₁ − q₀|; 1e-5 of the coordinates covers the rounding of the boxes' float operations.
    bool holds(Vec2 c, Rot r) const {
        if (below.x < 0.0f) return false;  // (then reach may be unknown too: negative)
        const float spare = reach * (std::fabs(r.c - q.c) + std::fabs(r.s - q.s)) +
                            1e-5f * (1.0f + std::fabs(c.x) + std::fabs(c.y) + reach);
        const Vec2 d = c - center;
        return spare <= below.x + d.x && spare <= above.x - d.x && spare <= below.y + d.y && spare <= above.y - d.y;
    }
};

}  // namespace perpdot
