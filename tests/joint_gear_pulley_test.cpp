// Gear and pulley joints against their closed forms: a gear keeps coordinateA + ratio·coordinateB
// to 1e-3 over 10 s under load; a pulley keeps lengthA + ratio·lengthB to 1 mm and its heavy side
// falls at the Atwood rate g (m1 − r m2)/(m1 + r² m2) within 1 %. Box2D 2.4.1's b2GearJoint and
// b2PulleyJoint run the built-in scenes alongside; bad definitions are refused.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "joint_helpers.hpp"
#include "perpdot/crosscheck.hpp"
#include "perpdot/error.hpp"
#include "perpdot/scene.hpp"
#include "perpdot/state_hash.hpp"

namespace perpdot {
namespace {

using joint_test::disc;
using joint_test::hinge;
using joint_test::staticBody;

constexpr float h = 1.0f / 60.0f;

// Two wheels on hinges, A carrying an off-centre weight, geared with `ratio`.
struct GearTrain {
    World world;
    BodyId ground, a, b;
    JointId hingeA, hingeB;
};

void weighted(GearTrain& t) {
    ShapeDef lead;
    lead.density = 20.0f;
    lead.filter.group = -1;
    t.world.createShape(t.a, lead, Circle{{0.7f, 0.0f}, 0.3f});
}

TEST(GearJoint, TwoWheelsKeepTheirRatioUnderLoad) {
    for (const float ratio : {2.0f, -0.5f}) {
        GearTrain t;
        t.ground = staticBody(t.world);
        t.a = disc(t.world, {0, 5}, 1.0f);
        t.b = disc(t.world, {3, 5}, 2.0f);
        weighted(t);
        t.hingeA = t.world.createJoint(hinge(t.world, t.ground, t.a, {0, 5}));
        t.hingeB = t.world.createJoint(hinge(t.world, t.ground, t.b, {3, 5}));
        t.world.createJoint(GearJointDef{.jointA = t.hingeA, .jointB = t.hingeB, .ratio = ratio});
        float worst = 0.0f, turned = 0.0f;
        for (int step = 0; step < 600; ++step) {
            t.world.step(h);
            worst = std::max(worst, std::fabs(t.world.angle(t.a) + ratio * t.world.angle(t.b)));
            turned = std::max(turned, std::fabs(t.world.angle(t.a)));
        }
        EXPECT_LT(worst, 1.0e-3f) << "ratio " << ratio;
        EXPECT_GT(turned, 0.5f) << "the weight must swing the train (ratio " << ratio << ")";
    }
}

// A vertical rack that gravity pulls down turns a wheel: θ + ratio·x stays constant, and the rack
// accelerates at m g / (m + I/r²), r = 1/ratio the wheel's pitch radius.
TEST(GearJoint, WheelAndRackKeepTheirRatioUnderLoad) {
    World world;
    const BodyId ground = staticBody(world);
    const BodyId wheel = disc(world, {0, 5}, 1.0f);
    const BodyId rack = joint_test::box(world, {1.2f, 5}, 0.2f, 2.0f, 3.0f);
    const JointId spin = world.createJoint(hinge(world, ground, wheel, {0, 5}));
    const JointId slide = world.createJoint(PrismaticJointDef{
        .bodyA = ground, .bodyB = rack, .localAnchorA = {1.2f, 5}, .localAxisA = {0, 1}});
    const float ratio = 1.0f;  // rack moves −1 m per radian
    world.createJoint(GearJointDef{.jointA = spin, .jointB = slide, .ratio = ratio});
    float worst = 0.0f;
    for (int step = 0; step < 600; ++step) {
        world.step(h);
        const float x = world.position(rack).y - 5.0f;
        worst = std::max(worst, std::fabs(world.angle(wheel) + ratio * x));
    }
    EXPECT_LT(worst, 1.0e-3f);
    const float m = world.mass(rack), I = world.rotationalInertia(wheel);
    const float expected = 10.0f * m / (m + I);
    EXPECT_NEAR(-world.linearVelocity(rack).y, expected * 10.0f, 0.01f * expected * 10.0f);
}

// Two point-like boxes on one rope, lengthA + r·lengthB constant (Box2D's convention): the rope
// pulls A with tension T and B with r·T, so a heavy B (m1) falls at g (m1 − r m2)/(m1 + r² m2)
// while the light A (m2) rises r times as fast.
struct Atwood {
    World world;
    BodyId light, heavy;
    Vec2 groundA{-2, 10}, groundB{2, 10};
    JointId rope;
    Atwood(float lightDensity, float heavyDensity, float ratio) {
        light = block(world, {-2, 6}, lightDensity);
        heavy = block(world, {2, 6}, heavyDensity);
        rope = world.createJoint(PulleyJointDef{.bodyA = light, .bodyB = heavy, .groundAnchorA = groundA,
                                                .groundAnchorB = groundB, .lengthA = 4.0f, .lengthB = 4.0f, .ratio = ratio});
    }
    static BodyId block(World& world, Vec2 position, float density) {
        const BodyId body = world.createBody({.type = BodyType::Dynamic, .position = position, .fixedRotation = true,
                                              .allowSleep = false});
        world.createShape(body, {.density = density}, makeBox(0.5f, 0.5f));
        return body;
    }
};

void expectAtwood(float lightDensity, float heavyDensity, float ratio) {
    Atwood t(lightDensity, heavyDensity, ratio);
    const float m1 = t.world.mass(t.heavy), m2 = t.world.mass(t.light);
    const float a = 10.0f * (m1 - ratio * m2) / (m1 + ratio * ratio * m2);
    const float constant = 4.0f + ratio * 4.0f;
    float worst = 0.0f;
    const int steps = 60;
    for (int step = 0; step < steps; ++step) {
        t.world.step(h);
        const float lengths = distance(t.world.position(t.light), t.groundA) + ratio * distance(t.world.position(t.heavy), t.groundB);
        worst = std::max(worst, std::fabs(lengths - constant));
    }
    const float time = steps * h;
    EXPECT_LT(worst, 1.0e-3f) << "ratio " << ratio;
    EXPECT_NEAR(-t.world.linearVelocity(t.heavy).y, a * time, 0.01f * a * time) << "ratio " << ratio;
    EXPECT_NEAR(t.world.linearVelocity(t.light).y, ratio * a * time, 0.01f * ratio * a * time) << "ratio " << ratio;
    // The rope pulls B up with r·T, T = m2 (g + r a) the tension that lifts A.
    const float pullOnB = ratio * m2 * (10.0f + ratio * a);
    EXPECT_NEAR(t.world.jointReactionForce(t.rope).y, pullOnB, 0.01f * pullOnB) << "ratio " << ratio;
}

TEST(PulleyJoint, HeavySideFallsAtTheAtwoodRate) {
    expectAtwood(1.0f, 2.0f, 1.0f);
    expectAtwood(1.0f, 3.0f, 2.0f);  // block and tackle: A rises at twice B's speed
}

TEST(PulleyJoint, BalancedMachineStaysAtRest) {
    Atwood t(1.0f, 2.0f, 2.0f);  // m1 = r m2: no acceleration
    for (int step = 0; step < 600; ++step) t.world.step(h);
    EXPECT_NEAR(t.world.position(t.heavy).y, 6.0f, 1.0e-3f);
    EXPECT_NEAR(t.world.position(t.light).y, 6.0f, 1.0e-3f);
}

TEST(GearPulleyBadInput, RefusedWithAClearError) {
    World world;
    const BodyId ground = staticBody(world);
    const BodyId a = disc(world, {0, 5}, 1.0f), b = disc(world, {3, 5}, 1.0f), c = disc(world, {6, 5}, 1.0f);
    const JointId hingeA = world.createJoint(hinge(world, ground, a, {0, 5}));
    const JointId hingeB = world.createJoint(hinge(world, ground, b, {3, 5}));
    const JointId floating = world.createJoint(hinge(world, b, c, {6, 5}));
    const JointId weld = world.createJoint(WeldJointDef{.bodyA = ground, .bodyB = c});
    const auto refuses = [&](const auto& def, const std::string& text) {
        try {
            world.createJoint(def);
            ADD_FAILURE() << "accepted; expected \"" << text << "\"";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
        }
    };
    const float nan = std::numeric_limits<float>::quiet_NaN();
    refuses(GearJointDef{.jointA = hingeA, .jointB = hingeB, .ratio = 0.0f}, "ratio must not be 0");
    refuses(GearJointDef{.jointA = hingeA, .jointB = hingeB, .ratio = nan}, "GearJointDef.ratio must be finite");
    refuses(GearJointDef{.jointA = hingeA, .jointB = weld}, "jointB must be a revolute or prismatic joint");
    refuses(GearJointDef{.jointA = hingeA, .jointB = floating}, "jointB's body A must be static");
    refuses(GearJointDef{.jointA = hingeA, .jointB = hingeA}, "move the same body");
    refuses(GearJointDef{.jointA = hingeA, .jointB = JointId{99, 0}}, "JointId {index");
    world.destroyJoint(hingeB);
    refuses(GearJointDef{.jointA = hingeA, .jointB = hingeB}, "JointId {index");

    const PulleyJointDef pulley{.bodyA = a, .bodyB = c, .groundAnchorA = {0, 10}, .groundAnchorB = {6, 10}};
    PulleyJointDef bad = pulley;
    bad.lengthA = 0.0f;
    refuses(bad, "lengthA and lengthB must be > 0");
    bad = pulley;
    bad.ratio = 0.0f;
    refuses(bad, "PulleyJointDef.ratio must be > 0");
    bad = pulley;
    bad.groundAnchorB.x = std::numeric_limits<float>::infinity();
    refuses(bad, "ground anchors must be finite");
    EXPECT_EQ(world.joints().size(), 3u);  // nothing half-made
}

// The scene reader names the JSON path of a bad gear or pulley.
TEST(GearPulleyBadInput, SceneErrorsNameTheJsonPath) {
    Scene scene = findScene("gears");
    const std::string good = toJson(scene);
    EXPECT_EQ(parseScene(good), scene);
    const auto fails = [&](std::string json, const std::string& from, const std::string& to, const std::string& text) {
        const size_t at = json.find(from);
        ASSERT_NE(at, std::string::npos) << from;
        json.replace(at, from.size(), to);
        try {
            parseScene(json);
            ADD_FAILURE() << "accepted " << to;
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
        }
    };
    fails(good, "\"joint_a\":0", "\"joint_a\":3", "joints[3].joint_a: must be the index of an earlier joint");
    fails(good, "\"joint_a\":0", "\"joint_a\":2", "joints[3].body_a: must be the geared joint's body_b");
    fails(good, "\"ratio\":1.5", "\"ratio\":0", "joints[3].ratio: must not be 0");
    fails(good, "\"joint_a\":0,", "", "joints[3].joint_a: missing required key");

    const std::string pulley = toJson(findScene("pulley"));
    EXPECT_EQ(parseScene(pulley), findScene("pulley"));
    fails(pulley, "\"type\":\"pulley\",", "\"type\":\"pulley\",\"ratio\":-1,", "joints[0].ratio: must be positive");
    fails(pulley, "\"type\":\"pulley\",", "\"type\":\"pulley\",\"length_a\":0,", "joints[0].length_a: must be positive");
    fails(pulley, "\"ground_anchor_a\"", "\"ground_anchor\"", "joints[0].ground_anchor: unknown key");
}

// The built-in scenes next to Box2D 2.4.1's b2GearJoint and b2PulleyJoint (at 240 Hz, as the
// other joint cross-checks: docs/joints.md).
void expectAgreement(const char* name, int steps, float tolerance) {
    Scene scene = findScene(name);
    scene.timestep = 1.0f / 240.0f;
    crosscheck::Options options;
    options.steps = steps;
    options.tolerance = tolerance;
    options.angleTolerance = tolerance;
    const crosscheck::Report report = crosscheck::run(scene, options);
    ASSERT_FALSE(report.bodies.empty());
    for (const auto& body : report.bodies) {
        EXPECT_LT(body.position.max, tolerance) << name << " " << body.name;
        EXPECT_LT(body.angle.max, tolerance) << name << " " << body.name;
    }
}

TEST(GearPulleyCrosscheck, GearsAgreeWithBox2D) { expectAgreement("gears", 240, 1.0e-2f); }
TEST(GearPulleyCrosscheck, PulleyAgreesWithBox2D) { expectAgreement("pulley", 240, 1.0e-2f); }

// Snapshots carry the gear and pulley state: restore + N steps equals N steps, bit for bit.
TEST(GearPulleySnapshot, RestoreContinuesBitForBit) {
    for (const char* name : {"gears", "pulley"}) {
        SceneWorld run = buildWorld(findScene(name));
        for (int i = 0; i < 30; ++i) run.step();
        const std::vector<uint8_t> bytes = run.world.snapshot();
        SceneWorld copy = buildWorld(findScene(name));
        copy.world.restore(bytes);
        for (int i = 0; i < 30; ++i) {
            run.world.step(h);
            copy.world.step(h);
        }
        EXPECT_EQ(stateHash(run.world), stateHash(copy.world)) << name;
    }
}

}  // namespace
}  // namespace perpdot
