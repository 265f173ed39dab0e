/// @file
/// World queries: ray casts, AABB, point and shape overlap, each filtered like collision
/// (a shape is reported when shouldCollide(queryFilter, shape's filter)).
#pragma once

#include "perpdot/ids.hpp"
#include "perpdot/math.hpp"

namespace perpdot {

/// A ray P(t) = origin + t·translation hit a shape at fraction t ∈ [0, 1].
struct RayHit {
    ShapeId shape;  ///< the shape hit
    Vec2 point;     ///< world
    Vec2 normal;    ///< the surface normal at the point, facing the ray
    float fraction = 0.0f;  ///< t of the hit point along the translation
};

}  // namespace perpdot
