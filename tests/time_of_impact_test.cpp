// collide::CollisionSystem::timeOfImpact (conservative advancement on b2Distance): analytic times
// of impact, a spinning plank, and sweeps whose distance overflows (where b2TimeOfImpact asserted).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "collide/collision.hpp"

namespace perpdot::collide {
namespace {

// Box2D's TOI target for two rounded shapes: the cores 3 linear slops inside touching.
constexpr float targetFor(float radiusA, float radiusB) { return radiusA + radiusB - 3.0f * linearSlop; }

Sweep still(Vec2 c) { return {{}, c, c, 0.0f, 0.0f}; }

// Two unit-diameter discs, A moving head-on from x = 0 to x = 10 at B (x = 5): the core distance
// 5 − 10 t reaches the target at t = (5 − target) / 10.
TEST(TimeOfImpact, HeadOnDiscsMeetAtTheTargetSeparation) {
    CollisionSystem collision;
    collision.setGeometry(0, Circle{{}, 0.5f});
    collision.setGeometry(1, Circle{{}, 0.5f});
    const float t = collision.timeOfImpact({0, 0}, Sweep{{}, {0.0f, 0.0f}, {10.0f, 0.0f}, 0.0f, 0.0f}, {1, 0}, still({5.0f, 0.0f}));
    EXPECT_NEAR(t, (5.0f - targetFor(0.5f, 0.5f)) / 10.0f, 1e-5f);
}

// A box (core half-width 0.5, skin polygonRadius) dropping 4 m onto a segment 1 m below its face.
TEST(TimeOfImpact, FallingBoxMeetsASegment) {
    CollisionSystem collision;
    collision.setGeometry(0, makeBox(0.5f, 0.5f));
    collision.setGeometry(1, Segment{{-5.0f, 0.0f}, {5.0f, 0.0f}});
    const float t = collision.timeOfImpact({0, 0}, Sweep{{}, {0.0f, 1.5f}, {0.0f, -2.5f}, 0.0f, 0.0f}, {1, 0}, still({}));
    // The core face starts 1 m above the segment and falls 4 m; the segment has no skin.
    EXPECT_NEAR(t, (1.0f - std::max(linearSlop, targetFor(polygonRadius, 0.0f))) / 4.0f, 1e-4f);
}

TEST(TimeOfImpact, PassingAsideOrMovingAwayIsNoImpact) {
    CollisionSystem collision;
    collision.setGeometry(0, Circle{{}, 0.5f});
    collision.setGeometry(1, Circle{{}, 0.5f});
    EXPECT_EQ(collision.timeOfImpact({0, 0}, Sweep{{}, {0.0f, 2.0f}, {10.0f, 2.0f}, 0.0f, 0.0f}, {1, 0}, still({5.0f, 0.0f})), 1.0f);
    EXPECT_EQ(collision.timeOfImpact({0, 0}, Sweep{{}, {0.0f, 0.0f}, {-10.0f, 0.0f}, 0.0f, 0.0f}, {1, 0}, still({5.0f, 0.0f})), 1.0f);
    // Already within the target at the start: 0.
    EXPECT_EQ(collision.timeOfImpact({0, 0}, Sweep{{}, {4.2f, 0.0f}, {4.5f, 0.0f}, 0.0f, 0.0f}, {1, 0}, still({5.0f, 0.0f})), 0.0f);
}

// A 4 m plank turning a quarter turn about its centre, from upright to flat, past a post 1.5 m to
// its right: its side hits the post. Like Box2D's, the time of impact leaves the rounded surfaces
// 3 linear slops into each other (the cores at the target distance), never deeper, and stops
// within the tolerance (a quarter slop) of it.
TEST(TimeOfImpact, SpinningPlankStopsBeforeAPost) {
    CollisionSystem collision;
    collision.setGeometry(0, makeBox(2.0f, 0.05f));
    collision.setGeometry(1, Circle{{}, 0.1f});
    const Sweep spin{{}, {0.0f, 0.0f}, {0.0f, 0.0f}, 0.5f * pi, 0.0f};  // upright, turning clockwise to flat
    const float t = collision.timeOfImpact({0, 0}, spin, {1, 0}, still({1.5f, 0.3f}));
    ASSERT_GT(t, 0.0f);
    ASSERT_LT(t, 1.0f);
    // At t the plank has turned to θ = π/2 (1 − t); the gap between its side and the post's surface:
    auto gapAt = [&](float s) {
        const float angle = 0.5f * pi * (1.0f - s);
        const Vec2 axis{std::cos(angle), std::sin(angle)};
        const Vec2 post{1.5f, 0.3f};
        const float along = std::clamp(dot(post, axis), -2.0f, 2.0f);
        return length(post - along * axis) - 0.05f - 0.1f - polygonRadius;
    };
    EXPECT_GT(gapAt(t), -3.0f * linearSlop - 1e-4f);
    EXPECT_LT(gapAt(t), -3.0f * linearSlop + 0.25f * linearSlop + 1e-4f);
}

// Sweeps whose distance overflows to infinity or NaN (finite but extreme poses): no impact, and no
// abort (extreme sweeps like these made b2TimeOfImpact assert: tests/fuzz/findings/snapshot/ccd-toi-*).
TEST(TimeOfImpact, OverflowingSweepsAreNoImpactInsteadOfAnAbort) {
    CollisionSystem collision;
    collision.setGeometry(0, makeBox(0.5f, 0.5f));
    collision.setGeometry(1, Circle{{}, 0.5f});
    const float huge = std::numeric_limits<float>::max();
    const float t1 = collision.timeOfImpact({0, 0}, Sweep{{}, {-huge, 0.0f}, {huge, 0.0f}, 0.0f, 1e30f}, {1, 0}, still({huge, -huge}));
    EXPECT_TRUE(t1 >= 0.0f && t1 <= 1.0f) << t1;
    const float t2 = collision.timeOfImpact({0, 0}, Sweep{{}, {huge, huge}, {-huge, -huge}, -1e38f, 1e38f}, {1, 0}, still({0.0f, 0.0f}));
    EXPECT_TRUE(t2 >= 0.0f && t2 <= 1.0f) << t2;
}

}  // namespace
}  // namespace perpdot::collide
