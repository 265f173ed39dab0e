// The speed limits against blow-ups, applied wherever velocities change position: the substep
// integration (integrate.cpp) and the impacts of continuous collision (continuous_impacts.cpp).
#pragma once

#include <algorithm>
#include <cmath>

#include "perpdot/math.hpp"

namespace perpdot {

// v scaled down to `maxSpeed` along its own direction. v·v overflows beyond 1.8e19 m/s: the
// direction then comes from v divided by its largest component first.
inline Vec2 clampSpeed(Vec2 v, float maxSpeed) {
    if (!(dot(v, v) > maxSpeed * maxSpeed)) return v;
    float len = length(v);
    if (!std::isfinite(len)) {
        v *= 1.0f / std::max(std::fabs(v.x), std::fabs(v.y));
        len = length(v);
    }
    return v * (maxSpeed / len);
}

// |ω| ≤ an eighth of a turn per substep of length hs: 0.25 π / hs.
inline float maxAngularSpeed(float invHs) { return 0.25f * pi * invHs; }
inline float clampAngularSpeed(float w, float maxSpeed) {
    return w * w > maxSpeed * maxSpeed ? w * (maxSpeed / std::fabs(w)) : w;
}

}  // namespace perpdot
