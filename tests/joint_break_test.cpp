// Breakable joints (World::setJointBreakLimits) against closed forms: a hanging mass pulls m g on
// its joint, and a pendulum released horizontal pulls T = 3 m g sin θ at θ below the horizontal
// (energy: v² = 2 g L sin θ; radial: T − m g sin θ = m v²/L), 3 m g at the bottom.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "perpdot/error.hpp"
#include "perpdot/scene.hpp"
#include "perpdot/world.hpp"
#include "physics_scenes.hpp"

namespace perpdot {
namespace {

using test::dt;
constexpr float g = 10.0f;
constexpr float never = std::numeric_limits<float>::infinity();

struct Hanging {
    World world{WorldDef{.enableSleep = false}};
    BodyId anchor, bob;
    JointId joint;
    float weight = 0.0f;  // m g, N
};

// A 0.2 m disc on a 1 m rod from a static anchor, hanging straight down (`release` false) or
// released horizontal (true).
void build(Hanging& h, bool horizontal) {
    h.anchor = h.world.createBody(test::bodyAt({0.0f, 5.0f}, BodyType::Static));
    h.bob = test::addDisc(h.world, horizontal ? Vec2{1.0f, 5.0f} : Vec2{0.0f, 4.0f}, 0.2f);
    DistanceJointDef def;
    def.bodyA = h.anchor;
    def.bodyB = h.bob;
    def.length = 1.0f;
    h.joint = h.world.createJoint(def);
    h.weight = h.world.mass(h.bob) * g;
}

TEST(JointBreak, AHangingMassHoldsAboveItsWeightAndBreaksBelow) {
    Hanging holds;
    build(holds, false);
    holds.world.setJointBreakLimits(holds.joint, 1.05f * holds.weight, never);
    for (int i = 0; i < 600; ++i) {
        holds.world.step(dt);
        ASSERT_TRUE(holds.world.jointEvents().breakEvents.empty()) << "broke at step " << i;
    }
    EXPECT_NEAR(length(holds.world.jointReactionForce(holds.joint)), holds.weight, 0.01f * holds.weight);

    Hanging breaks;
    build(breaks, false);
    breaks.world.setJointBreakLimits(breaks.joint, 0.95f * breaks.weight, never);
    int brokeAt = -1;
    for (int i = 0; i < 10 && brokeAt < 0; ++i) {
        breaks.world.step(dt);
        if (!breaks.world.jointEvents().breakEvents.empty()) brokeAt = i;
    }
    ASSERT_GE(brokeAt, 0);
    EXPECT_LE(brokeAt, 2) << "the load is there from the first step";
    const JointBreakEvent e = breaks.world.jointEvents().breakEvents[0];
    EXPECT_EQ(e.joint, breaks.joint);
    EXPECT_TRUE(e.destroyed);
    EXPECT_GT(length(e.force), 0.95f * breaks.weight);
    EXPECT_FALSE(breaks.world.isValid(breaks.joint));
    // Free now: it falls at g.
    const float v0 = breaks.world.linearVelocity(breaks.bob).y;
    test::run(breaks.world, 30);
    EXPECT_NEAR(breaks.world.linearVelocity(breaks.bob).y - v0, -g * 30.0f * dt, 1e-3f);
}

// Limit 2 m g: T = 3 m g sin θ passes it at sin θ = 2/3 (θ = 41.8°), before the bottom; with 3.3 m g
// the pendulum swings through the bottom (3 m g) and never breaks.
TEST(JointBreak, APendulumBreaksWhereItsTensionPassesTheLimit) {
    Hanging swing;
    build(swing, true);
    swing.world.setJointBreakLimits(swing.joint, 2.0f * swing.weight, never);
    float brokeBelow = -1.0f;  // θ below the horizontal when it broke, rad
    for (int i = 0; i < 120 && brokeBelow < 0.0f; ++i) {
        const Vec2 before = swing.world.position(swing.bob) - Vec2{0.0f, 5.0f};
        swing.world.step(dt);
        if (!swing.world.jointEvents().breakEvents.empty()) brokeBelow = std::asin(std::clamp(-before.y, -1.0f, 1.0f));
    }
    ASSERT_GE(brokeBelow, 0.0f) << "never broke";
    // One step of the swing near there turns it about 0.09 rad.
    EXPECT_NEAR(brokeBelow, std::asin(2.0f / 3.0f), 0.12f);

    Hanging whole;
    build(whole, true);
    whole.world.setJointBreakLimits(whole.joint, 3.3f * whole.weight, never);
    float lowest = 5.0f;
    for (int i = 0; i < 120; ++i) {
        whole.world.step(dt);
        ASSERT_TRUE(whole.world.jointEvents().breakEvents.empty()) << "broke at step " << i;
        lowest = std::min(lowest, whole.world.position(whole.bob).y);
    }
    EXPECT_NEAR(lowest, 4.0f, 0.01f) << "it swung through the bottom";
}

// A torque limit on a weld: a 1 m cantilever of mass m pulls m g · 0.5 m on its root.
TEST(JointBreak, AWeldBreaksOnTorqueAndCanStayWhenAskedTo) {
    World world({.enableSleep = false});
    const BodyId wall = world.createBody(test::bodyAt({0.0f, 5.0f}, BodyType::Static));
    const BodyId beam = test::addBox(world, {0.5f, 5.0f}, 0.5f, 0.05f);
    WeldJointDef def;
    def.bodyA = wall;
    def.bodyB = beam;
    def.localAnchorB = {-0.5f, 0.0f};
    const JointId weld = world.createJoint(def);
    const float torque = world.mass(beam) * g * 0.5f;
    world.setJointBreakLimits(weld, never, 0.8f * torque, false);
    test::run(world, 3);
    ASSERT_FALSE(world.jointEvents().breakEvents.empty());
    EXPECT_FALSE(world.jointEvents().breakEvents[0].destroyed);
    EXPECT_NEAR(std::fabs(world.jointEvents().breakEvents[0].torque), torque, 0.05f * torque);
    EXPECT_TRUE(world.isValid(weld)) << "destroy = false keeps it";
    world.setJointBreakLimits(weld, never, 1.2f * torque, false);
    test::run(world, 60);
    EXPECT_TRUE(world.jointEvents().breakEvents.empty());
}

TEST(JointBreak, RefusesBadLimitsAndSurvivesASnapshot) {
    Hanging h;
    build(h, false);
    EXPECT_THROW(h.world.setJointBreakLimits(h.joint, -1.0f, never), Error);
    EXPECT_THROW(h.world.setJointBreakLimits(h.joint, never, std::nanf("")), Error);
    EXPECT_THROW(h.world.setJointBreakLimits(JointId{}, 1.0f, 1.0f), Error);
    h.world.setJointBreakLimits(h.joint, 0.95f * h.weight, never);
    const std::vector<uint8_t> saved = h.world.snapshot();
    World restored;
    restored.restore(saved);
    restored.step(dt);
    h.world.step(dt);
    EXPECT_EQ(restored.jointEvents().breakEvents.size(), h.world.jointEvents().breakEvents.size());
    EXPECT_EQ(restored.jointEvents().breakEvents.size(), 1u);
}

// A one-step blow: an explosion-like impulse changes a 0.6 kg sign's velocity by 16 m/s; its weld
// to a post stops it within the step, so the average force over the step is about m·16/h = 576 N
// and a 60 N limit trips, although the last substep's reaction is far below the blow. Steady loads
// below the limit (50 N sideways, beside the 6 N weight) never trip it.
TEST(JointBreak, AOneStepBlowTripsALimitThatSteadyLoadsBelowItNeverDo) {
    struct Sign {
        World world{WorldDef{.enableSleep = false}};
        BodyId sign;
        JointId weld;
        Sign() {
            const BodyId post = world.createBody(test::bodyAt({0.0f, 5.0f}, BodyType::Static));
            sign = test::addBox(world, {0.0f, 4.0f}, 0.3f, 0.5f, test::material(1.0f));
            WeldJointDef def;
            def.bodyA = post;
            def.bodyB = sign;
            def.localAnchorA = {0.0f, -0.5f};
            def.localAnchorB = {0.0f, 0.5f};
            weld = world.createJoint(def);
            world.setJointBreakLimits(weld, 60.0f, never);
        }
    };
    Sign blown;
    const float m = blown.world.mass(blown.sign);
    ASSERT_NEAR(m, 0.6f, 1e-5f);
    test::run(blown.world, 30);
    ASSERT_TRUE(blown.world.isValid(blown.weld));
    blown.world.applyLinearImpulseToCenter(blown.sign, {m * 16.0f, 0.0f});
    blown.world.step(dt);
    ASSERT_EQ(blown.world.jointEvents().breakEvents.size(), 1u) << "the blow did not trip the limit";
    const JointBreakEvent e = blown.world.jointEvents().breakEvents[0];
    EXPECT_GT(length(e.force), 0.8f * m * 16.0f / dt);  // the blow is stopped within the step
    EXPECT_LT(length(e.force), 1.5f * m * 16.0f / dt);  // the soft weld pulls it back a little too
    EXPECT_FALSE(blown.world.isValid(blown.weld));

    Sign steady;
    for (int i = 0; i < 600; ++i) {
        steady.world.applyForceToCenter(steady.sign, {50.0f, 0.0f});
        steady.world.step(dt);
        ASSERT_TRUE(steady.world.jointEvents().breakEvents.empty()) << "broke at step " << i;
    }
    Sign over;
    int brokeAt = -1;
    for (int i = 0; i < 10 && brokeAt < 0; ++i) {
        over.world.applyForceToCenter(over.sign, {70.0f, 0.0f});
        over.world.step(dt);
        if (!over.world.jointEvents().breakEvents.empty()) brokeAt = i;
    }
    EXPECT_EQ(brokeAt, 0) << "70 N is over the limit from the first step";
}

// The built-in scene: hinges that break above 800 N; the settling deck alone pulls them up to about
// 400 N, with the 80 kg anvil on it 1,560 N.
TEST(JointBreak, TheBreakableBridgeSnapsUnderTheAnvil) {
    SceneWorld built = buildWorld(findScene("breakable_bridge"));
    int breaks = 0;
    for (int i = 0; i < 240; ++i) {
        built.step();
        breaks += static_cast<int>(built.world.jointEvents().breakEvents.size());
    }
    EXPECT_GT(breaks, 0);
    EXPECT_LT(built.world.position(built.bodies.back()).y, 2.0f) << "the anvil went through the deck";
    Scene calm = findScene("breakable_bridge");
    calm.bodies.pop_back();  // no anvil
    SceneWorld quiet = buildWorld(calm);
    for (int i = 0; i < 240; ++i) {
        quiet.step();
        ASSERT_TRUE(quiet.world.jointEvents().breakEvents.empty()) << "broke without the anvil at step " << i;
    }
}

}  // namespace
}  // namespace perpdot
