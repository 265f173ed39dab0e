// A shape's material changed while its contacts exist (setFriction, setTangentSpeed,
// setRollingResistance) reaches those contacts from the next step on: the contact cache mixes
// materials when a contact is created and again when a shape's material changes, not each step.
#include <gtest/gtest.h>

#include "features_helpers.hpp"

namespace perpdot {
namespace {

using features::dt;
constexpr float g = 10.0f;

TEST(MaterialChange, FrictionSetOnATouchingShapeBrakesItsSlide) {
    World world;
    features::addGround(world, 0.0f, 100.0f, {.friction = 0.5f});
    const BodyId box = features::addDynamic(world, {0.0f, 0.5f}, {4.0f, 0.0f});
    const ShapeId shape = world.createShape(box, {.friction = 0.0f}, makeBox(0.5f, 0.5f));
    features::run(world, 30);  // √(0.5 · 0) = 0: no friction, the box keeps its speed
    EXPECT_NEAR(world.linearVelocity(box).x, 4.0f, 1e-3f);
    world.setFriction(shape, 0.5f);  // √(0.5 · 0.5) = 0.5: decelerates at μ g = 5 m/s²
    features::run(world, 30);
    EXPECT_NEAR(world.linearVelocity(box).x, 4.0f - 0.5f * g * 30 * dt, 0.05f);
}

TEST(MaterialChange, TangentSpeedSetOnAStillBeltCarriesTheBoxOnIt) {
    World world;
    const ShapeId belt = features::addGround(world, 0.0f, 20.0f, {.friction = 0.6f});
    // Awake (a sleeping body's contacts are not solved, and a material change wakes nothing, as in Box2D).
    const BodyId box = world.createBody({.type = BodyType::Dynamic, .position = {0.0f, 0.5f}, .allowSleep = false});
    world.createShape(box, {.friction = 0.6f}, makeBox(0.5f, 0.5f));
    features::run(world, 30);
    EXPECT_NEAR(world.linearVelocity(box).x, 0.0f, 1e-4f);
    world.setTangentSpeed(belt, 2.0f);  // rightwards on top; μ g = 6 m/s² reaches it in 0.33 s
    features::run(world, 60);
    EXPECT_NEAR(world.linearVelocity(box).x, 2.0f, 0.01f);
}

TEST(MaterialChange, RollingResistanceSetOnARollingDiscSlowsIt) {
    World world;
    features::addGround(world, 0.0f, 200.0f);
    const float r = 0.5f, v0 = 5.0f, c = 0.2f;
    const BodyId disc = features::addDynamic(world, {0.0f, r}, {v0, 0.0f});
    world.setAngularVelocity(disc, -v0 / r);  // rolling without slipping
    const ShapeId shape = world.createShape(disc, {.friction = 0.8f}, Circle{.radius = r});
    features::run(world, 30);
    EXPECT_NEAR(world.linearVelocity(disc).x, v0, 0.01f);
    world.setRollingResistance(shape, c);  // dv/dt = −(2/3) c g (features_rolling_test.cpp)
    features::run(world, 60);
    EXPECT_NEAR(world.linearVelocity(disc).x, v0 - 2.0f / 3.0f * c * g * 60 * dt, 0.05f);
}

}  // namespace
}  // namespace perpdot
