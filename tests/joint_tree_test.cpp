// Joint trees solved directly (src/core/joints/joint_tree.hpp): which joints form a tree, and what the
// direct solve and the position projection keep — closed hinges under a heavy load at the default
// 4 substeps, the momentum and centre of mass of a free chain, a branched tree at rest.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "core/joints/joint_rows.hpp"
#include "core/joints/joint_tree.hpp"
#include "joint_helpers.hpp"

namespace perpdot {
namespace {

using namespace joint_test;

// A revolute joint (or another `type`) between solver slots a and b (slot 0: cannot move), with a
// limit or not; its body b's inverse mass where given (every other body that moves: 1).
struct Hinge {
    int a, b;
    bool limit = false;
    float invMassB = 1.0f;
    JointType type = JointType::Revolute;
};
Hinge hingeBetween(int a, int b, bool limit = false) { return {a, b, limit}; }

std::vector<std::vector<int>> treesOf(const std::vector<Hinge>& hinges, int slots) {
    std::vector<JointKey> keys;
    std::vector<BodyState> states(static_cast<size_t>(slots));
    for (int slot = 1; slot < slots; ++slot) states[slot].invMass = 1.0f;
    for (const Hinge& h : hinges) {
        keys.push_back({h.a, h.b, h.type, h.a != 0, h.b != 0, true, h.limit, h.limit});
        if (h.b != 0) states[h.b].invMass = h.invMassB;
    }
    JointTrees t;
    findJointTrees(t, keys, states);
    std::vector<std::vector<int>> out;
    for (size_t k = 0; k + 1 < t.start.size(); ++k) out.emplace_back(t.joints.begin() + t.start[k], t.joints.begin() + t.start[k + 1]);
    return out;
}

TEST(RevoluteTree, LinkedHingesAreTreesLoopsIncludedWithLimitsWhereMassesDiffer) {
    using Trees = std::vector<std::vector<int>>;
    // A pinned chain 0-1-2-3, and apart from it a free pair of joints 4-5-6.
    EXPECT_EQ(treesOf({hingeBetween(0, 1), hingeBetween(1, 2), hingeBetween(2, 3), hingeBetween(4, 5), hingeBetween(5, 6)}, 7),
              (Trees{{0, 1, 2}, {3, 4}}));
    // A branch: 1 holds 2 and 3.
    EXPECT_EQ(treesOf({hingeBetween(0, 1), hingeBetween(1, 2), hingeBetween(1, 3)}, 4), (Trees{{0, 1, 2}}));
    EXPECT_EQ(treesOf({hingeBetween(0, 1)}, 2), Trees{}) << "one joint: its own 2x2 solve is already exact";
    EXPECT_EQ(treesOf({hingeBetween(1, 2), hingeBetween(2, 3), hingeBetween(3, 1)}, 4), (Trees{{0, 1, 2}})) << "a cycle (K raised)";
    EXPECT_EQ(treesOf({hingeBetween(0, 1), hingeBetween(1, 2), hingeBetween(2, 0)}, 3), (Trees{{0, 1, 2}})) << "two anchors: a bridge";
    EXPECT_EQ(treesOf({hingeBetween(0, 1), hingeBetween(1, 2, true)}, 3), Trees{}) << "limits between like masses stay sequential";
    // The same chain ending in a body 10 times heavier (1/m = 0.1): its limit rows join the tree's system.
    EXPECT_EQ(treesOf({hingeBetween(0, 1), Hinge{1, 2, true, 0.1f}}, 3), (Trees{{0, 1}}));
    EXPECT_EQ(treesOf({hingeBetween(0, 1), Hinge{1, 2, true, 0.2f}}, 3), Trees{}) << "5 times heavier: sequential";
    // Welds and sliders are taken as limited hinges are: where the masses they join differ 10 times.
    const Hinge weld{1, 2, false, 1.0f, JointType::Weld}, slider{2, 3, false, 1.0f, JointType::Prismatic};
    EXPECT_EQ(treesOf({hingeBetween(0, 1), weld, slider}, 4), Trees{}) << "welded and sliding parts of like masses";
    EXPECT_EQ(treesOf({hingeBetween(0, 1), weld, Hinge{2, 3, false, 0.1f, JointType::Prismatic}}, 4), (Trees{{0, 1, 2}}));
}

// 20 links of 0.5 m, the last 100 times a link's mass, released horizontal (stress_chain): at the
// default 4 substeps every hinge stays closed within 1 % of a link (12 % before trees).
TEST(RevoluteTree, HeavyEndedChainKeepsItsHingesWithinOnePercentOfALink) {
    World world;
    const Vec2 pin{0.0f, 20.0f};
    BodyId previous = staticBody(world, pin);
    std::vector<JointId> joints;
    for (int i = 0; i < 20; ++i) {
        const BodyId link = box(world, pin + Vec2{(static_cast<float>(i) + 0.5f) * 0.5f, 0.0f}, 0.25f, 0.05f, i == 19 ? 100.0f : 1.0f);
        joints.push_back(world.createJoint(hinge(world, previous, link, pin + Vec2{static_cast<float>(i) * 0.5f, 0.0f})));
        previous = link;
    }
    float worst = 0.0f;
    for (int step = 0; step < 600; ++step) {
        world.step(1.0f / 60.0f);
        for (JointId j : joints) worst = std::max(worst, distance(world.jointAnchorA(j), world.jointAnchorB(j)));
    }
    EXPECT_LT(worst, 0.005f);
}

// Zero gravity, six links spinning and drifting with no anchor: the projection moves bodies by
// equal and opposite position impulses, so the centre of mass keeps its straight line; the
// velocity solve keeps linear momentum; the hinges stay closed.
TEST(RevoluteTree, FreeChainKeepsItsMomentumAndCentreOfMassLine) {
    World world(WorldDef{.gravity = {0.0f, 0.0f}});
    std::vector<BodyId> links;
    std::vector<JointId> joints;
    std::mt19937 random(7);
    std::uniform_real_distribution<float> spin(-6.0f, 6.0f);
    for (int i = 0; i < 6; ++i) {
        links.push_back(box(world, {0.5f * static_cast<float>(i), 0.0f}, 0.25f, 0.05f, 1.0f + static_cast<float>(i)));
        world.setAngularVelocity(links.back(), spin(random));
        world.setLinearVelocity(links.back(), {1.0f, 0.5f});
        if (i > 0) joints.push_back(world.createJoint(hinge(world, links[i - 1], links[i], {0.5f * static_cast<float>(i) - 0.25f, 0.0f})));
    }
    const auto momentum = [&] {
        Vec2 p{};
        for (BodyId b : links) p += world.mass(b) * world.linearVelocity(b);
        return p;
    };
    const auto centre = [&] {
        Vec2 c{};
        float m = 0.0f;
        for (BodyId b : links) c += world.mass(b) * world.worldCenter(b), m += world.mass(b);
        return c * (1.0f / m);
    };
    world.step(1.0f / 60.0f);  // the first step joins the bodies' velocities to the joints
    const Vec2 p0 = momentum(), c0 = centre();
    float worst = 0.0f;
    for (int step = 1; step <= 300; ++step) {
        world.step(1.0f / 60.0f);
        for (JointId j : joints) worst = std::max(worst, distance(world.jointAnchorA(j), world.jointAnchorB(j)));
    }
    EXPECT_LT(length(momentum() - p0), 1e-3f * length(p0));
    const float mass = length(p0) / length(Vec2{1.0f, 0.5f});
    EXPECT_LT(length(centre() - (c0 + (300.0f / 60.0f) * (1.0f / mass) * p0)), 5e-3f);
    EXPECT_LT(worst, 1e-3f);
}

// A hub on a pin with three arms: a branched tree comes to rest hanging, its hinges closed.
TEST(RevoluteTree, BranchedTreeHangsWithItsHingesClosed) {
    World world;
    const BodyId pin = staticBody(world, {0.0f, 10.0f});
    const BodyId hub = box(world, {0.0f, 9.5f}, 0.1f, 0.5f);
    std::vector<JointId> joints{world.createJoint(hinge(world, pin, hub, {0.0f, 10.0f}))};
    for (const float x : {-1.0f, 1.0f}) {
        const BodyId arm = box(world, {0.5f * x, 9.0f}, 0.5f, 0.05f, 10.0f);
        joints.push_back(world.createJoint(hinge(world, hub, arm, {0.0f, 9.0f})));
        const BodyId hand = disc(world, {1.0f * x, 9.0f}, 0.2f, 50.0f);
        joints.push_back(world.createJoint(hinge(world, arm, hand, {1.0f * x, 9.0f})));
    }
    float worst = 0.0f;
    for (int step = 0; step < 600; ++step) {
        world.step(1.0f / 60.0f);
        for (JointId j : joints) worst = std::max(worst, distance(world.jointAnchorA(j), world.jointAnchorB(j)));
    }
    EXPECT_LT(worst, 1e-3f);
    EXPECT_NEAR(world.worldCenter(hub).x, 0.0f, 0.05f) << "symmetric: it hangs straight";
}

}  // namespace
}  // namespace perpdot
