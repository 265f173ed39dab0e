// The joint API: generational ids, destruction at any time, collideConnected, and the soft
// joints (distance spring, wheel suspension, weld, motor and mouse joints) against their laws.
#include <gtest/gtest.h>

#include <cmath>

#include "joint_helpers.hpp"
#include "perpdot/error.hpp"

namespace perpdot {
namespace {

using namespace joint_test;

constexpr float h = 1.0f / 60.0f;

TEST(JointApi, StaleJointIdIsAnError) {
    World world;
    const BodyId a = staticBody(world), b = disc(world, {0.0f, -1.0f}, 0.25f);
    const JointId joint = world.createJoint(hinge(world, a, b, {0.0f, 0.0f}));
    EXPECT_TRUE(world.isValid(joint));
    world.destroyJoint(joint);
    EXPECT_FALSE(world.isValid(joint));
    EXPECT_THROW(world.jointType(joint), Error);
    EXPECT_THROW(world.jointReactionForce(joint), Error);
    EXPECT_THROW(world.destroyJoint(joint), Error);
    // The slot is reused with a new generation; the old id stays stale.
    const JointId again = world.createJoint(hinge(world, a, b, {0.0f, 0.0f}));
    EXPECT_EQ(again.index, joint.index);
    EXPECT_FALSE(world.isValid(joint));
    EXPECT_TRUE(world.isValid(again));
    EXPECT_THROW(world.createJoint(hinge(world, b, b, {0.0f, 0.0f})), Error);
}

TEST(JointApi, DestroyingABodyRemovesItsJointsAndLeavesAValidWorld) {
    World world;
    const BodyId anchor = staticBody(world, {0.0f, 5.0f});
    const BodyId first = disc(world, {0.0f, 4.0f}, 0.2f), second = disc(world, {0.0f, 3.0f}, 0.2f);
    const JointId upper = world.createJoint(hinge(world, anchor, first, {0.0f, 5.0f}));
    const JointId lower = world.createJoint(hinge(world, first, second, {0.0f, 4.0f}));
    for (int i = 0; i < 30; ++i) world.step(h);
    world.destroyBody(first);
    EXPECT_FALSE(world.isValid(upper));
    EXPECT_FALSE(world.isValid(lower));
    EXPECT_TRUE(world.joints().empty());
    EXPECT_TRUE(world.isAwake(second));
    // The survivor is now free: it falls like a free body.
    const float y0 = world.worldCenter(second).y, v0 = world.linearVelocity(second).y;
    for (int i = 0; i < 30; ++i) world.step(h);
    EXPECT_NEAR(world.linearVelocity(second).y, v0 - 10.0f * 30 * h, 1e-3f);
    EXPECT_LT(world.worldCenter(second).y, y0);
}

TEST(JointApi, JointedBodiesCollideOnlyWhenAsked) {
    for (bool collide : {false, true}) {
        World world(WorldDef{.gravity = {0.0f, 0.0f}});
        const BodyId a = box(world, {0.0f, 0.0f}, 0.5f, 0.5f), b = box(world, {0.8f, 0.0f}, 0.5f, 0.5f);
        world.step(h);
        ASSERT_EQ(world.contactCount(), 1);  // overlapping before the joint
        RevoluteJointDef def = hinge(world, a, b, {0.4f, 0.0f});
        def.collideConnected = collide;
        const JointId joint = world.createJoint(def);
        world.step(h);
        EXPECT_EQ(world.contactCount(), collide ? 1 : 0) << "collideConnected " << collide;
        // Without the joint the pair is found again.
        world.destroyJoint(joint);
        world.step(h);
        world.step(h);
        EXPECT_EQ(world.contactCount(), 1);
    }
}

TEST(JointApi, SetMotorSpeedOnlyForMotorisedJoints) {
    World world;
    const BodyId a = staticBody(world), b = disc(world, {1.0f, 0.0f}, 0.25f);
    DistanceJointDef def;
    def.bodyA = a;
    def.bodyB = b;
    const JointId rod = world.createJoint(def);
    EXPECT_THROW(world.setMotorSpeed(rod, 1.0f), Error);
    EXPECT_THROW(world.setMouseTarget(rod, {}), Error);
}

// A rigid distance joint is a rod: a ball on it swings at constant distance.
TEST(JointDistance, RigidRodKeepsItsLength) {
    World world;
    const BodyId a = staticBody(world, {0.0f, 5.0f}), b = disc(world, {2.0f, 5.0f}, 0.2f);
    DistanceJointDef def;
    def.bodyA = a;
    def.bodyB = b;
    def.length = 2.0f;
    world.createJoint(def);
    for (int i = 0; i < 240; ++i) {
        world.step(h);
        EXPECT_NEAR(distance(world.worldCenter(b), {0.0f, 5.0f}), 2.0f, 0.005f);
    }
}

// A body hanging on a spring of frequency f (against a static body) rests m g / (m ω²) = g / ω²
// below the spring's length; maxLength stops a fall that stretches it further.
TEST(JointDistance, SpringSagsByGOverOmegaSquaredAndMaxLengthHolds) {
    World world;
    const BodyId a = staticBody(world, {0.0f, 5.0f}), b = disc(world, {0.0f, 4.0f}, 0.2f);
    DistanceJointDef def;
    def.bodyA = a;
    def.bodyB = b;
    def.length = 1.0f;
    def.hertz = 2.0f;
    def.dampingRatio = 1.0f;
    const JointId spring = world.createJoint(def);
    for (int i = 0; i < 300; ++i) world.step(h);
    const float omega = 2.0f * pi * def.hertz;
    EXPECT_NEAR(5.0f - world.worldCenter(b).y, 1.0f + 10.0f / (omega * omega), 0.002f);
    world.destroyJoint(spring);
    def.maxLength = 1.1f;  // above the 1.063 m rest length
    world.createJoint(def);
    world.setLinearVelocity(b, {0.0f, -3.0f});
    for (int i = 0; i < 60; ++i) {
        world.step(h);
        EXPECT_LT(5.0f - world.worldCenter(b).y, def.maxLength + 0.01f);
    }
}

TEST(JointWheel, SuspensionSagsByGOverOmegaSquaredAndStaysOnItsAxis) {
    World world;
    const BodyId chassis = staticBody(world, {0.0f, 2.0f});
    const BodyId wheel = disc(world, {0.0f, 2.0f}, 0.4f);
    WheelJointDef def;
    def.bodyA = chassis;
    def.bodyB = wheel;
    def.hertz = 3.0f;
    def.dampingRatio = 1.0f;
    world.createJoint(def);
    for (int i = 0; i < 300; ++i) world.step(h);
    const float omega = 2.0f * pi * def.hertz;
    EXPECT_NEAR(2.0f - world.worldCenter(wheel).y, 10.0f / (omega * omega), 0.001f);
    EXPECT_NEAR(world.worldCenter(wheel).x, 0.0f, 1e-4f);
}

TEST(JointWeld, RigidWeldHoldsACantilever) {
    World world;
    const BodyId wall = staticBody(world);
    const BodyId beam = box(world, {1.0f, 0.0f}, 1.0f, 0.1f);
    WeldJointDef def;
    def.bodyA = wall;
    def.bodyB = beam;
    def.localAnchorB = {-1.0f, 0.0f};
    const JointId weld = world.createJoint(def);
    for (int i = 0; i < 120; ++i) world.step(h);
    EXPECT_NEAR(world.angle(beam), 0.0f, 0.01f);
    EXPECT_NEAR(world.position(beam).y, 0.0f, 0.005f);
    // The wall carries the weight and its moment m g · 1 m.
    const float weight = world.mass(beam) * 10.0f;
    EXPECT_NEAR(world.jointReactionForce(weld).y, weight, 1e-3f * weight);
    EXPECT_NEAR(world.jointReactionTorque(weld), weight * 1.0f, 1e-2f * weight);
}

TEST(JointMotorJoint, DrivesBodyToTheOffset) {
    World world(WorldDef{.gravity = {0.0f, 0.0f}});
    const BodyId ground = staticBody(world);
    const BodyId body = box(world, {0.0f, 0.0f}, 0.5f, 0.5f);
    MotorJointDef def;
    def.bodyA = ground;
    def.bodyB = body;
    def.linearOffset = {2.0f, 1.0f};
    def.angularOffset = 0.5f;
    def.maxForce = 50.0f;
    def.maxTorque = 20.0f;
    const JointId motor = world.createJoint(def);
    for (int i = 0; i < 240; ++i) {
        world.step(h);
        EXPECT_LE(length(world.jointReactionForce(motor)), def.maxForce * 1.0001f);
    }
    EXPECT_NEAR(distance(world.position(body), def.linearOffset), 0.0f, 0.01f);
    EXPECT_NEAR(world.angle(body), def.angularOffset, 0.01f);
}

TEST(JointMouse, PullsTheGrabbedPointToTheTarget) {
    World world;
    const BodyId ground = staticBody(world);
    const BodyId body = box(world, {0.0f, 0.0f}, 0.5f, 0.5f);
    MouseJointDef def;
    def.bodyA = ground;
    def.bodyB = body;
    def.target = {0.5f, 0.5f};  // a corner
    def.maxForce = 1000.0f * world.mass(body);
    const JointId mouse = world.createJoint(def);
    world.setMouseTarget(mouse, {3.0f, 2.0f});
    for (int i = 0; i < 300; ++i) world.step(h);
    // The spring holds the weight: it sags by g/ω² below the target.
    const float omega = 2.0f * pi * def.hertz;
    EXPECT_NEAR(distance(world.jointAnchorB(mouse), {3.0f, 2.0f}), 10.0f / (omega * omega), 0.01f);
}

}  // namespace
}  // namespace perpdot
