// Filter joint (Box2D v3's b2FilterJointDef): its two bodies pass through each other, and collide
// again once it is destroyed; it has no rows, and it survives a snapshot.
#include <gtest/gtest.h>

#include <vector>

#include "joint_helpers.hpp"
#include "perpdot/error.hpp"
#include "perpdot/state_hash.hpp"
#include "perpdot/world.hpp"

namespace perpdot {
namespace {

using joint_test::box;

struct Overlap {
    World world{WorldDef{.gravity = {0.0f, 0.0f}}};
    BodyId a = box(world, {0.0f, 0.0f}, 0.5f, 0.5f);
    BodyId b = box(world, {0.6f, 0.0f}, 0.5f, 0.5f);  // 0.4 m deep in a

    void step(int steps) {
        for (int i = 0; i < steps; ++i) world.step(1.0f / 60.0f);
    }
};

TEST(FilterJoint, OverlappingBodiesCollideWithoutIt) {
    Overlap s;
    s.step(30);
    EXPECT_GT(s.world.position(s.b).x - s.world.position(s.a).x, 0.9f) << "pushed apart";
}

TEST(FilterJoint, OverlappingBodiesStayWhereTheyAre) {
    Overlap s;
    s.world.createJoint(FilterJointDef{.bodyA = s.a, .bodyB = s.b});
    s.step(30);
    EXPECT_EQ(s.world.contactCount(), 0);
    EXPECT_EQ(s.world.position(s.a), (Vec2{0.0f, 0.0f}));
    EXPECT_EQ(s.world.position(s.b), (Vec2{0.6f, 0.0f}));
}

TEST(FilterJoint, BodiesPassThroughEachOther) {
    Overlap s;
    s.world.createJoint(FilterJointDef{.bodyA = s.a, .bodyB = s.b});
    s.world.setLinearVelocity(s.a, {3.0f, 0.0f});
    s.step(60);  // a crosses all of b
    EXPECT_EQ(s.world.linearVelocity(s.a), (Vec2{3.0f, 0.0f}));
    EXPECT_EQ(s.world.linearVelocity(s.b), (Vec2{0.0f, 0.0f}));
    EXPECT_NEAR(s.world.position(s.a).x, 3.0f, 1e-4f);
}

TEST(FilterJoint, DestroyingItRestoresCollision) {
    Overlap s;
    const JointId filter = s.world.createJoint(FilterJointDef{.bodyA = s.a, .bodyB = s.b});
    s.step(30);
    EXPECT_EQ(s.world.position(s.b).x - s.world.position(s.a).x, 0.6f);
    s.world.destroyJoint(filter);
    s.step(30);
    EXPECT_GT(s.world.contactCount(), 0);
    EXPECT_GT(s.world.position(s.b).x - s.world.position(s.a).x, 0.9f) << "pushed apart";
}

// a leaves its fat box every step (0.15 m a step, Box2D's margin is 0.1 m), so the box it moved
// from overlapped b's: the pair finder must still look the pair up once the joint is gone.
TEST(FilterJoint, DestroyingItWhileABodyMovesRestoresCollisionAtOnce) {
    Overlap s;
    const JointId filter = s.world.createJoint(FilterJointDef{.bodyA = s.a, .bodyB = s.b});
    s.world.setLinearVelocity(s.a, {9.0f, 0.0f});
    s.step(2);
    ASSERT_EQ(s.world.contactCount(), 0);
    s.world.destroyJoint(filter);
    s.step(1);
    EXPECT_EQ(s.world.contactCount(), 1);
}

TEST(FilterJoint, HasNoRowsAndNoMotor) {
    Overlap s;
    const JointId filter = s.world.createJoint(FilterJointDef{.bodyA = s.a, .bodyB = s.b});
    s.step(2);
    EXPECT_EQ(s.world.jointType(filter), JointType::Filter);
    EXPECT_EQ(s.world.jointBodyA(filter), s.a);
    EXPECT_EQ(s.world.jointBodyB(filter), s.b);
    EXPECT_EQ(s.world.jointReactionForce(filter), (Vec2{0.0f, 0.0f}));
    EXPECT_EQ(s.world.jointReactionTorque(filter), 0.0f);
    EXPECT_THROW(s.world.setMotorSpeed(filter, 1.0f), Error);
    EXPECT_THROW(s.world.createJoint(FilterJointDef{.bodyA = s.a, .bodyB = s.a}), Error);
}

// Restored, the world continues exactly: same hash, same bytes, still passing through.
TEST(FilterJoint, SurvivesSnapshotAndRestore) {
    Overlap s;
    s.world.createJoint(FilterJointDef{.bodyA = s.a, .bodyB = s.b});
    s.world.setLinearVelocity(s.a, {3.0f, 0.5f});
    s.world.setAngularVelocity(s.b, 1.0f);
    s.step(10);
    const std::vector<uint8_t> bytes = s.world.snapshot();
    World restored;
    restored.restore(bytes);
    EXPECT_EQ(stateHash(restored), stateHash(s.world));
    EXPECT_EQ(restored.snapshot(), bytes);
    ASSERT_EQ(restored.joints().size(), 1u);
    EXPECT_EQ(restored.jointType(restored.joints()[0]), JointType::Filter);
    for (int i = 0; i < 50; ++i) {
        s.world.step(1.0f / 60.0f);
        restored.step(1.0f / 60.0f);
        ASSERT_EQ(stateHash(restored), stateHash(s.world)) << "step " << i;
    }
    EXPECT_EQ(restored.contactCount(), 0);
    EXPECT_EQ(restored.snapshot(), s.world.snapshot());
}

}  // namespace
}  // namespace perpdot
