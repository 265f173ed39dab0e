// Rolling resistance and tangent speed (conveyor belts).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "features_helpers.hpp"

namespace perpdot {
namespace {

using features::dt;

// A disc of radius r rolling at v0 on flat ground; returns how far its centre travelled.
float rollingDistance(float rollingResistance, float v0, int steps) {
    World world;
    features::addGround(world, 0.0f, 200.0f);
    const float r = 0.5f;
    const BodyId disc = features::addDynamic(world, {0.0f, r}, {v0, 0.0f});
    world.setAngularVelocity(disc, -v0 / r);  // rolling without slipping: v = −ω r
    world.createShape(disc, {.friction = 0.8f, .rollingResistance = rollingResistance}, Circle{.radius = r});
    features::run(world, steps);
    return world.position(disc).x;
}

TEST(FeaturesRolling, RollingResistanceStopsADiscAtTheEnergyPredictedDistance) {
    // The row's torque limit is c·r·N with N = m g; it dissipates τ|ω| = c m g v while the disc's
    // rolling energy is ¾ m v² (I = ½ m r²): dv/dt = −(2/3) c g, distance = 3 v0² / (4 c g).
    const float c = 0.2f, v0 = 5.0f, g = 10.0f;
    const float expected = 3.0f * v0 * v0 / (4.0f * c * g);  // 9.375 m
    EXPECT_NEAR(rollingDistance(c, v0, 300), expected, 0.05f * expected);
}

TEST(FeaturesRolling, WithoutRollingResistanceTheDiscKeepsRolling) {
    // 5 s at 5 m/s: 25 m, less nothing but rounding.
    EXPECT_NEAR(rollingDistance(0.0f, 5.0f, 300), 25.0f, 0.25f);
}

// A 1 m box resting on a static conveyor of tangent speed s made of `belt`; returns the box's
// velocity after two seconds.
template <class Geometry>
Vec2 carriedVelocity(const Geometry& belt, float speed) {
    World world;
    world.createShape(features::addStatic(world, {}), {.friction = 0.6f, .tangentSpeed = speed}, belt);
    const BodyId box = features::addDynamic(world, {0.0f, 0.5f});
    world.createShape(box, {.friction = 0.6f}, makeBox(0.5f, 0.5f));
    features::run(world, 120);
    return world.linearVelocity(box);
}

TEST(FeaturesRolling, ConveyorCarriesABoxAtItsTangentSpeed) {
    // Positive tangent speed moves the surface clockwise around its shape: rightwards on top.
    // The box reaches the belt speed (friction accelerates it at μ g = 6 m/s² for 0.33 s).
    const Vec2 onBox = carriedVelocity(makeBox(20.0f, 0.5f, {0.0f, -0.5f}), 2.0f);
    EXPECT_NEAR(onBox.x, 2.0f, 0.01f);
    EXPECT_NEAR(onBox.y, 0.0f, 0.01f);
    // The same on a segment belt (the segment is the contact's shape A, the polygon box was B
    // or A above): the sign convention does not depend on the pair's order.
    EXPECT_NEAR(carriedVelocity(Segment{{-20.0f, 0.0f}, {20.0f, 0.0f}}, -3.0f).x, -3.0f, 0.01f);
}

}  // namespace
}  // namespace perpdot
