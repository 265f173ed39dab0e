// The revolute point rows of src/core/joint_solver_wide.hpp solve four joints in simd::Float4
// lanes (a RevoluteBlock) with bit for bit the results of the scalar revolute joint
// (warmStartRevolute, solveRevolute) solving them one at a time, including a joint on a static
// body, a warm-started angular impulse and an empty lane.
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "core/joint_solver_wide.hpp"
#include "lanes_helpers.hpp"

namespace perpdot {
namespace {

using lanes_test::Random;
using lanes_test::randomBody;
using lanes_test::sameBits;

// A revolute joint without motor or limit, prepared between solver slots a and b.
PreparedJoint randomJoint(Random& r, int a, int b) {
    PreparedJoint j;
    j.indexA = a;
    j.indexB = b;
    j.mass = {r(0.1f, 2.0f), r(0.1f, 4.0f), r(0.1f, 2.0f), r(0.1f, 4.0f)};
    j.anchorA = {r(-0.5f, 0.5f), r(-0.5f, 0.5f)};
    j.anchorB = {r(-0.5f, 0.5f), r(-0.5f, 0.5f)};
    j.deltaCenter = {r(-1.0f, 1.0f), r(-1.0f, 1.0f)};
    j.data.as<RevoluteJoint>().linearImpulse = {r(-2.0f, 2.0f), r(-2.0f, 2.0f)};
    j.data.as<RevoluteJoint>().motorImpulse = r(-0.3f, 0.3f);  // left from a motor: the warm start re-applies it
    return j;
}

TEST(JointSolverWide, FourLanesEqualFourScalarSolves) {
    StepContext ctx;
    ctx.jointSoftness = makeSoftness(60.0f, 5.0f, 1.0f / 240.0f);
    Random r{123456789u};
    for (int round = 0; round < 50; ++round) {
        // Lanes: two joints between moving bodies, one whose body A is static (slot 0, no mass),
        // and an empty lane (round % 2 == 0: joint -1, slots 0, no mass) or a fourth joint.
        const bool emptyLast = round % 2 == 0;
        std::vector<BodyState> states(9);
        for (int i = 1; i < 9; ++i) states[i] = randomBody(r);
        const int count = emptyLast ? 3 : 4;
        std::array<PreparedJoint, 4> joints;
        for (int lane = 0; lane < count; ++lane) joints[lane] = randomJoint(r, 2 * lane + 1, 2 * lane + 2);
        joints[2].indexA = 0;  // static: no mass
        joints[2].mass.mA = joints[2].mass.iA = 0.0f;

        std::vector<BodyState> scalar = states;
        std::array<PreparedJoint, 4> scalarJoints = joints;
        for (const bool useBias : {true, false}) {
            for (int lane = 0; lane < count; ++lane) {
                PreparedJoint& j = scalarJoints[lane];
                JointPair p{scalar[j.indexA], scalar[j.indexB], j.mass};
                warmStartRevolute(j, p);
                solveRevolute(j, p, ctx, useBias);
            }
        }

        RevoluteBlock block = packRevoluteBlock({&joints[0], &joints[1], &joints[2], &joints[3]},
                                                {0, 1, 2, emptyLast ? -1 : 3});
        for (const bool useBias : {true, false}) {
            BodyLanes<simd::Float4> a = gatherBodies(states, block.bodyA), b = gatherBodies(states, block.bodyB);
            JointPairT<simd::Float4> p{a, b, block.mass};
            warmStartRevoluteRows(block.rows, p);
            solveRevolutePoint(block.rows, p, rigidSoftness(ctx, useBias));
            scatterVelocities(states, block.bodyA, a);
            scatterVelocities(states, block.bodyB, b);
        }

        for (int i = 0; i < 9; ++i) {
            EXPECT_TRUE(sameBits(states[i].v.x, scalar[i].v.x)) << "round " << round << " body " << i;
            EXPECT_TRUE(sameBits(states[i].v.y, scalar[i].v.y)) << "round " << round << " body " << i;
            EXPECT_TRUE(sameBits(states[i].w, scalar[i].w)) << "round " << round << " body " << i;
        }
        // The impulses go back to the joints (an empty lane to none).
        std::vector<Joint> stored(4);
        unpackRevoluteImpulses(block, stored);
        for (int lane = 0; lane < 4; ++lane) {
            const Vec2 impulse = stored[lane].data.as<RevoluteJoint>().linearImpulse;
            const Vec2 expected = lane < count ? scalarJoints[lane].data.as<RevoluteJoint>().linearImpulse : Vec2{};
            EXPECT_TRUE(sameBits(impulse.x, expected.x)) << "round " << round << " lane " << lane;
            EXPECT_TRUE(sameBits(impulse.y, expected.y)) << "round " << round << " lane " << lane;
        }
    }
}

}  // namespace
}  // namespace perpdot
