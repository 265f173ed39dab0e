// Joints changed at run time (World::enableLimit, setLimits, enableMotor, setMaxMotorTorque, the
// spring and length setters) against closed forms, the joint coordinate getters against the
// bodies' motion, the friction joint's constant deceleration, and the goodbye callback of
// destroyBody.
#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

#include "perpdot/error.hpp"
#include "perpdot/world.hpp"
#include "physics_scenes.hpp"

namespace perpdot {
namespace {

using test::dt;
constexpr float pi = 3.14159265f;

// A 2 m × 0.2 m bar on a hinge at its centre (static ground), no gravity: I = m (w² + h²)/12.
struct Hinge {
    World world{WorldDef{.gravity = {0.0f, 0.0f}, .enableSleep = false}};
    BodyId ground, bar;
    JointId joint;
    Hinge() {
        ground = world.createBody({});
        bar = test::addBox(world, {0.0f, 0.0f}, 1.0f, 0.1f, test::material(1.0f));
        joint = world.createJoint(RevoluteJointDef{.bodyA = ground, .bodyB = bar});
    }
    void push(float torque, int steps) {
        for (int i = 0; i < steps; ++i) {
            world.applyTorque(bar, torque);
            world.step(dt);
        }
    }
};

TEST(JointRuntime, RevoluteLimitsSetAtRunTimeHoldUnderATorque) {
    Hinge h;
    h.push(5.0f, 30);  // turns freely first
    const float free = h.world.jointAngle(h.joint);
    ASSERT_GT(free, 0.3f);
    EXPECT_FALSE(h.world.isLimitEnabled(h.joint));
    h.world.setLimits(h.joint, -0.25f, free + 0.2f);
    h.world.enableLimit(h.joint, true);
    EXPECT_TRUE(h.world.isLimitEnabled(h.joint));
    EXPECT_EQ(h.world.upperLimit(h.joint), free + 0.2f);
    for (int i = 0; i < 240; ++i) {
        h.push(20.0f, 1);
        ASSERT_LE(h.world.jointAngle(h.joint), free + 0.2f + 0.01f) << "step " << i;
    }
    EXPECT_NEAR(h.world.jointAngle(h.joint), free + 0.2f, 0.01f);  // pressed against the upper limit
    // Narrowed below the current angle: pushed back, and held at the new lower limit the other way.
    h.world.setLimits(h.joint, -0.25f, 0.1f);
    h.push(0.0f, 60);
    EXPECT_NEAR(h.world.jointAngle(h.joint), 0.1f, 0.01f);
    h.push(-20.0f, 240);
    EXPECT_NEAR(h.world.jointAngle(h.joint), -0.25f, 0.01f);
    // Off again: the torque turns it past the old limit.
    h.world.enableLimit(h.joint, false);
    h.push(-20.0f, 30);
    EXPECT_LT(h.world.jointAngle(h.joint), -0.5f);
    EXPECT_THROW(h.world.setLimits(h.joint, 1.0f, 0.0f), Error);
}

// Switched on at run time the motor spins the bar up at α = T/I (its torque bound) until it
// reaches the speed; a lower bound slows the spin-up in proportion.
TEST(JointRuntime, AMotorEnabledAtRunTimeDrivesTheSpeedWithItsTorqueCapped) {
    Hinge h;
    const float inertia = h.world.rotationalInertia(h.bar);
    EXPECT_FALSE(h.world.isMotorEnabled(h.joint));
    h.world.enableMotor(h.joint, true);
    h.world.setMotorSpeed(h.joint, 4.0f);
    h.world.setMaxMotorTorque(h.joint, 0.5f);
    EXPECT_EQ(h.world.motorSpeed(h.joint), 4.0f);
    EXPECT_EQ(h.world.maxMotorTorque(h.joint), 0.5f);
    h.push(0.0f, 30);  // 0.5 s at α = 0.5/I
    const float expected = 0.5f / inertia * 30.0f * dt;
    ASSERT_LT(expected, 4.0f);
    EXPECT_NEAR(h.world.jointAngularSpeed(h.joint), expected, 1e-3f * expected);
    EXPECT_NEAR(h.world.motorTorque(h.joint), 0.5f, 1e-4f);
    h.world.setMaxMotorTorque(h.joint, 100.0f);
    h.push(0.0f, 30);
    EXPECT_NEAR(h.world.jointAngularSpeed(h.joint), 4.0f, 1e-3f);
    EXPECT_NEAR(h.world.motorTorque(h.joint), 0.0f, 1e-3f);  // at speed, nothing left to do
    h.world.enableMotor(h.joint, false);
    h.push(-1.0f, 30);  // free again: the torque slows it at 1/I
    EXPECT_NEAR(h.world.jointAngularSpeed(h.joint), 4.0f - 30.0f * dt / inertia, 1e-3f);
}

// Two dynamic bodies hinged together, spun and thrown: the angle is θB − θA − θref, its rate the
// relative angular velocity (finite differences of the angle over a step agree).
TEST(JointRuntime, RevoluteAngleAndSpeedFollowTheBodies) {
    World world(WorldDef{.gravity = {0.0f, 0.0f}, .enableSleep = false});
    const BodyId a = test::addBox(world, {0.0f, 0.0f}, 0.5f, 0.5f, test::material(1.0f));
    const BodyId b = test::addBox(world, {1.0f, 0.0f}, 0.5f, 0.2f, test::material(1.0f), 0.3f);
    const JointId joint = world.createJoint(RevoluteJointDef{
        .bodyA = a, .bodyB = b, .localAnchorA = {0.5f, 0.0f}, .localAnchorB = invTransformPoint(world.transform(b), {0.5f, 0.0f}),
        .referenceAngle = 0.3f});
    world.setAngularVelocity(a, 1.0f);
    world.setAngularVelocity(b, -2.0f);
    world.setLinearVelocity(a, {2.0f, 1.0f});
    world.step(dt);
    for (int i = 0; i < 60; ++i) {
        const float before = world.jointAngle(joint);
        const float speed = world.jointAngularSpeed(joint);
        world.step(dt);
        EXPECT_EQ(world.jointAngle(joint), world.angle(b) - world.angle(a) - 0.3f);
        EXPECT_EQ(world.jointAngularSpeed(joint), world.angularVelocity(b) - world.angularVelocity(a));
        // The speed changes within the step (the substeps trade momentum): the angle advances by
        // h times about the mean of the speeds at the step's ends.
        const float turned = world.jointAngle(joint) - before;
        EXPECT_NEAR(turned, 0.5f * dt * (speed + world.jointAngularSpeed(joint)), 0.02f * std::fabs(turned) + 1e-5f);
    }
}

// A slider on a turning body: the translation is the anchors' separation along the world axis and
// the linear speed its rate (finite differences agree, the axis's turn included).
TEST(JointRuntime, PrismaticTranslationAndSpeedFollowTheBodies) {
    World world(WorldDef{.gravity = {0.0f, 0.0f}, .enableSleep = false});
    const BodyId a = test::addBox(world, {0.0f, 0.0f}, 1.0f, 0.2f, test::material(1.0f));
    const BodyId b = test::addBox(world, {0.5f, 0.0f}, 0.2f, 0.2f, test::material(1.0f));
    const JointId joint = world.createJoint(PrismaticJointDef{.bodyA = a, .bodyB = b, .localAxisA = {1.0f, 0.0f}});
    EXPECT_NEAR(world.jointTranslation(joint), 0.5f, 1e-6f);
    world.setAngularVelocity(a, 0.5f);
    world.setAngularVelocity(b, 0.5f);
    world.setLinearVelocity(b, {1.0f, 0.0f});
    world.step(dt);
    for (int i = 0; i < 60; ++i) {
        const float before = world.jointTranslation(joint);
        const float speed = world.jointLinearSpeed(joint);
        world.step(dt);
        const Vec2 axis = rotate(world.transform(a).q, {1.0f, 0.0f});
        EXPECT_NEAR(world.jointTranslation(joint), dot(world.position(b) - world.position(a), axis), 1e-5f);
        EXPECT_NEAR(world.jointTranslation(joint) - before, 0.5f * dt * (speed + world.jointLinearSpeed(joint)), 2e-4f);
    }
    EXPECT_GT(world.jointTranslation(joint), 0.6f);  // it slid outwards
}

// Prismatic motor switched on at run time accelerates the slider at F/m up to its speed; a limit
// set then stops it there.
TEST(JointRuntime, PrismaticMotorForceAndLimitsAtRunTime) {
    World world(WorldDef{.gravity = {0.0f, 0.0f}, .enableSleep = false});
    const BodyId ground = world.createBody({});
    const BodyId slider = test::addBox(world, {0.0f, 0.0f}, 0.5f, 0.5f, test::material(2.0f));
    const JointId joint = world.createJoint(PrismaticJointDef{.bodyA = ground, .bodyB = slider});
    const float m = world.mass(slider);
    world.enableMotor(joint, true);
    world.setMotorSpeed(joint, 3.0f);
    world.setMaxMotorForce(joint, 1.0f);
    test::run(world, 30);
    EXPECT_NEAR(world.jointLinearSpeed(joint), 1.0f / m * 30.0f * dt, 1e-4f);
    EXPECT_NEAR(world.motorForce(joint), 1.0f, 1e-4f);
    world.setMaxMotorForce(joint, 50.0f);
    world.setLimits(joint, -1.0f, 1.5f);
    world.enableLimit(joint, true);
    test::run(world, 120);
    EXPECT_NEAR(world.jointTranslation(joint), 1.5f, 0.01f);
    EXPECT_NEAR(world.motorForce(joint), 50.0f, 0.01f);  // pushing against the limit with all it has
    EXPECT_THROW(world.setMaxMotorTorque(joint, 1.0f), Error);  // a prismatic motor has a force
}

// A wheel on a vertical suspension under gravity sags g/ω² (k = m ω² with A static, ω = 2π f):
// a spring stiffened at run time sags a quarter as far at twice the frequency.
TEST(JointRuntime, WheelSpringStiffnessChangedAtRunTimeChangesTheSag) {
    World world(WorldDef{.enableSleep = false});
    const BodyId ground = world.createBody({});
    const BodyId wheel = test::addDisc(world, {0.0f, 0.0f}, 0.3f);
    const JointId joint = world.createJoint(WheelJointDef{.bodyA = ground, .bodyB = wheel, .hertz = 2.0f, .dampingRatio = 1.0f});
    auto sag = [&](float hertz) {
        world.setSpringHertz(joint, hertz);
        test::run(world, 300);
        const float omega = 2.0f * pi * hertz;
        EXPECT_NEAR(world.jointTranslation(joint), -10.0f / (omega * omega), 0.01f * 10.0f / (omega * omega)) << hertz;
    };
    sag(2.0f);
    world.setSpringDampingRatio(joint, 2.0f);
    EXPECT_EQ(world.springDampingRatio(joint), 2.0f);
    sag(4.0f);
    EXPECT_EQ(world.springHertz(joint), 4.0f);
    EXPECT_THROW(world.setSpringHertz(joint, -1.0f), Error);
}

// A pendulum rod lengthened at run time hangs at the new length; a rope range keeps a spring's
// anchors within [min, max].
TEST(JointRuntime, DistanceLengthAndRangeChangedAtRunTime) {
    World world(WorldDef{.enableSleep = false});
    const BodyId ground = world.createBody({});
    const BodyId bob = test::addDisc(world, {0.0f, -1.0f}, 0.1f);
    const JointId rod = world.createJoint(DistanceJointDef{.bodyA = ground, .bodyB = bob, .length = 1.0f});
    test::run(world, 60);
    EXPECT_NEAR(world.currentLength(rod), 1.0f, 1e-3f);
    world.setLength(rod, 2.0f);
    EXPECT_EQ(world.restLength(rod), 2.0f);
    test::run(world, 240);
    EXPECT_NEAR(world.currentLength(rod), 2.0f, 2e-3f);
    // A very soft spring: gravity would stretch it far; the range's maximum holds it (Box2D's rope).
    world.setSpringHertz(rod, 0.1f);
    world.setSpringDampingRatio(rod, 1.0f);
    world.setLengthRange(rod, 0.5f, 2.5f);
    EXPECT_EQ(world.minLength(rod), 0.5f);
    EXPECT_EQ(world.maxLength(rod), 2.5f);
    test::run(world, 240);
    EXPECT_NEAR(world.currentLength(rod), 2.5f, 5e-3f);
    EXPECT_THROW(world.setLengthRange(rod, 2.0f, 1.0f), Error);
    EXPECT_THROW(world.setLimits(rod, 0.0f, 1.0f), Error);
}

// Top-down friction: a box slid and spun on a friction joint to the static ground decelerates at
// F/m and its spin at T/I, then stays still; a push below the bounds never moves it.
TEST(JointRuntime, FrictionJointDeceleratesAtItsBoundsAndHoldsBelowThem) {
    World world(WorldDef{.gravity = {0.0f, 0.0f}, .enableSleep = false});
    const BodyId ground = world.createBody({});
    const BodyId box = test::addBox(world, {0.0f, 0.0f}, 0.5f, 0.25f, test::material(2.0f));
    const float m = world.mass(box), inertia = world.rotationalInertia(box);
    const JointId joint = world.createJoint(FrictionJointDef{.bodyA = ground, .bodyB = box, .maxForce = 2.0f, .maxTorque = 0.1f});
    EXPECT_EQ(world.jointType(joint), JointType::Friction);
    world.setLinearVelocity(box, {3.0f, -1.0f});
    world.setAngularVelocity(box, 2.0f);
    test::run(world, 30);
    const float t = 30.0f * dt;
    const float v = std::sqrt(10.0f) - 2.0f / m * t;
    EXPECT_NEAR(length(world.linearVelocity(box)), v, 1e-3f);
    EXPECT_NEAR(world.linearVelocity(box).x / world.linearVelocity(box).y, -3.0f, 1e-3f);  // straight on
    EXPECT_NEAR(world.angularVelocity(box), 2.0f - 0.1f / inertia * t, 1e-3f);
    // Bounds raised at run time: stops within the next step.
    world.setMaxForce(joint, 1000.0f);
    world.setMaxTorque(joint, 1000.0f);
    test::run(world, 2);
    EXPECT_NEAR(length(world.linearVelocity(box)), 0.0f, 1e-5f);
    EXPECT_NEAR(world.angularVelocity(box), 0.0f, 1e-5f);
    world.setMaxForce(joint, 2.0f);
    world.setMaxTorque(joint, 0.1f);
    const Vec2 still = world.position(box);
    for (int i = 0; i < 120; ++i) {
        world.applyForceToCenter(world.jointBodyB(joint), {1.5f, 1.0f});  // |F| 1.8 < 2
        world.applyTorque(box, 0.09f);
        world.step(dt);
    }
    EXPECT_NEAR(distance(world.position(box), still), 0.0f, 1e-5f);
    EXPECT_NEAR(world.angularVelocity(box), 0.0f, 1e-5f);
    EXPECT_EQ(world.maxForce(joint), 2.0f);
    EXPECT_THROW(world.createJoint(FrictionJointDef{.bodyA = ground, .bodyB = box, .maxForce = -1.0f}), Error);
}

TEST(JointRuntime, UserDataCanBeReadAndChanged) {
    World world;
    const BodyId ground = world.createBody({});
    const BodyId bob = test::addDisc(world, {0.0f, -1.0f}, 0.1f);
    int tag = 0, other = 0;
    const JointId joint = world.createJoint(DistanceJointDef{.bodyA = ground, .bodyB = bob, .userData = &tag});
    EXPECT_EQ(world.userData(joint), &tag);
    world.setUserData(joint, &other);
    EXPECT_EQ(world.userData(joint), &other);
}

// destroyBody says goodbye to each joint it destroys with the body (stale ids, their userData),
// after the body is gone; destroyJoint does not.
TEST(JointRuntime, DestroyingABodyReportsTheJointsItDestroys) {
    World world;
    const BodyId ground = world.createBody({});
    const BodyId a = test::addDisc(world, {0.0f, -1.0f}, 0.1f);
    const BodyId b = test::addDisc(world, {1.0f, -1.0f}, 0.1f);
    int tags[3] = {};
    const JointId toGround = world.createJoint(DistanceJointDef{.bodyA = ground, .bodyB = a, .userData = &tags[0]});
    const JointId between = world.createJoint(RevoluteJointDef{.bodyA = a, .bodyB = b, .userData = &tags[1]});
    const JointId kept = world.createJoint(DistanceJointDef{.bodyA = ground, .bodyB = b, .userData = &tags[2]});
    const JointId destroyed = world.createJoint(WeldJointDef{.bodyA = ground, .bodyB = a});
    std::vector<std::pair<JointId, void*>> goodbyes;
    world.setJointDestroyedCallback([&](JointId joint, void* data) {
        EXPECT_FALSE(world.isValid(joint));
        EXPECT_FALSE(world.isValid(a));  // the body is gone first
        goodbyes.emplace_back(joint, data);
    });
    world.destroyJoint(destroyed);
    EXPECT_TRUE(goodbyes.empty());
    world.destroyBody(a);
    ASSERT_EQ(goodbyes.size(), 2u);
    const bool inOrder = goodbyes[0].first == toGround;
    EXPECT_EQ(goodbyes[inOrder ? 0 : 1].first, toGround);
    EXPECT_EQ(goodbyes[inOrder ? 0 : 1].second, &tags[0]);
    EXPECT_EQ(goodbyes[inOrder ? 1 : 0].first, between);
    EXPECT_EQ(goodbyes[inOrder ? 1 : 0].second, &tags[1]);
    EXPECT_TRUE(world.isValid(kept));
    world.setJointDestroyedCallback({});
    world.destroyBody(b);
    EXPECT_EQ(goodbyes.size(), 2u);
}

}  // namespace
}  // namespace perpdot
