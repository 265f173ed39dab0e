// Small builders shared by the tests/features_*_test.cpp suites (public API only).
#pragma once

#include "perpdot/world.hpp"

namespace perpdot::features {

inline constexpr float dt = 1.0f / 60.0f;

inline BodyId addStatic(World& world, Vec2 position) { return world.createBody({.type = BodyType::Static, .position = position}); }

inline BodyId addDynamic(World& world, Vec2 position, Vec2 velocity = {}, bool bullet = false) {
    return world.createBody({.type = BodyType::Dynamic, .position = position, .linearVelocity = velocity, .bullet = bullet});
}

// A static box ground whose top face is the line y = top.
inline ShapeId addGround(World& world, float top = 0.0f, float hx = 50.0f, const ShapeDef& def = {}) {
    return world.createShape(addStatic(world, {0.0f, top - 0.5f}), def, makeBox(hx, 0.5f));
}

inline void run(World& world, int steps) {
    for (int i = 0; i < steps; ++i) world.step(dt);
}

// Either order: events name the pair in the contact's (A, B) order.
inline bool samePair(ShapeId a, ShapeId b, ShapeId x, ShapeId y) { return (a == x && b == y) || (a == y && b == x); }

}  // namespace perpdot::features
