// Sleeping: a resting body falls asleep after timeToSleep = 0.5 s below the sleep tolerances
// (0.01 m/s, 2°/s), and wakes when something hits it or a force is applied.
#include <gtest/gtest.h>

#include <vector>

#include "perpdot/world.hpp"
#include "physics_scenes.hpp"

namespace perpdot {
namespace {

using test::dt;

// Steps until the body sleeps; returns the time, or -1 after `limit` seconds.
float timeToFallAsleep(World& world, BodyId body, float limit) {
    for (int i = 1; i * dt <= limit; ++i) {
        world.step(dt);
        if (!world.isAwake(body)) return i * dt;
    }
    return -1.0f;
}

TEST(Sleep, RestingBoxFallsAsleepAfterHalfASecond) {
    // The box starts at rest on the ground (2 mm above it), so it is still from the first steps on:
    // it cannot sleep before 0.5 s, and the contact settles within a few steps (static contacts
    // are 60 Hz with ζ = 10), so it sleeps well before 1 s.
    World world;
    test::addGround(world);
    const BodyId box = test::addBox(world, {0.0f, 0.5f + 0.002f}, 0.5f, 0.5f);
    const float t = timeToFallAsleep(world, box, 2.0f);
    EXPECT_GE(t, 0.5f);
    EXPECT_LE(t, 1.0f);
    const Vec2 p = world.position(box);
    test::run(world, 60);
    EXPECT_FALSE(world.isAwake(box));
    EXPECT_EQ(world.position(box), p) << "a sleeping body does not move";
    EXPECT_EQ(world.linearVelocity(box), (Vec2{}));
}

TEST(Sleep, SleepingBoxWakesWhenHit) {
    World world;
    test::addGround(world);
    const BodyId box = test::addBox(world, {0.0f, 0.502f}, 0.5f, 0.5f);
    ASSERT_GT(timeToFallAsleep(world, box, 2.0f), 0.0f);
    const float y = world.position(box).y;
    // A ball dropped onto one corner from 1 m: it must wake the box and tip it.
    const BodyId ball = test::addDisc(world, {0.4f, 2.0f}, 0.2f, test::material(20.0f));
    bool woke = false;
    for (int i = 0; i < 60 && !woke; ++i) {
        world.step(dt);
        woke = world.isAwake(box);
    }
    EXPECT_TRUE(woke);
    EXPECT_TRUE(world.isAwake(ball));
    test::run(world, 10);
    EXPECT_NE(world.position(box).y, y) << "the woken box responds to the hit";
}

TEST(Sleep, ForceWakesASleepingBody) {
    World world;
    test::addGround(world);
    const BodyId box = test::addBox(world, {0.0f, 0.502f}, 0.5f, 0.5f);
    ASSERT_GT(timeToFallAsleep(world, box, 2.0f), 0.0f);
    const float x = world.position(box).x;
    // 100 N sideways beats static friction μ m g = 0.6 × 1 × 10 = 6 N: the box must slide.
    world.applyForce(box, {100.0f, 0.0f}, world.worldCenter(box));
    EXPECT_TRUE(world.isAwake(box)) << "applyForce wakes at once";
    world.step(dt);
    EXPECT_GT(world.position(box).x, x);
    // A body that may not sleep never does.
    BodyDef def = test::bodyAt({3.0f, 0.502f});
    def.allowSleep = false;
    const BodyId restless = world.createBody(def);
    world.createShape(restless, {}, makeBox(0.5f, 0.5f));
    test::run(world, 120);
    EXPECT_TRUE(world.isAwake(restless));
}

// Bodies made asleep are islands of their own. A sleeper touched by an awake body wakes, and its
// contacts take their narrowphase from the next step on (Box2D v3): through a row of sleepers
// touching edge to edge, waking spreads one box a step, not the whole row in one pass.
TEST(Sleep, WakingSpreadsOneContactAStepThroughBodiesThatSleptApart) {
    WorldDef def;
    def.gravity = {0.0f, 0.0f};
    World world(def);
    constexpr int count = 8;
    std::vector<BodyId> row;
    for (int i = 0; i < count; ++i) {
        BodyDef sleeper = test::bodyAt({1.0f * static_cast<float>(i), 0.0f});
        sleeper.awake = false;
        row.push_back(world.createBody(sleeper));
        world.createShape(row.back(), test::material(1.0f), makeBox(0.5f, 0.5f));
    }
    const BodyId ram = test::addBox(world, {-1.2f, 0.0f}, 0.5f, 0.5f, test::material(1.0f));
    world.setLinearVelocity(ram, {3.0f, 0.0f});
    auto awake = [&] {
        int n = 0;
        for (BodyId b : row) n += world.isAwake(b) ? 1 : 0;
        return n;
    };
    int steps = 0;
    while (awake() == 0 && steps < 60) {
        world.step(test::dt);
        ++steps;
    }
    ASSERT_EQ(awake(), 1) << "the first box wakes alone, after " << steps << " steps";
    EXPECT_TRUE(world.isAwake(row[0]));
    for (int k = 1; k < count; ++k) {
        world.step(test::dt);
        EXPECT_LE(awake(), k + 1) << "step " << k << " after the hit";
    }
    test::run(world, count);
    EXPECT_EQ(awake(), count);
    // Only contacts between awake bodies push: the row and the ram keep the ram's momentum.
    Vec2 p = world.mass(ram) * world.linearVelocity(ram);
    for (BodyId b : row) p += world.mass(b) * world.linearVelocity(b);
    EXPECT_NEAR(p.x, 3.0f, 1e-4f);
    EXPECT_NEAR(p.y, 0.0f, 1e-4f);
    EXPECT_GT(world.linearVelocity(row[count - 1]).x, 0.0f) << "the push reached the last box";
}

}  // namespace
}  // namespace perpdot
