// The revolute rows of src/core/joint_solver_wide.hpp solve four joints in simd::Float4 lanes (a
// RevoluteBlock) with bit for bit the results of the scalar revolute joint (warmStartRevolute,
// solveRevolute) solving them one at a time: point rows alone, and motors and limits on or off
// lane by lane, mixed in one block, with a joint on a static body, warm-started impulses and an
// empty lane.
#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

#include "core/joint_solver_wide.hpp"
#include "lanes_helpers.hpp"

namespace perpdot {
namespace {

using lanes_test::Random;
using lanes_test::randomBody;
using lanes_test::sameBits;
using simd::Float4;

// A revolute joint prepared between solver slots a and b, with a motor and a limit if asked. The
// impulses are warm-started ones, also those of rows it lacks (left from when it had them: the
// warm start re-applies them). The limits are sometimes reached, sometimes speculative, and the
// motor's torque sometimes caps its impulse.
PreparedJoint randomJoint(Random& r, int a, int b, bool motor, bool limit) {
    PreparedJoint j;
    j.indexA = a;
    j.indexB = b;
    j.mass = {r(0.1f, 2.0f), r(0.1f, 4.0f), r(0.1f, 2.0f), r(0.1f, 4.0f)};
    j.anchorA = {r(-0.5f, 0.5f), r(-0.5f, 0.5f)};
    j.anchorB = {r(-0.5f, 0.5f), r(-0.5f, 0.5f)};
    j.deltaCenter = {r(-1.0f, 1.0f), r(-1.0f, 1.0f)};
    j.deltaAngle = r(-1.0f, 1.0f);
    RevoluteJoint& rev = j.data.as<RevoluteJoint>();
    rev.linearImpulse = {r(-2.0f, 2.0f), r(-2.0f, 2.0f)};
    rev.motorImpulse = r(-0.3f, 0.3f);
    rev.lowerImpulse = r(0.0f, 0.3f);
    rev.upperImpulse = r(0.0f, 0.3f);
    rev.enableMotor = motor;
    rev.motorSpeed = r(-5.0f, 5.0f);
    rev.maxMotorTorque = r(0.0f, 60.0f);  // |λ| ≤ 60·hs = 0.25 at most
    rev.enableLimit = limit;
    rev.lowerAngle = r(-0.8f, 0.0f);
    rev.upperAngle = r(0.0f, 0.8f);
    rev.axialMass = effectiveMass(j.mass, angularRow);
    return j;
}

StepContext substepContext() {
    StepContext ctx;
    ctx.hs = 1.0f / 240.0f;
    ctx.invHs = 240.0f;
    ctx.jointSoftness = makeSoftness(60.0f, 5.0f, ctx.hs);
    return ctx;
}

// Joints [0, count) (count < 4: the last lane empty) solved both ways from the same bodies, a warm
// start and a pass with bias, then a warm start and the relax pass: the bodies' velocities and
// the joints' impulses must agree bit for bit.
void expectLanesEqualScalar(std::array<PreparedJoint, 4> joints, int count, std::vector<BodyState> states,
                            const std::vector<float>& stepRotation, const StepContext& ctx, const std::string& what) {
    std::vector<BodyState> scalar = states;
    std::array<PreparedJoint, 4> scalarJoints = joints;
    for (const bool useBias : {true, false}) {
        for (int lane = 0; lane < count; ++lane) {
            PreparedJoint& j = scalarJoints[lane];
            JointPair p = pairOf(scalar, stepRotation, j);
            warmStartRevolute(j, p);
            solveRevolute(j, p, ctx, useBias);
        }
    }

    RevoluteBlock block = packRevoluteBlock({&joints[0], &joints[1], &joints[2], &joints[3]},
                                            {0, 1, 2, count == 4 ? 3 : -1});
    for (const bool useBias : {true, false}) {
        BodyLanes<Float4> a = gatherBodies(states, block.bodyA), b = gatherBodies(states, block.bodyB);
        JointPairT<Float4> p{a, b, block.mass};
        warmStartRevoluteRows(block.rows, p);
        solveRevoluteBlock(block, p, stepRotation, ctx, useBias);
        scatterVelocities(states, block.bodyA, a);
        scatterVelocities(states, block.bodyB, b);
    }

    for (size_t i = 0; i < states.size(); ++i) {
        EXPECT_TRUE(sameBits(states[i].v.x, scalar[i].v.x)) << what << " body " << i;
        EXPECT_TRUE(sameBits(states[i].v.y, scalar[i].v.y)) << what << " body " << i;
        EXPECT_TRUE(sameBits(states[i].w, scalar[i].w)) << what << " body " << i;
    }
    // The impulses go back to the joints (an empty lane's to none), and the axial mass to those
    // with a motor or a limit, as their whole data went back when they were solved one by one
    // (-1: a value the rows did not write).
    std::vector<Joint> stored(4);
    for (int lane = 0; lane < 4; ++lane) {
        stored[lane].data = joints[lane].data;
        stored[lane].data.as<RevoluteJoint>().axialMass = -1.0f;
    }
    unpackRevoluteImpulses(block, stored);
    for (int lane = 0; lane < 4; ++lane) {
        const RevoluteJoint& got = stored[lane].data.as<RevoluteJoint>();
        const RevoluteJoint& expected = (lane < count ? scalarJoints[lane] : joints[lane]).data.as<RevoluteJoint>();
        EXPECT_TRUE(sameBits(got.linearImpulse.x, expected.linearImpulse.x)) << what << " lane " << lane;
        EXPECT_TRUE(sameBits(got.linearImpulse.y, expected.linearImpulse.y)) << what << " lane " << lane;
        EXPECT_TRUE(sameBits(got.motorImpulse, expected.motorImpulse)) << what << " lane " << lane;
        EXPECT_TRUE(sameBits(got.lowerImpulse, expected.lowerImpulse)) << what << " lane " << lane;
        EXPECT_TRUE(sameBits(got.upperImpulse, expected.upperImpulse)) << what << " lane " << lane;
        const bool angleRows = lane < count && (expected.enableMotor || expected.enableLimit);
        EXPECT_TRUE(sameBits(got.axialMass, angleRows ? expected.axialMass : -1.0f)) << what << " lane " << lane;
    }
}

// Bodies 1..8 moving, each turned since the step began; slot 0 static.
std::vector<BodyState> randomBodies(Random& r, std::vector<float>& stepRotation) {
    std::vector<BodyState> states(9);
    stepRotation.assign(9, 0.0f);
    for (int i = 1; i < 9; ++i) {
        states[i] = randomBody(r);
        stepRotation[i] = r(-0.2f, 0.2f);
    }
    return states;
}

TEST(JointSolverWide, FourLanesEqualFourScalarSolves) {
    const StepContext ctx = substepContext();
    Random r{123456789u};
    for (int round = 0; round < 50; ++round) {
        // Point rows alone: two joints between moving bodies, one whose body A is static (slot 0,
        // no mass), and an empty lane (round % 2 == 0: joint -1, slots 0, no mass) or a fourth joint.
        const int count = round % 2 == 0 ? 3 : 4;
        std::vector<float> stepRotation;
        const std::vector<BodyState> states = randomBodies(r, stepRotation);
        std::array<PreparedJoint, 4> joints;
        for (int lane = 0; lane < count; ++lane) joints[lane] = randomJoint(r, 2 * lane + 1, 2 * lane + 2, false, false);
        joints[2].indexA = 0;
        joints[2].mass.mA = joints[2].mass.iA = 0.0f;
        expectLanesEqualScalar(joints, count, states, stepRotation, ctx, "round " + std::to_string(round));
    }
}

TEST(JointSolverWide, MotorAndLimitLanesEqualScalarSolves) {
    const StepContext ctx = substepContext();
    Random r{987654321u};
    // Every combination of motor and limit over the four lanes (bits 2·lane and 2·lane + 1 of the
    // round): none, all, and mixed in one block; twice, the second time with the last lane empty.
    for (int round = 0; round < 512; ++round) {
        const int flags = round % 256;
        const int count = round < 256 ? 4 : 3;
        std::vector<float> stepRotation;
        const std::vector<BodyState> states = randomBodies(r, stepRotation);
        std::array<PreparedJoint, 4> joints;
        for (int lane = 0; lane < count; ++lane) {
            const bool motor = (flags >> (2 * lane)) & 1, limit = (flags >> (2 * lane + 1)) & 1;
            joints[lane] = randomJoint(r, 2 * lane + 1, 2 * lane + 2, motor, limit);
        }
        joints[2].indexA = 0;
        joints[2].mass.mA = joints[2].mass.iA = 0.0f;
        joints[2].data.as<RevoluteJoint>().axialMass = effectiveMass(joints[2].mass, angularRow);
        expectLanesEqualScalar(joints, count, states, stepRotation, ctx,
                               "flags " + std::to_string(flags) + " joints " + std::to_string(count));
    }
}

// A lane without the row keeps its velocities and λ bit for bit, even −0, which a zero impulse
// would turn into +0 (−0 + +0 = +0).
TEST(JointSolverWide, LanesWithoutARowKeepTheirBits) {
    BodyLanes<Float4> a, b;
    a.v = b.v = {Float4(-0.0f), Float4(-0.0f)};
    a.w = b.w = Float4(-0.0f);
    JointPairT<Float4> p{a, b, {Float4(1.0f), Float4(1.0f), Float4(1.0f), Float4(1.0f)}};
    Float4 lambda(-0.0f);
    const float on[4] = {1.0f, 0.0f, 1.0f, 0.0f};
    solveWhere(Float4::load(on) != Float4(0.0f), p,
               [&] { solveMotorRow(p, angularRowOf<Float4>(), Float4(0.5f), Float4(0.0f), Float4(1.0f), lambda); }, lambda);
    float values[7][4];
    a.v.x.store(values[0]);
    a.v.y.store(values[1]);
    a.w.store(values[2]);
    b.v.x.store(values[3]);
    b.v.y.store(values[4]);
    b.w.store(values[5]);
    lambda.store(values[6]);
    for (const auto& value : values)
        for (int lane : {1, 3}) EXPECT_TRUE(sameBits(value[lane], -0.0f)) << "lane " << lane;
}

}  // namespace
}  // namespace perpdot
