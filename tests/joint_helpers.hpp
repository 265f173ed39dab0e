// Small builders shared by the joint tests: bodies without designated-initializer noise, and
// the mechanical energy of a body.
#pragma once

#include "perpdot/world.hpp"

namespace perpdot::joint_test {

inline BodyId staticBody(World& world, Vec2 position = {}) {
    BodyDef def;
    def.position = position;
    return world.createBody(def);
}

inline BodyId dynamicBody(World& world, Vec2 position, float angle = 0.0f) {
    BodyDef def;
    def.type = BodyType::Dynamic;
    def.position = position;
    def.angle = angle;
    def.allowSleep = false;
    return world.createBody(def);
}

inline BodyId disc(World& world, Vec2 position, float radius, float density = 1.0f) {
    const BodyId body = dynamicBody(world, position);
    ShapeDef shape;
    shape.density = density;
    world.createShape(body, shape, Circle{{}, radius});
    return body;
}

inline BodyId box(World& world, Vec2 position, float hx, float hy, float density = 1.0f) {
    const BodyId body = dynamicBody(world, position);
    ShapeDef shape;
    shape.density = density;
    world.createShape(body, shape, makeBox(hx, hy));
    return body;
}

// ½ m v² + ½ I ω² − m g·x_cm
inline float energy(const World& world, BodyId body) {
    const Vec2 v = world.linearVelocity(body);
    const float w = world.angularVelocity(body);
    return 0.5f * world.mass(body) * dot(v, v) + 0.5f * world.rotationalInertia(body) * w * w -
           world.mass(body) * dot(world.settings().gravity, world.worldCenter(body));
}

inline RevoluteJointDef hinge(const World& world, BodyId a, BodyId b, Vec2 anchor) {
    RevoluteJointDef def;
    def.bodyA = a;
    def.bodyB = b;
    def.localAnchorA = invTransformPoint(world.transform(a), anchor);
    def.localAnchorB = invTransformPoint(world.transform(b), anchor);
    def.referenceAngle = world.angle(b) - world.angle(a);
    return def;
}

}  // namespace perpdot::joint_test
