// Small scene builders shared by the physics suites: everything goes through the public API.
#pragma once

#include <limits>
#include <vector>

#include "perpdot/world.hpp"

namespace perpdot::test {

inline constexpr float epsilon = std::numeric_limits<float>::epsilon();  // 2^-23
inline constexpr float dt = 1.0f / 60.0f;

// Definitions built field by field: GCC 12's -Wextra flags designated initialisers that omit a
// member without a default member initialiser (BodyDef::position, ShapeDef::filter, Circle::center).
inline BodyDef bodyAt(Vec2 position, BodyType type = BodyType::Dynamic, float angle = 0.0f) {
    BodyDef def;
    def.type = type;
    def.position = position;
    def.angle = angle;
    return def;
}

inline ShapeDef material(float density, float friction = 0.6f, float restitution = 0.0f) {
    ShapeDef def;
    def.density = density;
    def.friction = friction;
    def.restitution = restitution;
    return def;
}

// A static box of half extents (hx, hy) whose top face is the line y = top.
inline BodyId addGround(World& world, float top = 0.0f, float hx = 50.0f, const ShapeDef& def = {}) {
    const BodyId ground = world.createBody(bodyAt({0.0f, top - 0.5f}, BodyType::Static));
    world.createShape(ground, def, makeBox(hx, 0.5f));
    return ground;
}

inline BodyId addBox(World& world, Vec2 position, float hx, float hy, const ShapeDef& def = {}, float angle = 0.0f) {
    const BodyId body = world.createBody(bodyAt(position, BodyType::Dynamic, angle));
    world.createShape(body, def, makeBox(hx, hy));
    return body;
}

inline BodyId addDisc(World& world, Vec2 position, float radius, const ShapeDef& def = {}) {
    const BodyId body = world.createBody(bodyAt(position));
    world.createShape(body, def, Circle{{}, radius});
    return body;
}

inline void run(World& world, int steps, float h = dt) {
    for (int i = 0; i < steps; ++i) world.step(h);
}

// The pyramid of the `pyramid` scene: `rows` rows of 1 m boxes on the line y = 0, centred on x = 0.
// Returns the bodies bottom row first; the last one is the top box.
inline std::vector<BodyId> addPyramid(World& world, int rows) {
    std::vector<BodyId> boxes;
    for (int row = 0; row < rows; ++row)
        for (int column = row; column < rows; ++column)
            boxes.push_back(addBox(world, {-0.5f * rows + 0.5f * (row + 1) + (column - row), 0.5f + row}, 0.5f, 0.5f));
    return boxes;
}

}  // namespace perpdot::test
