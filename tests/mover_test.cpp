// Character mover scenarios, headless and scripted: each walks, jumps or rides for a fixed number
// of frames and checks where the mover ended, whether it was grounded, and that no frame was stuck
// (input pushing, zero progress) where progress was possible.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "features_helpers.hpp"
#include "perpdot/error.hpp"

namespace perpdot::features {
namespace {

// Feet at y = 0 when the capsule centre is at feetToCenter.
const MoverDef def{};
const float feetToCenter = def.halfHeight + def.radius;
constexpr float polygonSkin = 0.01f;  // Box2D 2.4 polygon radius: boxes and segments are this much fatter

struct Scenario {
    World world;
    MoverState mover;
    int stuckFrames = 0;      // walking input, grounded, |Δx| < 1 mm
    int groundFlickers = 0;   // grounded → airborne → grounded within three frames without a jump

    explicit Scenario(Vec2 start, const WorldDef& wd = {}) : world(wd) { mover = world.createMover(def, start); }

    // `frames` frames of the same input; `progressPossible` counts stuck frames.
    void walk(int frames, MoverInput input, bool progressPossible = true) {
        int airborneRun = 0;
        for (int i = 0; i < frames; ++i) {
            world.step(dt);
            const bool was = mover.grounded;
            world.moveMover(def, mover, input, dt);
            if (progressPossible && mover.grounded && input.walkSpeed != 0.0f && std::fabs(mover.lastDisplacement.x) < 1e-3f) ++stuckFrames;
            if (!input.jump) {
                if (was && !mover.grounded) airborneRun = 1;
                else if (!mover.grounded && airborneRun > 0) ++airborneRun;
                else if (mover.grounded && airborneRun > 0 && airborneRun <= 3) ++groundFlickers, airborneRun = 0;
                else airborneRun = 0;
            }
        }
    }
    ShapeId box(Vec2 center, Vec2 half, float angle = 0.0f, const ShapeDef& sd = {}) {
        return world.createShape(addStatic(world, {}), sd, makeBox(half.x, half.y, center, angle));
    }
    float feet() const { return mover.position.y - feetToCenter; }
};

Scenario onFlatGround(float x = 0.0f) {
    Scenario r({x, feetToCenter + 0.05f});
    addGround(r.world);
    return r;
}

TEST(Mover, LandsAndStaysGroundedWithoutFlicker) {
    Scenario r({0.0f, 2.0f});
    addGround(r.world);
    r.walk(90, {});
    EXPECT_TRUE(r.mover.grounded);
    EXPECT_NEAR(r.feet(), def.skin + polygonSkin, 0.01f);
    r.walk(120, {.walkSpeed = 4.0f});
    EXPECT_EQ(r.groundFlickers, 0);
    EXPECT_EQ(r.stuckFrames, 0);
}

TEST(Mover, WalksAtItsSpeedOnFlatGround) {
    Scenario r = onFlatGround();
    r.walk(10, {});
    const float x0 = r.mover.position.x;
    r.walk(60, {.walkSpeed = 3.0f});
    EXPECT_NEAR(r.mover.position.x - x0, 3.0f, 0.01f);
    EXPECT_EQ(r.stuckFrames, 0);
}

TEST(Mover, StopsAtAWall) {
    Scenario r = onFlatGround();
    r.box({2.0f, 2.0f}, {0.2f, 2.0f});
    r.walk(120, {.walkSpeed = 3.0f}, false);
    EXPECT_NEAR(r.mover.position.x, 2.0f - 0.2f - polygonSkin - def.radius - def.skin, 0.01f);
    EXPECT_TRUE(r.mover.grounded);
}

TEST(Mover, ClimbsStairsUp) {
    Scenario r = onFlatGround();
    for (int i = 1; i <= 5; ++i) r.box({1.5f + 0.5f * i + 2.5f, 0.1f * i}, {2.5f, 0.1f * i});  // 0.2 m rise, 0.5 m run
    r.walk(150, {.walkSpeed = 3.0f});
    EXPECT_GT(r.mover.position.x, 6.0f);
    EXPECT_NEAR(r.feet(), 1.0f, 0.05f);
    EXPECT_TRUE(r.mover.grounded);
    EXPECT_EQ(r.stuckFrames, 0);
}

TEST(Mover, WalksStairsDownWithoutLeavingTheGround) {
    Scenario r({0.0f, 1.0f + feetToCenter + 0.02f});
    addGround(r.world);
    for (int i = 0; i < 4; ++i) {  // tops 0.8, 0.6, 0.4, 0.2, each 0.5 m deep
        const float top = 0.8f - 0.2f * i;
        r.box({0.5f * i + 0.25f, 0.5f * top}, {0.25f, 0.5f * top});
    }
    r.box({-5.0f, 0.5f}, {5.0f, 0.5f});  // landing at y = 1 to the left
    r.walk(20, {});
    ASSERT_TRUE(r.mover.grounded);
    r.walk(120, {.walkSpeed = 2.0f});
    EXPECT_GT(r.mover.position.x, 3.0f);
    EXPECT_NEAR(r.feet(), 0.0f, 0.05f);
    EXPECT_EQ(r.groundFlickers, 0);  // snapped down each step
    EXPECT_EQ(r.stuckFrames, 0);
}

TEST(Mover, RefusesAStepTallerThanStepHeight) {
    Scenario r = onFlatGround();
    r.box({4.0f, 0.25f}, {2.0f, 0.25f});  // 0.5 m > 0.3 m
    r.walk(120, {.walkSpeed = 3.0f}, false);
    EXPECT_LT(r.mover.position.x, 2.0f);
    EXPECT_LT(r.feet(), 0.05f);
}

void slope(Scenario& r, float angle) {
    // A ramp rising to +x from (1, 0).
    const Vec2 along{std::cos(angle), std::sin(angle)};
    r.world.createShape(addStatic(r.world, {}), {}, Segment{{1.0f, 0.0f}, Vec2{1.0f, 0.0f} + 20.0f * along});
}

TEST(Mover, WalksUpASlopeBelowTheLimit) {
    Scenario r = onFlatGround();
    slope(r, 0.5f);  // 29°
    r.walk(150, {.walkSpeed = 3.0f});
    EXPECT_GT(r.mover.position.x, 4.0f);
    EXPECT_GT(r.feet(), 1.5f);
    EXPECT_TRUE(r.mover.grounded);
    EXPECT_EQ(r.stuckFrames, 0);
    EXPECT_EQ(r.groundFlickers, 0);
}

TEST(Mover, CannotWalkUpASlopeAboveTheLimit) {
    Scenario r = onFlatGround();
    slope(r, 1.1f);  // 63° > 50°
    r.walk(150, {.walkSpeed = 3.0f}, false);
    EXPECT_LT(r.feet(), def.stepHeight + 0.05f);
    EXPECT_LT(r.mover.position.x, 1.5f);
}

TEST(Mover, SlidesDownASlopeAboveTheLimit) {
    Scenario r({6.0f, 10.0f});
    addGround(r.world);
    r.world.createShape(addStatic(r.world, {}), {}, Segment{{0.0f, 0.0f}, {4.0f, 8.0f}});  // 63°
    r.walk(30, {});
    r.walk(120, {});
    EXPECT_TRUE(r.mover.grounded);
    EXPECT_LT(r.feet(), 0.05f);  // came down to the floor
}

TEST(Mover, WalksDownASlopeStayingGrounded) {
    Scenario r({5.0f, 3.0f});
    addGround(r.world);
    r.world.createShape(addStatic(r.world, {}), {}, Segment{{0.0f, 0.0f}, {6.0f, 3.0f}});  // 27°, rising to +x
    r.walk(30, {});
    ASSERT_TRUE(r.mover.grounded);
    r.walk(90, {.walkSpeed = -3.0f});
    EXPECT_EQ(r.groundFlickers, 0);
    EXPECT_LT(r.mover.position.x, 1.0f);
    EXPECT_EQ(r.stuckFrames, 0);
}

TEST(Mover, DoesNotClimbASteepCorner) {
    Scenario r = onFlatGround();
    // A V-shaped corner of two steep faces: walking into it must not ride it upward.
    r.world.createShape(addStatic(r.world, {}), {}, Segment{{2.0f, 0.0f}, {3.0f, 3.0f}});
    r.walk(180, {.walkSpeed = 3.0f}, false);
    EXPECT_LT(r.feet(), def.stepHeight + 0.05f);
}

TEST(Mover, CeilingStopsAJump) {
    Scenario r = onFlatGround();
    r.box({0.0f, 2.5f}, {3.0f, 0.1f});  // ceiling underside at 2.4
    r.walk(10, {});
    r.walk(1, {.jump = true});
    float top = 0.0f;
    for (int i = 0; i < 60; ++i) {
        r.walk(1, {});
        top = std::max(top, r.mover.position.y + feetToCenter);
    }
    EXPECT_LT(top, 2.4f - polygonSkin + 1e-3f);
    EXPECT_GT(top, 2.3f);
    EXPECT_TRUE(r.mover.grounded);  // fell back down
}

TEST(Mover, JumpReachesBallisticHeight) {
    Scenario r = onFlatGround();
    r.walk(10, {});
    const float y0 = r.mover.position.y;
    r.walk(1, {.jump = true});
    float top = y0;
    for (int i = 0; i < 90; ++i) {
        r.walk(1, {});
        top = std::max(top, r.mover.position.y);
    }
    const float expected = def.jumpSpeed * def.jumpSpeed / 20.0f;  // v²/2g
    EXPECT_NEAR(top - y0, expected, 0.05f * expected);
    EXPECT_TRUE(r.mover.grounded);
}

TEST(Mover, FitsThroughAGapWiderThanItself) {
    Scenario r = onFlatGround();
    r.box({3.0f, 3.0f}, {0.5f, 1.0f});  // underside at 2.0: the capsule (1.4 m tall) walks under
    r.walk(120, {.walkSpeed = 3.0f});
    EXPECT_GT(r.mover.position.x, 4.0f);
    EXPECT_EQ(r.stuckFrames, 0);
}

TEST(Mover, IsStoppedByAGapLowerThanItself) {
    Scenario r = onFlatGround();
    r.box({3.0f, 2.0f}, {0.5f, 0.9f});  // underside at 1.1 < 1.4
    r.walk(120, {.walkSpeed = 3.0f}, false);
    EXPECT_LT(r.mover.position.x, 2.5f);
    EXPECT_LT(r.feet(), 0.05f);
}

TEST(Mover, RidesAMovingPlatform) {
    Scenario r({0.0f, 1.0f + feetToCenter + 0.02f});
    const BodyId platform = r.world.createBody({.type = BodyType::Kinematic, .position = {0.0f, 0.5f}, .linearVelocity = {1.5f, 0.5f}});
    r.world.createShape(platform, {}, makeBox(2.0f, 0.5f));
    r.walk(60, {});
    EXPECT_TRUE(r.mover.grounded);
    EXPECT_NEAR(r.mover.position.x - r.world.position(platform).x, 0.0f, 0.05f);
    EXPECT_NEAR(r.feet() - (r.world.position(platform).y + 0.5f), def.skin + polygonSkin, 0.03f);
    EXPECT_EQ(r.groundFlickers, 0);
}

TEST(Mover, JumpsUpThroughAOneWayPlatformAndLandsOnIt) {
    const uint16_t oneWay = 0x0002;
    MoverDef d = def;
    d.oneWayCategories = oneWay;
    World world;
    addGround(world);
    world.createShape(addStatic(world, {}), {.filter = {.category = oneWay}}, makeBox(2.0f, 0.05f, {0.0f, 1.2f}));
    MoverState m = world.createMover(d, {0.0f, feetToCenter + 0.02f});
    for (int i = 0; i < 10; ++i) world.step(dt), world.moveMover(d, m, {}, dt);
    world.step(dt);
    world.moveMover(d, m, {.jump = true}, dt);
    for (int i = 0; i < 120; ++i) world.step(dt), world.moveMover(d, m, {}, dt);
    EXPECT_TRUE(m.grounded);
    EXPECT_NEAR(m.position.y - feetToCenter, 1.25f + d.skin + polygonSkin, 0.03f);
}

TEST(Mover, StandsOnAOneWayPlatformFromAbove) {
    const uint16_t oneWay = 0x0002;
    MoverDef d = def;
    d.oneWayCategories = oneWay;
    World world;
    world.createShape(addStatic(world, {}), {.filter = {.category = oneWay}}, makeBox(2.0f, 0.05f));
    MoverState m = world.createMover(d, {0.0f, 3.0f});
    for (int i = 0; i < 120; ++i) world.step(dt), world.moveMover(d, m, {}, dt);
    EXPECT_TRUE(m.grounded);
    EXPECT_NEAR(m.position.y - feetToCenter, 0.05f + d.skin + polygonSkin, 0.03f);
}

TEST(Mover, PushesADynamicBox) {
    Scenario r = onFlatGround();
    const BodyId box = addDynamic(r.world, {2.0f, 0.5f});
    r.world.createShape(box, {.density = 5.0f, .friction = 0.3f}, makeBox(0.5f, 0.5f));
    r.walk(120, {.walkSpeed = 2.0f}, false);
    EXPECT_GT(r.world.position(box).x, 4.0f);  // moved with the mover
    EXPECT_GT(r.mover.position.x, 3.0f);
    EXPECT_LT(r.mover.position.x, r.world.position(box).x);
}

TEST(Mover, IsPushedByAMovingWall) {
    Scenario r = onFlatGround();
    const BodyId wall = r.world.createBody({.type = BodyType::Kinematic, .position = {2.0f, 1.0f}, .linearVelocity = {-1.0f, 0.0f}});
    r.world.createShape(wall, {}, makeBox(0.2f, 1.0f));
    r.walk(120, {}, false);
    EXPECT_LT(r.mover.position.x, -0.5f);  // the wall moved 2 m left and carried it along
    EXPECT_GT(r.world.position(wall).x - 0.2f - r.mover.position.x, def.radius - 0.02f);
}

TEST(Mover, IsPushedByAHeavyDynamicBody) {
    Scenario r = onFlatGround();
    const BodyId ball = addDynamic(r.world, {-3.0f, 0.6f}, {6.0f, 0.0f});
    r.world.createShape(ball, {.density = 50.0f, .friction = 0.0f}, Circle{{}, 0.6f});
    r.walk(60, {}, false);
    EXPECT_GT(r.mover.position.x, 0.2f);  // knocked forward
}

TEST(Mover, SnapshotRestoresTheSameMotion) {
    Scenario r = onFlatGround();
    r.box({3.0f, 0.1f}, {1.0f, 0.1f});
    r.walk(20, {.walkSpeed = 2.0f});
    const std::vector<uint8_t> bytes = r.world.snapshot();
    const MoverState saved = r.mover;
    r.walk(60, {.walkSpeed = 2.0f});
    const MoverState first = r.mover;
    r.world.restore(bytes);
    r.mover = saved;
    r.walk(60, {.walkSpeed = 2.0f});
    EXPECT_EQ(r.mover, first);
}

TEST(Mover, BadDefinitionIsRefused) {
    World world;
    MoverDef bad = def;
    bad.radius = 0.0f;
    EXPECT_THROW(world.createMover(bad, {}), Error);
    bad = def;
    bad.maxSlope = 2.0f;
    EXPECT_THROW(world.createMover(bad, {}), Error);
    bad = def;
    bad.halfHeight = NAN;
    EXPECT_THROW(world.createMover(bad, {}), Error);
    EXPECT_THROW(world.createMover(def, {INFINITY, 0.0f}), Error);
    MoverState m = world.createMover(def, {});
    EXPECT_THROW(world.moveMover(def, m, {}, 0.0f), Error);
    EXPECT_THROW(world.moveMover(def, m, {.walkSpeed = NAN}, dt), Error);
}

}  // namespace
}  // namespace perpdot::features
