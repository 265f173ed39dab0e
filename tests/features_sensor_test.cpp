// Sensors: overlap begin/end events and no collision response.
#include <gtest/gtest.h>

#include "features_helpers.hpp"

namespace perpdot {
namespace {

using features::dt;

TEST(FeaturesSensor, BallFallsThroughAZoneReportingEntryAndExitAndKeepsItsFreeFall) {
    // A 2 m tall sensor zone centred at y = 5; a ball dropped from y = 10 passes through it.
    World world;
    const ShapeId zone = world.createShape(features::addStatic(world, {0.0f, 5.0f}), {.sensor = true}, makeBox(2.0f, 1.0f));
    const BodyId body = features::addDynamic(world, {0.0f, 10.0f});
    const ShapeId ball = world.createShape(body, {}, Circle{.radius = 0.25f});
    // The same ball in a world with no sensor: the reference free fall.
    World free;
    const BodyId reference = features::addDynamic(free, {0.0f, 10.0f});
    free.createShape(reference, {}, Circle{.radius = 0.25f});

    int beginStep = -1, endStep = -1;
    for (int i = 0; i < 90; ++i) {
        world.step(dt);
        free.step(dt);
        ASSERT_EQ(world.position(body), free.position(reference)) << "step " << i;  // no response at all
        const SensorEvents events = world.sensorEvents();
        for (const SensorBeginTouchEvent& e : events.beginEvents) {
            EXPECT_EQ(e.sensorShape, zone);
            EXPECT_EQ(e.visitorShape, ball);
            EXPECT_EQ(beginStep, -1);
            beginStep = i;
            // Entered: the ball's bottom has just crossed the zone's top (y = 6).
            EXPECT_LT(world.position(body).y - 0.25f, 6.0f);
        }
        for (const SensorEndTouchEvent& e : events.endEvents) {
            EXPECT_EQ(e.sensorShape, zone);
            EXPECT_EQ(e.visitorShape, ball);
            EXPECT_EQ(endStep, -1);
            endStep = i;
            EXPECT_LT(world.position(body).y + 0.25f, 4.0f);  // left through the bottom
        }
        EXPECT_TRUE(world.contactEvents().beginEvents.empty());
    }
    EXPECT_GE(beginStep, 0);
    EXPECT_GT(endStep, beginStep);
    EXPECT_EQ(world.contactCount(), 0);
}

// A trigger zone sees a kinematic body (a character mover, a moving platform) passing through it,
// at the zone's faces; a kinematic body and a static one still make no contact.
TEST(FeaturesSensor, AStaticZoneSeesAKinematicBodyPassAndKinematicMeetsStaticWithoutContact) {
    World world({.gravity = {0.0f, 0.0f}});
    const ShapeId zone = world.createShape(features::addStatic(world, {5.0f, 0.0f}), {.sensor = true}, makeBox(1.0f, 1.0f));
    world.createShape(features::addStatic(world, {5.0f, 3.0f}), {}, makeBox(1.0f, 1.0f));  // a solid static box
    const BodyId mover = world.createBody({.type = BodyType::Kinematic, .position = {0.0f, 0.0f}, .linearVelocity = {3.0f, 0.0f}});
    const ShapeId hull = world.createShape(mover, {}, Circle{.radius = 0.25f});
    const BodyId high = world.createBody({.type = BodyType::Kinematic, .position = {0.0f, 3.0f}, .linearVelocity = {3.0f, 0.0f}});
    world.createShape(high, {}, Circle{.radius = 0.25f});
    float entered = -1.0f, left = -1.0f;
    for (int i = 0; i < 180; ++i) {
        world.step(dt);
        const float x = world.position(mover).x;
        for (const SensorBeginTouchEvent& e : world.sensorEvents().beginEvents) {
            EXPECT_EQ(e.sensorShape, zone);
            EXPECT_EQ(e.visitorShape, hull);
            EXPECT_LT(entered, 0.0f);
            entered = x;
        }
        for (const SensorEndTouchEvent& e : world.sensorEvents().endEvents) {
            EXPECT_EQ(e.visitorShape, hull);
            left = x;
        }
        EXPECT_EQ(world.contactCount(), 0);  // the kinematic ball passes through the static box
        EXPECT_EQ(world.position(high).y, 3.0f);
    }
    // Entered when its front (x + 0.25) crossed the zone's left face (x = 4): the overlap is
    // tested at the start of a step and x read at its end, so up to two steps' 5 cm later.
    EXPECT_GE(entered + 0.25f, 4.0f);
    EXPECT_LE(entered + 0.25f, 4.101f);
    EXPECT_GE(left - 0.25f, 6.0f);  // left when its back crossed the right face
    EXPECT_LE(left - 0.25f, 6.101f);
}

TEST(FeaturesSensor, ShapesCanOptOutOfSensorEventsAndSensorsIgnoreSensors) {
    World world;
    world.createShape(features::addStatic(world, {0.0f, 5.0f}), {.sensor = true}, makeBox(2.0f, 1.0f));
    const BodyId shy = features::addDynamic(world, {-1.0f, 5.0f});
    world.createShape(shy, {.enableSensorEvents = false}, Circle{.radius = 0.25f});
    const BodyId ghost = features::addDynamic(world, {1.0f, 5.0f});
    world.createShape(ghost, {.sensor = true}, Circle{.radius = 0.25f});
    for (int i = 0; i < 30; ++i) {
        world.step(dt);
        EXPECT_TRUE(world.sensorEvents().beginEvents.empty());
    }
}

TEST(FeaturesSensor, AVisitorAtRestInsideIsReportedOnceAndAMovingSensorFindsIt) {
    // A kinematic sensor sweeps across a ball resting on the ground: begin, then end.
    World world;
    features::addGround(world);
    const BodyId body = features::addDynamic(world, {0.0f, 0.25f});
    const ShapeId ball = world.createShape(body, {}, Circle{.radius = 0.25f});
    const BodyId scanner = world.createBody({.type = BodyType::Kinematic, .position = {-3.0f, 0.5f}, .linearVelocity = {2.0f, 0.0f}});
    const ShapeId beam = world.createShape(scanner, {.sensor = true}, makeBox(0.1f, 1.0f));
    int begins = 0, ends = 0;
    for (int i = 0; i < 240; ++i) {
        world.step(dt);
        for (const SensorBeginTouchEvent& e : world.sensorEvents().beginEvents) begins += e.sensorShape == beam && e.visitorShape == ball;
        for (const SensorEndTouchEvent& e : world.sensorEvents().endEvents) ends += e.sensorShape == beam && e.visitorShape == ball;
    }
    EXPECT_EQ(begins, 1);
    EXPECT_EQ(ends, 1);
    EXPECT_NEAR(world.position(body).x, 0.0f, 1e-3f);  // the beam never pushed it
}

}  // namespace
}  // namespace perpdot
