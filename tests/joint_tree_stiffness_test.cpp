// Geometric stiffness of revolute trees (src/core/joints/joint_tree_stiffness.hpp): chains and
// trees whose ends outweigh a link 1000 and 10,000 times keep their hinges closed through the
// motion, and the added inertia takes energy out, never in; so do closed loops of hinges carrying
// 1000 times a link's mass, solved directly since K's diagonal is raised (joint_tree.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "joint_helpers.hpp"
#include "perpdot/scene.hpp"

namespace perpdot {
namespace {

using namespace joint_test;

constexpr float g = 10.0f;

float energyOf(const World& world, const std::vector<BodyId>& bodies) {
    float e = 0.0f;
    for (BodyId b : bodies) e += energy(world, b);
    return e;
}

// The worst hinge gap over `steps` steps at 60 Hz, and the most the energy rose above its start.
struct Motion {
    float worstGap = 0.0f, energyRise = 0.0f, energyScale = 0.0f, worstAngle = 0.0f;
};
Motion run(World& world, const std::vector<BodyId>& bodies, const std::vector<JointId>& joints, int steps) {
    Motion m;
    const float e0 = energyOf(world, bodies);
    for (int step = 0; step < steps; ++step) {
        world.step(1.0f / 60.0f);
        for (JointId j : joints) {
            m.worstGap = std::max(m.worstGap, distance(world.jointAnchorA(j), world.jointAnchorB(j)));
            m.worstAngle = std::max(m.worstAngle, std::fabs(world.jointAngle(j)));
        }
        m.energyRise = std::max(m.energyRise, energyOf(world, bodies) - e0);
    }
    // The energy the end's fall of a chain's length makes: the scale of the swing.
    for (BodyId b : bodies) m.energyScale = std::max(m.energyScale, world.mass(b) * g * 10.0f);
    return m;
}

// 20 links of 0.5 m pinned at one end, released horizontal, the last `ratio` times a link's mass.
class HeavyEndedChain : public ::testing::TestWithParam<float> {};

TEST_P(HeavyEndedChain, KeepsEveryHingeWithinOnePercentOfALinkForThreeSeconds) {
    World world(WorldDef{.gravity = {0.0f, -g}});
    const Vec2 pin{0.0f, 20.0f};
    BodyId previous = staticBody(world, pin);
    std::vector<BodyId> links;
    std::vector<JointId> joints;
    for (int i = 0; i < 20; ++i) {
        links.push_back(box(world, pin + Vec2{(static_cast<float>(i) + 0.5f) * 0.5f, 0.0f}, 0.25f, 0.05f, i == 19 ? GetParam() : 1.0f));
        joints.push_back(world.createJoint(hinge(world, previous, links.back(), pin + Vec2{static_cast<float>(i) * 0.5f, 0.0f})));
        previous = links.back();
    }
    const Motion m = run(world, links, joints, 180);
    EXPECT_LT(m.worstGap, 0.01f * 0.5f);
    EXPECT_LT(m.energyRise, 1e-3f * m.energyScale) << "the energy does not grow";
}

INSTANTIATE_TEST_SUITE_P(RevoluteTree, HeavyEndedChain, ::testing::Values(1000.0f, 10000.0f));

// The same chains with a motor at every hinge (1 N·m toward 0.5 rad/s): a tree solves each motor
// row one by one, then the point rows as one system. Solved row by row, such chains (0.01 and
// 100 N·m) opened 2.6 and 2.7 m at 1000 : 1, 34 and 32 m at 10,000 : 1.
TEST_P(HeavyEndedChain, WithMotorsKeepsEveryHingeWithinOnePercentOfALink) {
    World world(WorldDef{.gravity = {0.0f, -g}});
    const Vec2 pin{0.0f, 20.0f};
    BodyId previous = staticBody(world, pin);
    std::vector<BodyId> links;
    std::vector<JointId> joints;
    for (int i = 0; i < 20; ++i) {
        links.push_back(box(world, pin + Vec2{(static_cast<float>(i) + 0.5f) * 0.5f, 0.0f}, 0.25f, 0.05f, i == 19 ? GetParam() : 1.0f));
        RevoluteJointDef def = hinge(world, previous, links.back(), pin + Vec2{static_cast<float>(i) * 0.5f, 0.0f});
        def.enableMotor = true;
        def.motorSpeed = 0.5f;
        def.maxMotorTorque = 1.0f;
        joints.push_back(world.createJoint(def));
        previous = links.back();
    }
    const Motion m = run(world, links, joints, 180);
    EXPECT_LT(m.worstGap, 0.01f * 0.5f);
}

// A pinned hub with two 5-link arms, each ending in a hand 10,000 times a link's mass, released
// from the horizontal: a branched tree whose hands swing and pull its arms taut. Its bodies share
// a collision group, as a ragdoll's do: the hands meeting under the hub would be contacts, which
// the direct solve does not take: they run in the sequential passes, and with them this tree's
// hinges open 3.1 m.
TEST(RevoluteTree, BranchedTreeWithHeavyHandsKeepsItsHingesClosed) {
    World world(WorldDef{.gravity = {0.0f, -g}});
    const BodyId pin = staticBody(world, {0.0f, 10.0f});
    const BodyId hub = box(world, {0.0f, 9.5f}, 0.1f, 0.5f);
    std::vector<BodyId> bodies{hub};
    std::vector<JointId> joints{world.createJoint(hinge(world, pin, hub, {0.0f, 10.0f}))};
    for (const float side : {-1.0f, 1.0f}) {
        BodyId previous = hub;
        for (int i = 0; i < 5; ++i) {
            const float x = side * (0.5f * static_cast<float>(i) + 0.25f);
            bodies.push_back(box(world, {x, 9.0f}, 0.25f, 0.05f, i == 4 ? 10000.0f : 1.0f));
            joints.push_back(world.createJoint(hinge(world, previous, bodies.back(), {x - side * 0.25f, 9.0f})));
            previous = bodies.back();
        }
    }
    for (BodyId b : bodies)
        for (ShapeId s : world.shapes(b)) world.setFilter(s, Filter{.group = -1});
    const Motion m = run(world, bodies, joints, 180);
    EXPECT_LT(m.worstGap, 0.01f * 0.5f);
    EXPECT_LT(m.energyRise, 1e-3f * m.energyScale);
}

// Closed loops, solved directly like trees. A swing: a 5 m deck 1000 times a rope link's mass
// hangs from two posts by two ropes of 10 links, and is pushed sideways at 3 m/s.
TEST(RevoluteLoop, HeavySwingKeepsItsHingesClosed) {
    World world(WorldDef{.gravity = {0.0f, -g}});
    const BodyId deck = box(world, {0.0f, 5.0f}, 2.5f, 0.05f, 100.0f);  // 10 links' area, 100 times the density
    std::vector<BodyId> bodies{deck};
    std::vector<JointId> joints;
    for (const float x : {-2.5f, 2.5f}) {
        BodyId previous = staticBody(world, {x, 10.0f});
        for (int i = 0; i < 10; ++i) {
            bodies.push_back(box(world, {x, 10.0f - 0.5f * static_cast<float>(i) - 0.25f}, 0.05f, 0.25f));
            joints.push_back(world.createJoint(hinge(world, previous, bodies.back(), {x, 10.0f - 0.5f * static_cast<float>(i)})));
            previous = bodies.back();
        }
        joints.push_back(world.createJoint(hinge(world, previous, deck, {x, 5.0f})));
    }
    for (BodyId b : bodies)
        for (ShapeId s : world.shapes(b)) world.setFilter(s, Filter{.group = -1});
    world.setLinearVelocity(deck, {3.0f, 0.0f});
    const Motion m = run(world, bodies, joints, 180);
    EXPECT_LT(m.worstGap, 0.01f * 0.5f);
    EXPECT_LT(m.energyRise, 1e-3f * m.energyScale);
}

// A bridge of 20 planks pulled straight between two posts, its middle plank 1000 times the
// others' mass: a closed loop whose K is singular (a tension along it moves nothing).
TEST(RevoluteLoop, StraightBridgeCarriesAHeavyPlank) {
    World world(WorldDef{.gravity = {0.0f, -g}});
    BodyId previous = staticBody(world, {-5.0f, 10.0f});
    std::vector<BodyId> planks;
    std::vector<JointId> joints;
    for (int i = 0; i < 20; ++i) {
        const float x = -5.0f + 0.5f * static_cast<float>(i);
        planks.push_back(box(world, {x + 0.25f, 10.0f}, 0.25f, 0.05f, i == 10 ? 1000.0f : 1.0f));
        joints.push_back(world.createJoint(hinge(world, previous, planks.back(), {x, 10.0f})));
        previous = planks.back();
    }
    joints.push_back(world.createJoint(hinge(world, previous, staticBody(world, {5.0f, 10.0f}), {5.0f, 10.0f})));
    const Motion m = run(world, planks, joints, 180);
    EXPECT_LT(m.worstGap, 0.01f * 0.5f);
    EXPECT_LT(m.energyRise, 1e-3f * m.energyScale);
}

// `stress_bridge1000`: 20 planks of 0.05 kg on an arc 0.99 m deep between posts 9.74 m apart,
// hinged to each other and to the posts (joint i at hinge i, plank i from hinge i to hinge i + 1),
// its 50 kg load (the last body) hung by the last joint from the lowest hinge, hinge 10.
constexpr int middlePlank = 10;
Vec2 hingeOf(const Scene& bridge, int i) { return *bridge.joints[static_cast<size_t>(i)].anchor; }
std::vector<BodyId> planksOf(const SceneWorld& bridge) { return {bridge.bodies.begin() + 2, bridge.bodies.end() - 1}; }

// The load hung by a hinge from the middle plank, at its end (the lowest hinge), a quarter or half
// along it: the load joins the deck's tree, falls until the deck's halves are taut, and is caught,
// every hinge within 1 % of a link throughout 10 s.
TEST(RevoluteLoop, LoadHungAnywhereOnAPlankIsCaught) {
    for (const float along : {0.0f, 0.125f, 0.25f}) {
        Scene scene = findScene("stress_bridge1000");
        const Vec2 lowest = hingeOf(scene, middlePlank);
        const Vec2 at = lowest + along * normalize(hingeOf(scene, middlePlank + 1) - lowest);
        scene.bodies.back().position = at + Vec2{0.0f, -0.45f};
        scene.joints.back().bodyA = "plank" + std::to_string(middlePlank);
        scene.joints.back().anchor = at;
        SceneWorld bridge = buildWorld(scene);
        const Motion m = run(bridge.world, planksOf(bridge), bridge.joints, 600);
        EXPECT_LT(m.worstGap, 0.01f * 0.5f) << along;
        EXPECT_GT(bridge.world.position(bridge.bodies.back()).y, at.y - 1.0f) << along << ": the deck caught it";
    }
}

// Outside the direct solve (docs/stress.md, "What the direct solve does not take"): a load resting
// by contact on a loop. The load set on the two middle planks instead of hung: the contact is
// solved row by row against a plank's own mass, and the load goes through the deck, while the loop
// keeps its hinges closed.
TEST(RevoluteLoop, LoadRestingOnTheDeckByContactGoesThroughIt) {
    Scene scene = findScene("stress_bridge1000");
    scene.joints.pop_back();
    const Vec2 lowest = hingeOf(scene, middlePlank);
    const float tilt = scene.bodies[2 + middlePlank].angle;                  // the middle planks' slope, ±
    const float surface = lowest.y + 0.05f + 0.25f * std::tan(tilt);        // under the load's corners
    scene.bodies.back().position = {lowest.x, surface + 0.25f};
    SceneWorld bridge = buildWorld(scene);
    const Motion m = run(bridge.world, planksOf(bridge), bridge.joints, 600);
    const BodyId load = bridge.bodies.back();
    EXPECT_LT(m.worstGap, 0.01f * 0.5f);
    EXPECT_TRUE(std::isfinite(bridge.world.position(load).y));
    EXPECT_LT(bridge.world.position(load).y, lowest.y - 10.0f) << "the load is through the deck and falling";
}

// 20 (or `links`) links of 0.5 m pinned at one end, released horizontal, the last `ratio` times a
// link's mass; `limited`: every hinge within ±1 rad. Outside the direct solve (docs/stress.md,
// "What the direct solve does not take"), groups of more than 32 hinges run in the sequential
// passes: a heavy end then opens them — the tests pin how far, over 10 s — while the motion stays
// finite and takes no energy in.
struct Chain {
    std::vector<BodyId> links;
    std::vector<JointId> joints;
};
Chain heavyChain(World& world, int links, float ratio, bool limited) {
    const Vec2 pin{0.0f, 40.0f};
    BodyId previous = staticBody(world, pin);
    Chain c;
    for (int i = 0; i < links; ++i) {
        c.links.push_back(box(world, pin + Vec2{(static_cast<float>(i) + 0.5f) * 0.5f, 0.0f}, 0.25f, 0.05f, i == links - 1 ? ratio : 1.0f));
        RevoluteJointDef def = hinge(world, previous, c.links.back(), pin + Vec2{static_cast<float>(i) * 0.5f, 0.0f});
        if (limited) def.enableLimit = true, def.lowerAngle = -1.0f, def.upperAngle = 1.0f;
        c.joints.push_back(world.createJoint(def));
        previous = c.links.back();
    }
    return c;
}

// The worst gap over 10 s, after checking that every link ends finite and the energy never rose.
float sequentialGap(int links, float ratio, bool limited) {
    World world(WorldDef{.gravity = {0.0f, -g}});
    const Chain c = heavyChain(world, links, ratio, limited);
    const Motion m = run(world, c.links, c.joints, 600);
    for (BodyId b : c.links) EXPECT_TRUE(std::isfinite(world.position(b).x) && std::isfinite(world.position(b).y));
    EXPECT_LT(m.energyRise, 1e-3f * m.energyScale) << "the energy does not grow";
    return m.worstGap;
}

// The 20-link chain with every hinge limited to ±1 rad, its end 100, 1000 and 10,000 times a link's
// mass: the limits join the tree's system (one-sided rows), and the hinges stay closed within 1 %
// of a link over 10 s (the sequential passes opened them 0.13 / 4.2 / 36 m), each limit overshot by
// at most 0.06 rad. The energy rises at most 0.2 % of the end's fall: the limits are soft like
// every joint row (the joint stiffness), and give back what they stored under the 500 kg end, about
// 1 cm of its height (0.1 %; 0.0 % at 100 and 1000 : 1).
TEST(RevoluteTree, LimitedHeavyChainKeepsItsHingesClosed) {
    for (const float ratio : {100.0f, 1000.0f, 10000.0f}) {
        World world(WorldDef{.gravity = {0.0f, -g}});
        const Chain c = heavyChain(world, 20, ratio, true);
        const Motion m = run(world, c.links, c.joints, 600);
        EXPECT_LT(m.worstGap, 0.01f * 0.5f) << ratio;
        EXPECT_LT(m.worstAngle, 1.06f) << ratio;
        EXPECT_LT(m.energyRise, 2e-3f * m.energyScale) << ratio;
    }
}

// Limited hinges between like masses (a ragdoll's) stay with the sequential passes: the same chain
// with an end twice a link's mass opens 2.6 cm over 10 s.
TEST(RevoluteTree, LimitedChainOfLikeMassesIsLeftToTheSequentialPasses) {
    const float gap = sequentialGap(20, 2.0f, true);
    EXPECT_GT(gap, 0.01f);
    EXPECT_LT(gap, 0.05f);
}

TEST(RevoluteTree, ChainOfMoreThan32HingesIsLeftToTheSequentialPasses) {
    EXPECT_LT(sequentialGap(40, 100.0f, false), 0.1f);  // 6.7 cm
    const float at1000 = sequentialGap(40, 1000.0f, false);
    EXPECT_GT(at1000, 1.0f);  // 3.5 m
    EXPECT_LT(at1000, 10.0f);
}

}  // namespace
}  // namespace perpdot
