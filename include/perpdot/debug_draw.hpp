// Debug drawing: the World describes itself through this interface; a viewer implements it.
#pragma once

#include <cstdint>
#include <span>

#include "perpdot/math.hpp"

namespace perpdot {

class World;

struct Color {
    uint8_t r = 255, g = 255, b = 255, a = 255;
};

struct DebugDrawOptions {
    bool shapes = true;
    bool centerOfMass = false;
    bool velocities = false;
    bool aabbs = false;
    bool contacts = false;        // points and normals
    bool contactImpulses = false;
    bool joints = true;
    bool dimSleeping = true;
};

class DebugDraw {
public:
    virtual ~DebugDraw() = default;
    // Closed polygon outline, world vertices.
    virtual void drawPolygon(std::span<const Vec2> vertices, Color color) = 0;
    // Filled polygon with outline, world vertices, optionally rounded by `radius`. A capsule comes
    // as its two centres rounded by its radius.
    virtual void drawSolidPolygon(std::span<const Vec2> vertices, float radius, Color color) = 0;
    virtual void drawCircle(Vec2 center, float radius, Color color) = 0;
    // Filled circle with a radius line showing its rotation.
    virtual void drawSolidCircle(Vec2 center, float radius, Rot rotation, Color color) = 0;
    virtual void drawSegment(Vec2 a, Vec2 b, Color color) = 0;
    virtual void drawPoint(Vec2 p, float sizePixels, Color color) = 0;
};

// Draw the world's state through `draw`.
void debugDraw(const World& world, DebugDraw& draw, const DebugDrawOptions& options = {});

}  // namespace perpdot
