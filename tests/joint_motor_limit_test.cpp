// Motors reach their speed without exceeding their torque or force; limits hold.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "joint_helpers.hpp"

namespace perpdot {
namespace {

using namespace joint_test;

constexpr float h = 1.0f / 60.0f;

// A disc spun about its centre by a revolute motor: ω grows at τmax/I until it reaches the speed.
TEST(JointMotor, RevoluteMotorAcceleratesAtMaxTorqueThenHoldsSpeed) {
    World world(WorldDef{.gravity = {0.0f, 0.0f}});
    const BodyId ground = staticBody(world);
    const BodyId wheel = disc(world, {0.0f, 0.0f}, 1.0f);
    RevoluteJointDef def = hinge(world, ground, wheel, {0.0f, 0.0f});
    def.enableMotor = true;
    def.motorSpeed = 3.0f;
    def.maxMotorTorque = 2.0f;
    const JointId motor = world.createJoint(def);
    const float I = world.rotationalInertia(wheel);
    const float rampTime = def.motorSpeed * I / def.maxMotorTorque;

    const int rampSteps = static_cast<int>(0.5f * rampTime / h);
    for (int i = 0; i < rampSteps; ++i) world.step(h);
    EXPECT_NEAR(world.angularVelocity(wheel), def.maxMotorTorque * rampSteps * h / I, 1e-3f * def.motorSpeed);
    EXPECT_NEAR(world.jointReactionTorque(motor), def.maxMotorTorque, 1e-3f * def.maxMotorTorque);

    for (int i = 0; i < static_cast<int>(2.0f * rampTime / h); ++i) world.step(h);
    EXPECT_NEAR(world.angularVelocity(wheel), def.motorSpeed, 1e-4f * def.motorSpeed);
    EXPECT_LE(std::fabs(world.jointReactionTorque(motor)), def.maxMotorTorque * 1.0001f);
}

// A motor too weak to lift its load stalls at its maximum torque instead of exceeding it.
TEST(JointMotor, StalledRevoluteMotorRespectsMaxTorque) {
    World world;
    const BodyId ground = staticBody(world);
    const BodyId arm = box(world, {1.0f, 0.0f}, 1.0f, 0.1f);
    RevoluteJointDef def = hinge(world, ground, arm, {0.0f, 0.0f});
    def.enableMotor = true;
    def.motorSpeed = 1.0f;
    def.maxMotorTorque = 0.5f * world.mass(arm) * 10.0f * 1.0f;  // half the gravity torque when horizontal
    const JointId motor = world.createJoint(def);
    for (int i = 0; i < 10; ++i) {
        world.step(h);
        EXPECT_LE(std::fabs(world.jointReactionTorque(motor)), def.maxMotorTorque * 1.0001f);
    }
    EXPECT_LT(world.angularVelocity(arm), 0.0f);  // it falls despite the motor
}

// Ten m/s straight down on `ball` for half a second, with the motor's reaction (|torque| or |force|)
// checked against `maxReaction` at every step: the struck body's largest |speed| and the motor's
// largest reaction.
struct Blow {
    float fastest = 0.0f, strongest = 0.0f;
};
template <class Speed, class Reaction>
Blow strike(World& world, BodyId ball, float maxReaction, Speed speed, Reaction reaction) {
    world.setLinearVelocity(ball, {0.0f, -10.0f});
    Blow blow;
    for (int i = 0; i < 30; ++i) {
        world.step(h);
        blow.fastest = std::max(blow.fastest, std::fabs(speed()));
        blow.strongest = std::max(blow.strongest, std::fabs(reaction()));
        EXPECT_LE(std::fabs(reaction()), maxReaction * 1.0001f) << "step " << i;
    }
    return blow;
}

// A blow far beyond a motor's strength: a 0.1 kg arm held at rest by a 1 N·m motor, struck near
// its tip by a ball 50 times its mass at 10 m/s (stress case hinge_hit without the limit). The
// ball turns the arm; the motor resists with exactly its maximum torque at every step, never more.
TEST(JointMotor, StruckMotorNeverExceedsItsMaxTorque) {
    World world(WorldDef{.gravity = {0.0f, 0.0f}});
    const BodyId ground = staticBody(world);
    const BodyId arm = box(world, {0.5f, 0.0f}, 0.5f, 0.05f);  // 0.1 kg
    RevoluteJointDef def = hinge(world, ground, arm, {0.0f, 0.0f});
    def.enableMotor = true;
    def.motorSpeed = 0.0f;
    def.maxMotorTorque = 1.0f;
    const JointId motor = world.createJoint(def);
    const BodyId ball = disc(world, {0.9f, 0.25f}, 0.1f, 5.0f / (3.14159265f * 0.01f));  // 5 kg
    const Blow blow = strike(world, ball, def.maxMotorTorque, [&] { return world.angularVelocity(arm); },
                             [&] { return world.jointReactionTorque(motor); });
    EXPECT_GT(blow.fastest, 5.0f);                                               // the blow overpowered the motor
    EXPECT_NEAR(blow.strongest, def.maxMotorTorque, 1e-3f * def.maxMotorTorque);  // which pushed back with all it has
}

// The same blow along a prismatic motor's axis: a 0.25 kg slider held by a 1 N motor, struck by a
// 12.5 kg ball at 10 m/s; the motor's force stays within its maximum at every step.
TEST(JointMotor, StruckPrismaticMotorNeverExceedsItsMaxForce) {
    World world(WorldDef{.gravity = {0.0f, 0.0f}});
    const BodyId ground = staticBody(world);
    const BodyId slider = box(world, {0.0f, 0.0f}, 0.25f, 0.25f);  // 0.25 kg
    PrismaticJointDef def;
    def.bodyA = ground;
    def.bodyB = slider;
    def.localAxisA = {0.0f, 1.0f};
    def.enableMotor = true;
    def.motorSpeed = 0.0f;
    def.maxMotorForce = 1.0f;
    const JointId motor = world.createJoint(def);
    const BodyId ball = disc(world, {0.0f, 0.5f}, 0.1f, 12.5f / (3.14159265f * 0.01f));  // 12.5 kg
    const Blow blow = strike(world, ball, def.maxMotorForce, [&] { return world.linearVelocity(slider).y; },
                             [&] { return world.jointReactionForce(motor).y; });
    EXPECT_GT(blow.fastest, 5.0f);
    EXPECT_NEAR(blow.strongest, def.maxMotorForce, 1e-3f * def.maxMotorForce);
}

TEST(JointMotor, PrismaticMotorAcceleratesAtMaxForceThenHoldsSpeed) {
    World world(WorldDef{.gravity = {0.0f, 0.0f}});
    const BodyId ground = staticBody(world);
    const BodyId slider = box(world, {0.0f, 0.0f}, 0.5f, 0.5f);
    PrismaticJointDef def;
    def.bodyA = ground;
    def.bodyB = slider;
    def.localAxisA = {1.0f, 0.0f};
    def.enableMotor = true;
    def.motorSpeed = 2.0f;
    def.maxMotorForce = 1.0f;
    const JointId motor = world.createJoint(def);
    const float m = world.mass(slider);
    const float rampTime = def.motorSpeed * m / def.maxMotorForce;
    const int rampSteps = static_cast<int>(0.5f * rampTime / h);
    for (int i = 0; i < rampSteps; ++i) world.step(h);
    EXPECT_NEAR(world.linearVelocity(slider).x, def.maxMotorForce * rampSteps * h / m, 1e-3f * def.motorSpeed);
    EXPECT_NEAR(world.jointReactionForce(motor).x, def.maxMotorForce, 1e-3f * def.maxMotorForce);
    for (int i = 0; i < static_cast<int>(2.0f * rampTime / h); ++i) world.step(h);
    EXPECT_NEAR(world.linearVelocity(slider).x, def.motorSpeed, 1e-4f * def.motorSpeed);
    EXPECT_NEAR(world.linearVelocity(slider).y, 0.0f, 1e-5f);
}

TEST(JointMotor, WheelMotorReachesSpeed) {
    World world(WorldDef{.gravity = {0.0f, 0.0f}});
    const BodyId chassis = staticBody(world);
    const BodyId wheel = disc(world, {0.0f, 0.0f}, 0.5f);
    WheelJointDef def;
    def.bodyA = chassis;
    def.bodyB = wheel;
    def.enableMotor = true;
    def.motorSpeed = -5.0f;
    def.maxMotorTorque = 10.0f;
    world.createJoint(def);
    for (int i = 0; i < 120; ++i) world.step(h);
    EXPECT_NEAR(world.angularVelocity(wheel), def.motorSpeed, 1e-4f * std::fabs(def.motorSpeed));
}

// A bar released horizontal swings down until the lower limit stops it (−π/2 would be hanging).
TEST(JointLimit, RevoluteLimitHolds) {
    World world;
    const BodyId ground = staticBody(world);
    const BodyId arm = box(world, {1.0f, 0.0f}, 1.0f, 0.1f);
    RevoluteJointDef def = hinge(world, ground, arm, {0.0f, 0.0f});
    def.enableLimit = true;
    def.lowerAngle = -0.5f;
    def.upperAngle = 0.25f;
    world.createJoint(def);
    float lowest = 0.0f;
    for (int i = 0; i < 180; ++i) {
        world.step(h);
        lowest = std::min(lowest, world.angle(arm));
    }
    EXPECT_GT(lowest, def.lowerAngle - 0.02f);
    EXPECT_NEAR(world.angle(arm), def.lowerAngle, 0.01f);  // resting on the limit
}

TEST(JointLimit, PrismaticLimitHolds) {
    World world;
    const BodyId ground = staticBody(world);
    const BodyId slider = box(world, {0.0f, 0.0f}, 0.25f, 0.25f);
    PrismaticJointDef def;
    def.bodyA = ground;
    def.bodyB = slider;
    def.localAxisA = {0.0f, 1.0f};
    def.enableLimit = true;
    def.lower = -1.0f;
    def.upper = 1.0f;
    world.createJoint(def);
    float lowest = 0.0f;
    for (int i = 0; i < 180; ++i) {
        world.step(h);
        lowest = std::min(lowest, world.position(slider).y);
        EXPECT_NEAR(world.position(slider).x, 0.0f, 1e-4f);
    }
    EXPECT_GT(lowest, def.lower - 0.01f);
    EXPECT_NEAR(world.position(slider).y, def.lower, 0.005f);
}

}  // namespace
}  // namespace perpdot
