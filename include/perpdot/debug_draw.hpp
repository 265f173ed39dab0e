/// @file
/// Debug drawing: the World describes itself through this interface; a viewer implements it.
#pragma once

#include <cstdint>
#include <span>

#include "perpdot/math.hpp"

namespace perpdot {

class World;

/// An 8-bit RGBA colour.
struct Color {
    uint8_t r = 255;  ///< red
    uint8_t g = 255;  ///< green
    uint8_t b = 255;  ///< blue
    uint8_t a = 255;  ///< alpha: 255 opaque
};

/// What debugDraw() draws.
struct DebugDrawOptions {
    bool shapes = true;         ///< outlines and fills of every shape
    bool centerOfMass = false;  ///< a mark at each body's centre of mass
    bool velocities = false;    ///< each body's v as a segment from its centre of mass
    bool aabbs = false;         ///< each shape's bounding box
    bool contacts = false;        ///< points and normals
    bool contactImpulses = false;  ///< normal impulses as segments along the normals
    bool joints = true;            ///< anchors and the segments between them
    bool dimSleeping = true;       ///< sleeping bodies drawn in dimmer colours
};

/// The drawing primitives a viewer implements (world coordinates, metres).
class DebugDraw {
public:
    virtual ~DebugDraw() = default;  ///< destroyed through the interface
    /// Closed polygon outline, world vertices.
    virtual void drawPolygon(std::span<const Vec2> vertices, Color color) = 0;
    /// Filled polygon with outline, world vertices, optionally rounded by `radius`. A capsule comes
    /// as its two centres rounded by its radius.
    virtual void drawSolidPolygon(std::span<const Vec2> vertices, float radius, Color color) = 0;
    /// Circle outline.
    virtual void drawCircle(Vec2 center, float radius, Color color) = 0;
    /// Filled circle with a radius line showing its rotation.
    virtual void drawSolidCircle(Vec2 center, float radius, Rot rotation, Color color) = 0;
    /// Line segment from a to b.
    virtual void drawSegment(Vec2 a, Vec2 b, Color color) = 0;
    /// A dot of `sizePixels` pixels, whatever the zoom.
    virtual void drawPoint(Vec2 p, float sizePixels, Color color) = 0;
};

/// Draw the world's state through `draw`.
void debugDraw(const World& world, DebugDraw& draw, const DebugDrawOptions& options = {});

}  // namespace perpdot
