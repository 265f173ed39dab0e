// Joint trees of revolute, weld and prismatic joints (src/core/joints/joint_tree.hpp): a chain
// whose joints are all three, with limits and motors, and an end 1000 and 10,000 times a link's
// mass keeps every joint within 1 % of a link — the hinges closed, the welds unbent, the sliders on
// their axes and within their limits — through 10 s of its swing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "joint_helpers.hpp"

namespace perpdot {
namespace {

using namespace joint_test;

constexpr float g = 10.0f, link = 0.5f;

// A 20-link chain pinned at its left end, released horizontal, the last link `ratio` times a
// link's mass. Joint i is, by i mod 4: a hinge; a hinge limited to ±1 rad with a 1 N·m motor toward
// 0.5 rad/s; a weld; a slider along the link, limited to ±5 cm.
struct MixedChain {
    std::vector<BodyId> links;
    std::vector<JointId> joints;
};
MixedChain mixedChain(World& world, float ratio) {
    const Vec2 pin{0.0f, 40.0f};
    BodyId previous = staticBody(world, pin);
    MixedChain c;
    for (int i = 0; i < 20; ++i) {
        const Vec2 at = pin + Vec2{static_cast<float>(i) * link, 0.0f};
        const BodyId body = box(world, at + Vec2{0.5f * link, 0.0f}, 0.5f * link, 0.05f, i == 19 ? ratio : 1.0f);
        const RevoluteJointDef h = hinge(world, previous, body, at);
        switch (i % 4) {
            case 0: c.joints.push_back(world.createJoint(h)); break;
            case 1: {
                RevoluteJointDef def = h;
                def.enableLimit = true, def.lowerAngle = -1.0f, def.upperAngle = 1.0f;
                def.enableMotor = true, def.motorSpeed = 0.5f, def.maxMotorTorque = 1.0f;
                c.joints.push_back(world.createJoint(def));
                break;
            }
            case 2:
                c.joints.push_back(world.createJoint(WeldJointDef{.bodyA = previous, .bodyB = body, .localAnchorA = h.localAnchorA,
                                                                  .localAnchorB = h.localAnchorB}));
                break;
            default:
                c.joints.push_back(world.createJoint(PrismaticJointDef{.bodyA = previous, .bodyB = body, .localAnchorA = h.localAnchorA,
                                                                       .localAnchorB = h.localAnchorB, .localAxisA = {1.0f, 0.0f},
                                                                       .enableLimit = true, .lower = -0.05f, .upper = 0.05f}));
        }
        c.links.push_back(body);
        previous = body;
    }
    return c;
}

// How far a joint is from what it holds, m or rad: a hinge's anchor gap; a weld's gap and bend; a
// slider's offset from its axis, its turn, and how far it is past a limit.
struct Worst {
    float gap = 0.0f, angle = 0.0f, overshoot = 0.0f;
};
void measure(const World& world, JointId j, Worst& w) {
    const Vec2 d = world.jointAnchorB(j) - world.jointAnchorA(j);
    switch (world.jointType(j)) {
        case JointType::Revolute: w.gap = std::max(w.gap, length(d)); break;
        case JointType::Weld:
            w.gap = std::max(w.gap, length(d));
            w.angle = std::max(w.angle, std::fabs(world.jointAngle(j)));
            break;
        default: {
            const float t = world.jointTranslation(j);
            w.gap = std::max(w.gap, std::sqrt(std::max(0.0f, dot(d, d) - t * t)));
            w.angle = std::max(w.angle, std::fabs(world.jointAngle(j)));
            w.overshoot = std::max(w.overshoot, std::fabs(t) - 0.05f);
        }
    }
}

// The worst of every joint over 10 s, and the most the energy rose above its start, as a share of
// the end's fall through the chain's length.
struct Motion {
    Worst worst;
    float energyRise = 0.0f;
};
Motion swing(float ratio) {
    World world(WorldDef{.gravity = {0.0f, -g}});
    const MixedChain c = mixedChain(world, ratio);
    const auto energyOf = [&] {
        float e = 0.0f;
        for (BodyId b : c.links) e += energy(world, b);
        return e;
    };
    const float e0 = energyOf(), scale = world.mass(c.links.back()) * g * 10.0f;
    Motion m;
    for (int step = 0; step < 600; ++step) {
        world.step(1.0f / 60.0f);
        for (JointId j : c.joints) measure(world, j, m.worst);
        m.energyRise = std::max(m.energyRise, (energyOf() - e0) / scale);
    }
    return m;
}

class MixedHeavyChain : public ::testing::TestWithParam<float> {};

// As a tree: 0.08 / 0.07 / 2.6 mm at 100 / 1000 / 10,000 : 1. Solved by the sequential passes
// (before trees took welds and sliders), the chain opened 7.1 cm / 322 m / 346 m.
TEST_P(MixedHeavyChain, KeepsEveryJointOnItsAxisWithinOnePercentOfALink) {
    const Motion m = swing(GetParam());
    EXPECT_LT(m.worst.gap, 0.01f * link);
    EXPECT_LT(m.worst.angle, 0.01f) << "the welds unbent, the sliders unturned";
}

INSTANTIATE_TEST_SUITE_P(JointTree, MixedHeavyChain, ::testing::Values(100.0f, 1000.0f, 10000.0f));

// Up to 1000 : 1 the sliders' limits hold within 1 % of a link too (3.0 / 3.8 mm past them at
// 100 / 1000 : 1), and the swing takes no energy in.
TEST(JointTree, MixedHeavyChainKeepsItsSlidersWithinTheirLimits) {
    for (const float ratio : {100.0f, 1000.0f}) {
        const Motion m = swing(ratio);
        EXPECT_LT(m.worst.overshoot, 0.01f * link) << ratio;
        EXPECT_LT(m.energyRise, 2e-3f) << ratio;
    }
}

// At 10,000 : 1 a slider's limit carries the 500 kg end's pull as the soft row every limit is
// (the joint stiffness): it stretches 5.8 cm past it, and gives back what it stored, 5.5 % of the
// end's fall. The position step leaves the limits out (joint_tree.cpp); docs/stress.md says so.
TEST(JointTree, SliderLimitUnderATenThousandFoldPullStretches) {
    const Motion m = swing(10000.0f);
    EXPECT_GT(m.worst.overshoot, 0.02f);
    EXPECT_LT(m.worst.overshoot, 0.1f);
    EXPECT_LT(m.energyRise, 0.1f);
}

}  // namespace
}  // namespace perpdot
