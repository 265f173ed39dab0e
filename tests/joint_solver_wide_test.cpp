// The revolute point rows of src/core/joint_solver_wide.hpp solve four joints in simd::Float4
// lanes with bit for bit the results of solving them one at a time with F = float (the scalar
// revolute joint's path), including a joint on a static body, a warm-started angular impulse and
// an empty lane.
#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cstdint>
#include <vector>

#include "core/joint_solver_wide.hpp"

namespace perpdot {
namespace {

struct Random {
    uint32_t x = 123456789u;
    float operator()(float lo, float hi) {
        x = x * 1664525u + 1013904223u;
        return lo + (hi - lo) * static_cast<float>(x >> 8) / 16777216.0f;
    }
};

RevoluteRows<float> randomRows(Random& r) {
    return {{r(-0.5f, 0.5f), r(-0.5f, 0.5f)},
            {r(-0.5f, 0.5f), r(-0.5f, 0.5f)},
            {r(-1.0f, 1.0f), r(-1.0f, 1.0f)},
            {r(-2.0f, 2.0f), r(-2.0f, 2.0f)},
            r(-0.3f, 0.3f)};
}

JointMass randomMass(Random& r) { return {r(0.1f, 2.0f), r(0.1f, 4.0f), r(0.1f, 2.0f), r(0.1f, 4.0f)}; }

BodyState randomBody(Random& r) {
    const float angle = r(-0.1f, 0.1f);
    return {{r(-2.0f, 2.0f), r(-2.0f, 2.0f)}, r(-3.0f, 3.0f), {r(-0.1f, 0.1f), r(-0.1f, 0.1f)}, Rot::fromAngle(angle)};
}

bool sameBits(float a, float b) { return std::bit_cast<uint32_t>(a) == std::bit_cast<uint32_t>(b); }

TEST(JointSolverWide, FourLanesEqualFourScalarSolves) {
    StepContext ctx;
    ctx.jointSoftness = makeSoftness(60.0f, 5.0f, 1.0f / 240.0f);
    Random r;
    for (int round = 0; round < 50; ++round) {
        // Lanes: two joints between moving bodies, one whose body A is static (slot 0, no mass),
        // and an empty lane (round % 2) or a fourth joint.
        const bool emptyLast = round % 2 == 0;
        std::vector<BodyState> states(9);
        for (int i = 1; i < 9; ++i) states[i] = randomBody(r);
        std::array<RevoluteRows<float>, 4> rows = {randomRows(r), randomRows(r), randomRows(r),
                                                  emptyLast ? RevoluteRows<float>{} : randomRows(r)};
        std::array<JointMass, 4> mass = {randomMass(r), randomMass(r), randomMass(r),
                                         emptyLast ? JointMass{} : randomMass(r)};
        mass[2].mA = mass[2].iA = 0.0f;
        const int bodyA[4] = {1, 3, 0, emptyLast ? 0 : 7};
        const int bodyB[4] = {2, 4, 5, emptyLast ? 0 : 8};

        std::vector<BodyState> scalar = states;
        std::array<RevoluteRows<float>, 4> scalarRows = rows;
        for (const bool useBias : {true, false}) {
            for (int lane = 0; lane < (emptyLast ? 3 : 4); ++lane) {
                JointPair p{scalar[bodyA[lane]], scalar[bodyB[lane]], mass[lane]};
                warmStartRevoluteRows(scalarRows[lane], p);
                solveRevolutePoint(scalarRows[lane], p, rigidSoftness(ctx, useBias));
            }
        }

        RevoluteRows<simd::Float4> wide = packRevoluteRows(rows);
        const JointMassT<simd::Float4> wideMass = packJointMasses(mass);
        for (const bool useBias : {true, false}) {
            BodyLanes<simd::Float4> a = gatherBodies(states, bodyA), b = gatherBodies(states, bodyB);
            JointPairT<simd::Float4> p{a, b, wideMass};
            warmStartRevoluteRows(wide, p);
            solveRevolutePoint(wide, p, rigidSoftness(ctx, useBias));
            scatterVelocities(states, bodyA, a);
            scatterVelocities(states, bodyB, b);
        }

        for (int i = 0; i < 9; ++i) {
            EXPECT_TRUE(sameBits(states[i].v.x, scalar[i].v.x)) << "round " << round << " body " << i;
            EXPECT_TRUE(sameBits(states[i].v.y, scalar[i].v.y)) << "round " << round << " body " << i;
            EXPECT_TRUE(sameBits(states[i].w, scalar[i].w)) << "round " << round << " body " << i;
        }
        float x[4], y[4];
        wide.linearImpulse.x.store(x);
        wide.linearImpulse.y.store(y);
        for (int lane = 0; lane < (emptyLast ? 3 : 4); ++lane) {
            EXPECT_TRUE(sameBits(x[lane], scalarRows[lane].linearImpulse.x)) << "round " << round << " lane " << lane;
            EXPECT_TRUE(sameBits(y[lane], scalarRows[lane].linearImpulse.y)) << "round " << round << " lane " << lane;
        }
    }
}

}  // namespace
}  // namespace perpdot
