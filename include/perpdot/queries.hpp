/// @file
/// World queries: ray casts, AABB, point and shape overlap, each filtered like collision
/// (a shape is reported when shouldCollide(queryFilter, shape's filter)).
#pragma once

#include <variant>

#include "perpdot/ids.hpp"
#include "perpdot/math.hpp"
#include "perpdot/shapes.hpp"

namespace perpdot {

/// A ray P(t) = origin + t·translation hit a shape at fraction t ∈ [0, 1].
struct RayHit {
    ShapeId shape{};  ///< the shape hit
    Vec2 point{};   ///< world
    Vec2 normal{};  ///< the surface normal at the point, facing the ray
    float fraction = 0.0f;  ///< t of the hit point along the translation
};

/// A radial impulse for World::explode. A shape of a dynamic body whose true surface comes within
/// `radius` of `position` takes the impulse impulse·(1 − d/radius) at its surface point nearest
/// the centre, d away, pointing from the centre to that point (from the centre to the body's centre
/// of mass when the centre is inside the shape): linear falloff, nothing at `radius` and beyond.
/// Off-centre points also spin the body: Δω = perpDot(p − c, J)/I.
struct ExplosionDef {
    Vec2 position{};               ///< the centre, world
    float radius = 1.0f;           ///< m, > 0
    float impulse = 1.0f;          ///< N·s on a shape at the centre, ≥ 0
    bool blockedByStatic = false;  ///< a shape whose nearest point is hidden from the centre by a static shape takes nothing
    Filter filter{};               ///< shapes pushed: those with shouldCollide(filter, shape's filter)
};

/// A shape to sweep with World::castShape: a circle, a convex polygon (a box from makeBox) or a
/// segment, in its own frame; the cast places it at a transform.
using CastShape = std::variant<Circle, Polygon, Segment>;

/// Where a swept shape first touches a world shape.
struct ShapeCastHit {
    /// The world shape that was hit.
    ShapeId shape{};
    /// World point of first contact, on the hit shape's surface; the cast's start position when
    /// the shapes already overlap there.
    Vec2 point{};
    /// The hit shape's surface normal at `point`, facing the swept shape (−translation/|translation|
    /// for an overlap at the start).
    Vec2 normal{};
    /// t ∈ [0, 1]: the swept shape touches at xf.p + t·translation (0: overlapping at the start).
    float fraction = 0.0f;
};

}  // namespace perpdot
