// A 40-link chain of revolute joints holding a weight of a hundred links (2.5 times the chain).
// Rigid rows are soft in the biased pass, so under a load F a row settles F/(m_eff ω²) long, ω =
// 2π·jointHertz (the fixed point of Δλ = −m_eff·massScale·(Ċ + biasRate·C) − impulseScale·λ):
// the chain's stretch is (g/ω²) Σ load_k/m_eff,k, ~1/substeps² with the joint stiffness at its
// cap of a quarter of the substep rate. At 4 substeps (60 Hz) it is 2.2 % settled, 6.5 % in the
// first jerk; at 16 substeps (240 Hz) 16 times less (docs/joints.md).
#include <gtest/gtest.h>

#include <string>

#include "joint_helpers.hpp"

namespace perpdot {
namespace {

using namespace joint_test;

TEST(JointChain, FortyLinksUnderHeavyWeightStretchLessThanOnePercent) {
    WorldDef def;
    def.substeps = 16;
    def.jointHertz = 240.0f;
    World world(def);
    const float top = 30.0f, half = 0.25f;  // links 0.5 m long
    const int links = 40;
    const BodyId anchor = staticBody(world, {0.0f, top});
    BodyId previous = anchor;
    float linkMass = 0.0f;
    for (int i = 0; i < links; ++i) {
        const BodyId link = box(world, {0.0f, top - (2.0f * i + 1.0f) * half}, 0.0625f, half);
        linkMass = world.mass(link);
        world.createJoint(hinge(world, previous, link, {0.0f, top - 2.0f * i * half}));
        previous = link;
    }
    const float length = 2.0f * half * links;
    const float r = 0.5f;
    const BodyId weight = disc(world, {0.0f, top - length - r}, r, 1.0f);
    world.setDensity(world.shapes(weight)[0], 100.0f * linkMass / (pi * r * r));
    world.createJoint(hinge(world, previous, weight, {0.0f, top - length}));
    ASSERT_NEAR(world.mass(weight), 100.0f * linkMass, 1e-3f * world.mass(weight));

    // Released hanging straight, with a sideways kick: the worst stretch includes the first jerk.
    world.setLinearVelocity(weight, {2.0f, 0.0f});
    float worst = 0.0f;
    for (int step = 0; step < 300; ++step) {
        world.step(1.0f / 60.0f);
        const Vec2 hook = transformPoint(world.transform(weight), {0.0f, r});
        worst = std::max(worst, distance(hook, {0.0f, top}) / length - 1.0f);
    }
    EXPECT_LT(worst, 0.01f) << "stretch " << 100.0f * worst << " %";
}

}  // namespace
}  // namespace perpdot
