// Contact events (begin/end touch, hits), the pre-solve callback (one-way platforms, a locked
// world) and post-solve impulses.
#include <gtest/gtest.h>

#include <cmath>

#include "features_helpers.hpp"
#include "perpdot/error.hpp"

namespace perpdot {
namespace {

using features::dt;

TEST(FeaturesEvents, BeginTouchWhenABallLandsAndEndTouchWhenItLeaves) {
    World world;
    const ShapeId ground = features::addGround(world);
    const BodyId body = features::addDynamic(world, {0.0f, 2.0f});
    const ShapeId ball = world.createShape(body, {}, Circle{.radius = 0.5f});
    int begins = 0, landedStep = -1;
    for (int i = 0; i < 120; ++i) {
        world.step(dt);
        const ContactEvents events = world.contactEvents();
        for (const ContactBeginTouchEvent& e : events.beginEvents) {
            EXPECT_TRUE(features::samePair(e.shapeA, e.shapeB, ground, ball));
            ++begins;
            landedStep = i;
        }
        EXPECT_TRUE(events.endEvents.empty());
    }
    EXPECT_EQ(begins, 1);
    // Free fall of 1.5 m takes sqrt(2·1.5/10) = 0.55 s ≈ 33 steps; speculative contact may begin a step early.
    EXPECT_NEAR(landedStep, 32, 2);

    // Teleported away: the next step ends the touch.
    world.setTransform(body, {0.0f, 5.0f}, 0.0f);
    world.step(dt);
    ASSERT_EQ(world.contactEvents().endEvents.size(), 1u);
    EXPECT_TRUE(features::samePair(world.contactEvents().endEvents[0].shapeA, world.contactEvents().endEvents[0].shapeB, ground, ball));
    world.step(dt);
    EXPECT_TRUE(world.contactEvents().endEvents.empty());  // reported once
}

TEST(FeaturesEvents, DestroyingATouchingShapeBetweenStepsIsReportedByTheNextStep) {
    World world;
    features::addGround(world);
    const BodyId body = features::addDynamic(world, {0.0f, 0.5f});
    const ShapeId ball = world.createShape(body, {}, Circle{.radius = 0.5f});
    features::run(world, 10);
    ASSERT_EQ(world.contactCount(), 1);
    world.destroyShape(ball);
    world.step(dt);
    const ContactEvents events = world.contactEvents();
    ASSERT_EQ(events.endEvents.size(), 1u);
    EXPECT_TRUE(events.endEvents[0].shapeA == ball || events.endEvents[0].shapeB == ball);
    EXPECT_FALSE(world.isValid(ball));
}

TEST(FeaturesEvents, ShapesWithoutContactEventsReportNone) {
    World world;
    features::addGround(world, 0.0f, 50.0f, {.enableContactEvents = false});
    const BodyId body = features::addDynamic(world, {0.0f, 2.0f});
    world.createShape(body, {.enableContactEvents = false}, Circle{.radius = 0.5f});
    for (int i = 0; i < 60; ++i) {
        world.step(dt);
        EXPECT_TRUE(world.contactEvents().beginEvents.empty());
    }
    EXPECT_EQ(world.contactCount(), 1);
}

TEST(FeaturesEvents, HitEventCarriesTheImpactSpeedPointAndNormal) {
    // Dropped from 5 m above contact: it arrives at sqrt(2 g h) = 10 m/s.
    World world;
    const ShapeId ground = features::addGround(world);
    const BodyId body = features::addDynamic(world, {1.0f, 5.5f});
    const ShapeId ball = world.createShape(body, {.enableHitEvents = true}, Circle{.radius = 0.5f});
    std::vector<ContactHitEvent> hits;
    for (int i = 0; i < 180; ++i) {
        world.step(dt);
        for (const ContactHitEvent& e : world.contactEvents().hitEvents) hits.push_back(e);
    }
    ASSERT_EQ(hits.size(), 1u);  // resting afterwards is no hit
    const ContactHitEvent& hit = hits[0];
    EXPECT_TRUE(features::samePair(hit.shapeA, hit.shapeB, ground, ball));
    EXPECT_NEAR(hit.approachSpeed, 10.0f, 0.3f);
    EXPECT_NEAR(hit.point.x, 1.0f, 0.01f);
    EXPECT_NEAR(hit.point.y, 0.0f, 0.1f);  // midway into an overlap of at most v h = 0.17 m
    // The normal points from A to B: up if the ground is A.
    EXPECT_NEAR(std::fabs(hit.normal.y), 1.0f, 1e-4f);
    EXPECT_EQ(hit.normal.y > 0.0f, hit.shapeA == ground);
}

TEST(FeaturesEvents, HitThresholdFiltersSlowImpacts) {
    WorldDef def;
    def.hitEventThreshold = 20.0f;  // faster than the 10 m/s impact
    World world(def);
    features::addGround(world);
    const BodyId body = features::addDynamic(world, {0.0f, 5.5f});
    world.createShape(body, {.enableHitEvents = true}, Circle{.radius = 0.5f});
    for (int i = 0; i < 120; ++i) {
        world.step(dt);
        EXPECT_TRUE(world.contactEvents().hitEvents.empty());
    }
}

// One-way platform (Box2D v3's sample): the contact is enabled only while the normal pushes the
// visitor up, i.e. it arrives from above.
struct OneWay {
    ShapeId platform;
    bool operator()(ShapeId a, ShapeId, const ContactData& contact) const {
        const float up = a == platform ? contact.normal.y : -contact.normal.y;
        return up > 0.7f;
    }
};

TEST(FeaturesEvents, PreSolveMakesAOneWayPlatform) {
    // A ball launched up at 12 m/s from under a platform at y = 3 passes through it, then lands on it.
    World world;
    features::addGround(world);
    const ShapeId platform = world.createShape(features::addStatic(world, {0.0f, 3.0f}), {.enablePreSolveEvents = true}, makeBox(2.0f, 0.1f));
    const BodyId body = features::addDynamic(world, {0.0f, 0.5f}, {0.0f, 12.0f});
    world.createShape(body, {}, Circle{.radius = 0.25f});
    world.setPreSolve(OneWay{platform});
    float maxY = 0.0f;
    for (int i = 0; i < 240; ++i) {
        world.step(dt);
        maxY = std::max(maxY, world.position(body).y);
    }
    EXPECT_GT(maxY, 3.5f);                                   // went through from below
    EXPECT_NEAR(world.position(body).y, 3.1f + 0.25f, 0.02f);  // rests on top
}

TEST(FeaturesEvents, WithoutPreSolveThePlatformBlocksFromBelow) {
    World world;
    features::addGround(world);
    world.createShape(features::addStatic(world, {0.0f, 3.0f}), {.enablePreSolveEvents = true}, makeBox(2.0f, 0.1f));
    const BodyId body = features::addDynamic(world, {0.0f, 0.5f}, {0.0f, 12.0f});
    world.createShape(body, {}, Circle{.radius = 0.25f});
    float maxY = 0.0f;
    for (int i = 0; i < 240; ++i) {
        world.step(dt);
        maxY = std::max(maxY, world.position(body).y);
    }
    EXPECT_LT(maxY, 2.9f - 0.25f + 0.02f);
}

TEST(FeaturesEvents, TheWorldIsLockedInsidePreSolve) {
    World world;
    features::addGround(world, 0.0f, 50.0f, {.enablePreSolveEvents = true});
    const BodyId body = features::addDynamic(world, {0.0f, 0.5f});
    world.createShape(body, {}, Circle{.radius = 0.5f});
    int calls = 0, refused = 0, locked = 0;
    world.setPreSolve([&](ShapeId, ShapeId, const ContactData&) {
        ++calls;
        locked += world.isLocked() ? 1 : 0;
        try {
            world.createBody({.type = BodyType::Dynamic});
        } catch (const Error&) {
            ++refused;
        }
        try {
            world.setPreSolve({});
        } catch (const Error&) {
            ++refused;
        }
        return true;
    });
    EXPECT_FALSE(world.isLocked());
    features::run(world, 5);
    EXPECT_GT(calls, 0);
    EXPECT_EQ(locked, calls);
    EXPECT_EQ(refused, 2 * calls);
    EXPECT_EQ(world.bodyCount(), 2);
    EXPECT_FALSE(world.isLocked());
}

TEST(FeaturesEvents, PostSolveImpulsesHoldTheWeight) {
    // A resting 1×1 box of mass 1 kg: the stored normal impulses are the last substep's, so they
    // sum to m g h/substeps; the contact points sit symmetric, so each holds half.
    World world;
    features::addGround(world);
    const BodyId box = features::addDynamic(world, {0.0f, 0.5f});
    world.createShape(box, {.density = 1.0f}, makeBox(0.5f, 0.5f));
    features::run(world, 60);
    const std::vector<ContactData> contacts = world.contacts();
    ASSERT_EQ(contacts.size(), 1u);
    ASSERT_EQ(contacts[0].pointCount, 2);
    const float substepImpulse = world.mass(box) * 10.0f * dt / static_cast<float>(world.settings().substeps);
    const float total = contacts[0].points[0].normalImpulse + contacts[0].points[1].normalImpulse;
    EXPECT_NEAR(total, substepImpulse, 0.02f * substepImpulse);
    EXPECT_NEAR(contacts[0].points[0].normalImpulse, 0.5f * total, 0.05f * total);
}

}  // namespace
}  // namespace perpdot
