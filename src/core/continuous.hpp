// What the two continuous-collision passes share (continuous.cpp: fast bodies against static
// shapes; continuous_impacts.cpp: bullets against moving bodies).
#pragma once

#include <algorithm>

#include "core/world_impl.hpp"

namespace perpdot {

inline AABB combine(const AABB& a, const AABB& b) {
    return {{std::min(a.lower.x, b.lower.x), std::min(a.lower.y, b.lower.y)},
            {std::max(a.upper.x, b.upper.x), std::max(a.upper.y, b.upper.y)}};
}

// Solid shapes are swept; sensors and (massless) segments and chains on a moving body are not.
inline bool sweeps(const ShapeData& s) { return !s.sensor && s.minExtent > 0.0f; }

}  // namespace perpdot
