/// @file
/// Collision shapes in a body's local frame, their materials, and their mass properties.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "perpdot/math.hpp"

namespace perpdot {

/// The most vertices a Polygon holds (Box2D's b2_maxPolygonVertices).
inline constexpr int maxPolygonVertices = 8;
/// Shape coordinates (in the body frame) must lie within ±maxShapeCoordinate metres, Box2D v3's
/// "huge": beyond it a float keeps no millimetres and Box2D's distance routines break down.
inline constexpr float maxShapeCoordinate = 1.0e5f;
/// Whether both coordinates lie within ±maxShapeCoordinate.
inline bool withinShapeRange(Vec2 v) { return std::fabs(v.x) <= maxShapeCoordinate && std::fabs(v.y) <= maxShapeCoordinate; }
/// Whether a radius lies within maxShapeCoordinate: a larger one reaches past the shape range, and
/// its r² (mass, inertia, distances) overflows a float beyond about 1e19 m.
inline bool withinShapeRange(float radius) { return radius <= maxShapeCoordinate; }

/// Which geometry a shape holds.
enum class ShapeType : uint8_t { Circle, Polygon, Segment, Chain, Capsule };

/// A solid disc.
struct Circle {
    Vec2 center{};        ///< body frame
    float radius = 0.5f;  ///< m
    /// Exact equality of every field.
    friend bool operator==(const Circle&, const Circle&) = default;
};

/// A convex polygon, counter-clockwise, optionally rounded by `radius`. Build it with
/// makePolygon() or makeBox(), which validate and normalise the winding.
struct Polygon {
    std::array<Vec2, maxPolygonVertices> vertices{};  ///< body frame; the first `count` are used
    int count = 0;                                     ///< number of vertices, 3..maxPolygonVertices
    float radius = 0.0f;                               ///< rounding: the outline is pushed out by this much
    /// Exact equality of every field.
    friend bool operator==(const Polygon&, const Polygon&) = default;
};

/// Massless line segment (static geometry).
struct Segment {
    Vec2 v1{};  ///< one end, body frame
    Vec2 v2{};  ///< the other end, body frame
    /// Exact equality of every field.
    friend bool operator==(const Segment&, const Segment&) = default;
};

/// Which side of a chain is solid, looking along it from one vertex to the next.
enum class ChainSide : uint8_t {
    /// Solid on the right, shapes collide from the left: ground given left to right (solid below,
    /// surface normal up), or a clockwise loop around solid ground. The default.
    Right,
    /// Solid on the left, shapes collide from the right: Box2D's one-sided chains (its normal
    /// points to the right of v1→v2), ground given right to left, a counter-clockwise loop around
    /// solid ground or a clockwise loop as a container; the scene format's default (`"solid": "left"`).
    Left,
};

/// Massless chain of segments whose inner corners do not catch sliding shapes. One-sided: shapes
/// collide with it from its open side only (`solid` says which side is solid) and pass through
/// from the other.
struct Chain {
    std::vector<Vec2> vertices{};  ///< body frame, in order along the chain
    bool loop = false;           ///< the last vertex joins the first
    ChainSide solid = ChainSide::Right;  ///< the solid side; the default suits terrain given left to right
    /// Open chains: Box2D 2.4's ghost vertices, the points before the first vertex and after the
    /// last (b2ChainShape::CreateChain's prevVertex, nextVertex), so that the end segments meet the
    /// next piece of ground without a corner. None: the end segment continued straight on.
    /// A loop takes none (Error).
    std::optional<Vec2> prevVertex{};
    std::optional<Vec2> nextVertex{};  ///< Open chains: the ghost vertex after the last (see prevVertex).
    /// Exact equality of every field.
    friend bool operator==(const Chain&, const Chain&) = default;
};

/// Throws perpdot::Error unless `points` is 3..8 distinct points forming a strictly convex polygon.
/// Either winding is accepted; the result is counter-clockwise.
Polygon makePolygon(std::span<const Vec2> points, float radius = 0.0f);
/// Box with half extents (hx, hy), centred at `center` and turned by `angle` in the body frame.
Polygon makeBox(float hx, float hy, Vec2 center = {}, float angle = 0.0f);

/// A capsule: the set of points within `radius` of the segment center1–center2 (a rectangle of
/// length |center2 − center1| and width 2·radius capped by two half-discs), in the body frame.
/// Collides with every shape type; in Box2D 2.4 terms it is a 2-vertex b2PolygonShape whose
/// m_radius is `radius`. The centres must be at least the linear slop (0.005 m) apart (use a
/// Circle otherwise) and the radius finite and > 0.
struct Capsule {
    Vec2 center1{};   ///< first cap centre, body frame
    Vec2 center2{1.0f, 0.0f};  ///< second cap centre, body frame
    float radius = 0.25f;  ///< cap radius and half width, m
    /// Exact equality of every field.
    friend bool operator==(const Capsule&, const Capsule&) = default;
};

/// Collision filtering as in Box2D: two shapes collide when each one's category is in the other's
/// mask, unless they share a non-zero group (positive: always collide, negative: never).
struct Filter {
    uint16_t category = 0x0001;  ///< the category bits this shape belongs to
    uint16_t mask = 0xFFFF;      ///< the categories it collides with
    int16_t group = 0;           ///< non-zero: overrides category and mask for shapes of the same group
    /// Exact equality of every field.
    friend bool operator==(const Filter&, const Filter&) = default;
};

/// Whether shapes with filters `a` and `b` collide (see Filter).
bool shouldCollide(const Filter& a, const Filter& b);

/// Everything createShape() needs besides the geometry: material, events, filter.
struct ShapeDef {
    float density = 1.0f;       ///< kg/m²
    float friction = 0.6f;      ///< Coulomb μ; mixed as sqrt(μA μB)
    float restitution = 0.0f;   ///< e; mixed as max(eA, eB)
    bool sensor = false;        ///< reports overlaps (World::sensorEvents), takes no collision response
    float rollingResistance = 0.0f;  ///< angular drag; mixed as max(rA, rB)·(largest rounding radius)
    float tangentSpeed = 0.0f;  ///< m/s conveyor surface, clockwise around the shape; summed A + B
    bool enableContactEvents = true;   ///< begin/end touch events
    bool enableHitEvents = false;      ///< hit events
    bool enableSensorEvents = true;    ///< whether sensors see this shape
    bool enablePreSolveEvents = false; ///< whether World's pre-solve callback sees its contacts
    Filter filter{};            ///< which other shapes it collides with
    void* userData = nullptr;   ///< the application's pointer
};

/// Mass m, centre of mass (body frame) and scalar moment of inertia I about that centre.
struct MassData {
    float mass = 0.0f;               ///< m, kg
    Vec2 center{};                   ///< centre of mass, body frame
    float rotationalInertia = 0.0f;  ///< I about the centre of mass, kg·m²
};

/// Area integrals: m = ρ∫dA, c = ∫r dA / A, I = ρ∫|r - c|² dA.
MassData computeMass(const Circle& circle, float density);
MassData computeMass(const Polygon& polygon, float density);  ///< includes the rounding radius
/// Capsule mass properties: a 2r × L rectangle plus two half-discs, shifted to the capsule's
/// midpoint by the parallel-axis theorem: m = ρ(2rL + πr²),
/// I = ρ[2rL(L² + 4r²)/12 + πr²(r²/2 + L²/4) + 4r³L/3].
MassData computeMass(const Capsule& capsule, float density);

/// Parallel-axis sum: parts about their own centres -> whole about the combined centre.
MassData combineMass(std::span<const MassData> parts);

}  // namespace perpdot
