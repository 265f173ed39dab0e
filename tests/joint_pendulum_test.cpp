// Revolute joints against the closed forms of a rigid pendulum: the small-angle period
// 2π√(I_pivot/(m g d)), conservation of energy without friction, and the pivot's reaction m·g.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "joint_helpers.hpp"

namespace perpdot {
namespace {

using namespace joint_test;

struct Pendulum {
    World world;
    BodyId pivot, bob;
    JointId joint;
};

// A disc of radius r whose centre hangs d below the pivot, turned θ0 off the vertical.
Pendulum makePendulum(float d, float r, float theta0) {
    Pendulum p{World{}, {}, {}, {}};
    p.pivot = staticBody(p.world, {0.0f, 10.0f});
    p.bob = disc(p.world, {d * std::sin(theta0), 10.0f - d * std::cos(theta0)}, r);
    p.joint = p.world.createJoint(hinge(p.world, p.pivot, p.bob, {0.0f, 10.0f}));
    return p;
}

float swingAngle(const Pendulum& p) {
    const Vec2 arm = p.world.worldCenter(p.bob) - Vec2{0.0f, 10.0f};
    return std::atan2(arm.x, -arm.y);
}

TEST(JointPendulum, SmallAnglePeriodMatchesClosedForm) {
    const float d = 1.0f, r = 0.25f, h = 1.0f / 60.0f;
    Pendulum p = makePendulum(d, r, 0.05f);
    const float m = p.world.mass(p.bob), I = p.world.rotationalInertia(p.bob) + m * d * d;  // parallel axis
    const float expected = 2.0f * pi * std::sqrt(I / (m * 10.0f * d));

    // Times of downward zero crossings of the swing angle, interpolated within the step.
    std::vector<float> crossings;
    float previous = swingAngle(p);
    for (int step = 1; step <= 900 && crossings.size() < 5; ++step) {
        p.world.step(h);
        const float now = swingAngle(p);
        if (previous > 0.0f && now <= 0.0f) crossings.push_back(h * (step - 1 + previous / (previous - now)));
        previous = now;
    }
    ASSERT_EQ(crossings.size(), 5u);
    const float period = (crossings.back() - crossings.front()) / 4.0f;
    EXPECT_NEAR(period, expected, 0.01f * expected) << "measured " << period << " s, expected " << expected << " s";
}

TEST(JointPendulum, FrictionlessEnergyDriftsLessThanOnePercentOverTenSeconds) {
    Pendulum p = makePendulum(2.0f, 0.25f, pi / 3.0f);
    // Energy above the lowest point (centre 2 m below the pivot at y = 10): the swing's energy.
    const float bottom = p.world.mass(p.bob) * 10.0f * 8.0f;
    const float e0 = energy(p.world, p.bob) - bottom;
    ASSERT_GT(e0, 0.0f);
    float worst = 0.0f;
    for (int step = 0; step < 600; ++step) {
        p.world.step(1.0f / 60.0f);
        worst = std::max(worst, std::fabs(energy(p.world, p.bob) - bottom - e0) / e0);
    }
    EXPECT_LT(worst, 0.01f);
}

TEST(JointPendulum, ReactionOfHangingBodyIsItsWeight) {
    Pendulum p = makePendulum(1.5f, 0.3f, 0.0f);
    for (int step = 0; step < 120; ++step) p.world.step(1.0f / 60.0f);
    const float weight = p.world.mass(p.bob) * 10.0f;
    const Vec2 force = p.world.jointReactionForce(p.joint);
    EXPECT_NEAR(force.x, 0.0f, 1e-3f * weight);
    EXPECT_NEAR(force.y, weight, 1e-3f * weight);  // on the bob, upwards
    EXPECT_NEAR(p.world.jointReactionTorque(p.joint), 0.0f, 1e-3f * weight);
}

}  // namespace
}  // namespace perpdot
