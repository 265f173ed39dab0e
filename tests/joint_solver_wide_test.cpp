// The joint rows of src/core/joints/joint_solver_wide.hpp solve four joints of a type in simd::Float4
// lanes (a JointBlock) with bit for bit the results of the type's scalar stages solving them one
// at a time: revolute point rows alone; revolute and prismatic motors and limits, weld springs,
// wheel motors and springs, distance springs with their min and max rows on or off lane by lane,
// mixed in one block; motor joints' capped impulses; with a joint on a static body, warm-started
// impulses and an empty lane.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "core/joints/joint_distance.hpp"
#include "core/joints/joint_motor.hpp"
#include "core/joints/joint_prismatic.hpp"
#include "core/joints/joint_revolute.hpp"
#include "core/joints/joint_solver_wide.hpp"
#include "core/joints/joint_weld.hpp"
#include "core/joints/joint_wheel.hpp"
#include "lanes_helpers.hpp"

namespace perpdot {
namespace {

using lanes_test::Random;
using lanes_test::randomBody;
using lanes_test::sameBits;
using simd::Float4;

// A joint of `type` prepared between solver slots a and b (a = 0: body A static, no mass), its
// frame at step start random.
PreparedJoint randomFrame(Random& r, JointType type, int a, int b) {
    PreparedJoint j;
    j.type = type;
    j.indexA = a;
    j.indexB = b;
    j.mass = {r(0.1f, 2.0f), r(0.1f, 4.0f), r(0.1f, 2.0f), r(0.1f, 4.0f)};
    if (a == 0) j.mass.mA = j.mass.iA = 0.0f;
    j.anchorA = {r(-0.5f, 0.5f), r(-0.5f, 0.5f)};
    j.anchorB = {r(-0.5f, 0.5f), r(-0.5f, 0.5f)};
    j.deltaCenter = {r(-1.0f, 1.0f), r(-1.0f, 1.0f)};
    j.deltaAngle = r(-1.0f, 1.0f);
    return j;
}

Vec2 randomAxis(Random& r) { return normalize(Vec2{r(-1.0f, 1.0f), r(0.1f, 1.0f)}); }

// The joints below have warm-started impulses, also those of rows they lack (left from when they
// had them: the warm start re-applies them). Limits are sometimes reached, sometimes speculative,
// and a motor's torque or force sometimes caps its impulse (60·hs = 0.25 at most).

// A revolute joint, with a motor (flags bit 0) and a limit (bit 1) if asked.
PreparedJoint randomRevolute(Random& r, int a, int b, int flags, const StepContext&) {
    PreparedJoint j = randomFrame(r, JointType::Revolute, a, b);
    RevoluteJoint& rev = j.data.emplace<RevoluteJoint>();
    rev.linearImpulse = {r(-2.0f, 2.0f), r(-2.0f, 2.0f)};
    rev.motorImpulse = r(-0.3f, 0.3f);
    rev.lowerImpulse = r(0.0f, 0.3f);
    rev.upperImpulse = r(0.0f, 0.3f);
    rev.enableMotor = flags & 1;
    rev.motorSpeed = r(-5.0f, 5.0f);
    rev.maxMotorTorque = r(0.0f, 60.0f);
    rev.enableLimit = flags & 2;
    rev.lowerAngle = r(-0.8f, 0.0f);
    rev.upperAngle = r(0.0f, 0.8f);
    rev.axialMass = effectiveMass(j.mass, angularRow);
    return j;
}

// A weld joint, its angle a spring (flags bit 0) or rigid.
PreparedJoint randomWeld(Random& r, int a, int b, int flags, const StepContext& ctx) {
    PreparedJoint j = randomFrame(r, JointType::Weld, a, b);
    WeldJoint& weld = j.data.emplace<WeldJoint>();
    weld.hertz = flags & 1 ? r(1.0f, 30.0f) : 0.0f;
    weld.dampingRatio = r(0.0f, 2.0f);
    weld.angularSoftness = makeSoftness(weld.hertz, weld.dampingRatio, ctx.hs);
    weld.axialMass = effectiveMass(j.mass, angularRow);
    weld.linearImpulse = {r(-2.0f, 2.0f), r(-2.0f, 2.0f)};
    weld.angularImpulse = r(-0.3f, 0.3f);
    return j;
}

// A prismatic joint, with a motor (flags bit 0) and a limit (bit 1) if asked.
PreparedJoint randomPrismatic(Random& r, int a, int b, int flags, const StepContext&) {
    PreparedJoint j = randomFrame(r, JointType::Prismatic, a, b);
    PrismaticJoint& slider = j.data.emplace<PrismaticJoint>();
    slider.axisA = randomAxis(r);
    slider.enableMotor = flags & 1;
    slider.motorSpeed = r(-5.0f, 5.0f);
    slider.maxMotorForce = r(0.0f, 60.0f);
    slider.enableLimit = flags & 2;
    slider.lower = r(-1.5f, 0.0f);
    slider.upper = r(0.0f, 1.5f);
    slider.axialMass = axialMass(j, slider.axisA);
    slider.impulse = {r(-2.0f, 2.0f), r(-0.3f, 0.3f)};
    slider.motorImpulse = r(-0.3f, 0.3f);
    slider.lowerImpulse = r(0.0f, 0.3f);
    slider.upperImpulse = r(0.0f, 0.3f);
    return j;
}

// A wheel joint, with a motor (flags bit 0) and a spring suspension (bit 1) if asked.
PreparedJoint randomWheel(Random& r, int a, int b, int flags, const StepContext& ctx) {
    PreparedJoint j = randomFrame(r, JointType::Wheel, a, b);
    WheelJoint& wheel = j.data.emplace<WheelJoint>();
    wheel.axisA = randomAxis(r);
    wheel.enableMotor = flags & 1;
    wheel.motorSpeed = r(-5.0f, 5.0f);
    wheel.maxMotorTorque = r(0.0f, 60.0f);
    wheel.hertz = flags & 2 ? r(1.0f, 30.0f) : 0.0f;
    wheel.dampingRatio = r(0.0f, 2.0f);
    wheel.spring = makeSoftness(wheel.hertz, wheel.dampingRatio, ctx.hs);
    wheel.axialMass = axialMass(j, wheel.axisA);
    wheel.motorMass = effectiveMass(j.mass, angularRow);
    wheel.perpImpulse = r(-2.0f, 2.0f);
    wheel.springImpulse = r(-2.0f, 2.0f);
    wheel.motorImpulse = r(-0.3f, 0.3f);
    return j;
}

// A distance joint, a spring with min and max rows (flags bit 0) or a rigid rod, its lengths
// (bit 1) close to the anchors' distance at step start, so that the min or max row is often
// reached, or Box2D's defaults 0 and 1e30 (always speculative). Its rest length is near that
// distance too.
PreparedJoint randomDistance(Random& r, int a, int b, int flags, const StepContext& ctx) {
    PreparedJoint j = randomFrame(r, JointType::Distance, a, b);
    DistanceJoint& rope = j.data.emplace<DistanceJoint>();
    const Vec2 d = j.deltaCenter + j.anchorB - j.anchorA;
    const float gap = length(d);
    rope.length = gap * r(0.9f, 1.1f);
    rope.minLength = flags & 2 ? gap * r(0.9f, 1.05f) : 0.0f;
    rope.maxLength = flags & 2 ? std::max(rope.minLength, gap * r(0.95f, 1.1f)) : 1.0e30f;
    rope.hertz = flags & 1 ? r(1.0f, 30.0f) : 0.0f;
    rope.dampingRatio = r(0.0f, 2.0f);
    rope.spring = makeSoftness(rope.hertz, rope.dampingRatio, ctx.hs);
    rope.axis = normalize(d);
    rope.axialMass = effectiveMass(j.mass, linearRow(j.anchorA, j.anchorB, rope.axis));
    rope.impulse = r(-2.0f, 2.0f);
    rope.lowerImpulse = r(0.0f, 0.3f);
    rope.upperImpulse = r(0.0f, 0.3f);
    return j;
}

// A motor joint, its force and torque caps low enough to hold its impulses back (flags bit 0) or
// far above them.
PreparedJoint randomMotor(Random& r, int a, int b, int flags, const StepContext&) {
    PreparedJoint j = randomFrame(r, JointType::Motor, a, b);
    MotorJoint& motor = j.data.emplace<MotorJoint>();
    motor.maxForce = flags & 1 ? r(0.0f, 60.0f) : 1.0e4f;
    motor.maxTorque = flags & 1 ? r(0.0f, 60.0f) : 1.0e4f;
    motor.correctionFactor = r(0.0f, 1.0f);
    motor.axialMass = effectiveMass(j.mass, angularRow);
    motor.linearImpulse = {r(-0.3f, 0.3f), r(-0.3f, 0.3f)};
    motor.angularImpulse = r(-0.3f, 0.3f);
    return j;
}

StepContext substepContext() {
    StepContext ctx;
    ctx.hs = 1.0f / 240.0f;
    ctx.invHs = 240.0f;
    ctx.invH = 60.0f;
    ctx.jointSoftness = makeSoftness(60.0f, 5.0f, ctx.hs);
    return ctx;
}

// A prepared joint's data as the store holds it before the step: what prepare writes is last
// step's (-1 here).
JointData lastStep(const PreparedJoint& j) {
    JointData data = j.data;
    const Softness stale{-1.0f, -1.0f, -1.0f};
    switch (j.type) {
        case JointType::Revolute: data.as<RevoluteJoint>().axialMass = -1.0f; break;
        case JointType::Weld:
            data.as<WeldJoint>().axialMass = -1.0f;
            data.as<WeldJoint>().angularSoftness = stale;
            break;
        case JointType::Prismatic:
            data.as<PrismaticJoint>().axisA = {-1.0f, -1.0f};
            data.as<PrismaticJoint>().axialMass = -1.0f;
            break;
        case JointType::Wheel: {
            WheelJoint& wheel = data.as<WheelJoint>();
            wheel.axisA = {-1.0f, -1.0f};
            wheel.axialMass = wheel.motorMass = -1.0f;
            wheel.spring = stale;
            break;
        }
        case JointType::Motor: data.as<MotorJoint>().axialMass = -1.0f; break;
        case JointType::Distance: {
            DistanceJoint& rope = data.as<DistanceJoint>();
            rope.axis = {-1.0f, -1.0f};
            rope.axialMass = -1.0f;
            rope.spring = stale;
            break;
        }
        default: break;
    }
    return data;
}

// Joints [0, count) (count < 4: the last lane empty) solved both ways from the same bodies, a warm
// start and a pass with bias, then a warm start and the relax pass: the bodies' velocities and
// the joints' data (impulses and all) must agree bit for bit.
void expectLanesEqualScalar(std::array<PreparedJoint, 4> joints, int count, std::vector<BodyState> states,
                            const std::vector<float>& stepRotation, const StepContext& ctx, const std::string& what) {
    std::vector<BodyState> scalar = states;
    std::array<PreparedJoint, 4> scalarJoints = joints;
    for (const bool useBias : {true, false}) {
        for (int lane = 0; lane < count; ++lane) {
            PreparedJoint& j = scalarJoints[lane];
            JointPair p = pairOf(scalar, stepRotation, j);
            stagesOf(j.type).warmStart(j, p);
            stagesOf(j.type).solve(j, p, ctx, useBias);
        }
    }

    const JointLaneStages& lanes = *stagesOf(joints[0].type).lanes;
    JointBlock block;
    // An empty lane takes the first joint's rows, as prepareJoints gives it.
    bool optionalRows = false;
    for (int lane = 0; lane < count; ++lane) optionalRows = optionalRows || lanes.optionalRows(joints[lane]);
    packJointBlock(block, {&joints[0], &joints[1], &joints[2], count == 4 ? &joints[3] : &joints[0]},
                   {0, 1, 2, count == 4 ? 3 : -1}, optionalRows);
    for (const bool useBias : {true, false}) {
        lanes.warmStart(&block, 1, states);
        lanes.solve(&block, 1, states, stepRotation, ctx, useBias);
    }

    for (size_t i = 0; i < states.size(); ++i) {
        EXPECT_TRUE(sameBits(states[i].v.x, scalar[i].v.x)) << what << " body " << i;
        EXPECT_TRUE(sameBits(states[i].v.y, scalar[i].v.y)) << what << " body " << i;
        EXPECT_TRUE(sameBits(states[i].w, scalar[i].w)) << what << " body " << i;
    }
    // The impulses go back to the joints (an empty lane's to none), with what prepare wrote, which
    // the store still holds as last step's (-1 here): each joint's data is then the bytes the scalar
    // solves left in its prepared copy. Revolute joints with the point rows alone keep their axial
    // mass as it was (they never stored it).
    std::vector<Joint> stored(4);
    for (int lane = 0; lane < 4; ++lane) stored[lane].data = lastStep(joints[lane]);
    lanes.store(block, stored);
    for (int lane = 0; lane < 4; ++lane) {
        JointData expected = lane < count ? scalarJoints[lane].data : lastStep(joints[lane]);
        if (lane < count && pointRowsOnly(joints[lane])) expected.as<RevoluteJoint>().axialMass = -1.0f;
        EXPECT_EQ(std::memcmp(&stored[lane].data, &expected, sizeof(JointData)), 0) << what << " lane " << lane;
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

// Every combination of a joint type's `bits` flags over the four lanes (bits·lane up of the
// round's flags): none, all, and mixed in one block; at least 25 times each, and as often again
// with the last lane empty. Lane 2's body A is static.
template <class Make>
void expectEveryCombinationToEqualScalarSolves(int bits, uint32_t seed, Make make) {
    const StepContext ctx = substepContext();
    Random r{seed};
    const int combinations = 1 << (4 * bits), rounds = std::max(combinations, 25);
    for (int round = 0; round < 2 * rounds; ++round) {
        const int flags = round % combinations;
        const int count = round < rounds ? 4 : 3;
        std::vector<float> stepRotation;
        const std::vector<BodyState> states = randomBodies(r, stepRotation);
        std::array<PreparedJoint, 4> joints;
        for (int lane = 0; lane < count; ++lane)
            joints[lane] = make(r, lane == 2 ? 0 : 2 * lane + 1, 2 * lane + 2, (flags >> (bits * lane)) & ((1 << bits) - 1), ctx);
        expectLanesEqualScalar(joints, count, states, stepRotation, ctx,
                               "flags " + std::to_string(flags) + " joints " + std::to_string(count));
        if (::testing::Test::HasFailure()) return;
    }
}

TEST(JointSolverWide, FourLanesEqualFourScalarSolves) {
    // Revolute point rows alone.
    expectEveryCombinationToEqualScalarSolves(0, 123456789u, randomRevolute);
}

TEST(JointSolverWide, MotorAndLimitLanesEqualScalarSolves) {
    expectEveryCombinationToEqualScalarSolves(2, 987654321u, randomRevolute);
}

TEST(JointSolverWide, WeldLanesEqualScalarSolves) {
    expectEveryCombinationToEqualScalarSolves(1, 192837465u, randomWeld);
}

TEST(JointSolverWide, PrismaticMotorAndLimitLanesEqualScalarSolves) {
    expectEveryCombinationToEqualScalarSolves(2, 564738291u, randomPrismatic);
}

TEST(JointSolverWide, WheelMotorAndSpringLanesEqualScalarSolves) {
    expectEveryCombinationToEqualScalarSolves(2, 918273645u, randomWheel);
}

TEST(JointSolverWide, DistanceSpringAndLimitLanesEqualScalarSolves) {
    expectEveryCombinationToEqualScalarSolves(2, 371925846u, randomDistance);
}

TEST(JointSolverWide, MotorLanesEqualScalarSolves) {
    expectEveryCombinationToEqualScalarSolves(1, 615243987u, randomMotor);
}

// normalize over lanes is math.hpp's lane by lane: the unit vector, and +0 for a vector of length
// 1e-12 or less (even for −0 components or a length that is not zero).
TEST(JointSolverWide, NormalizeLanesEqualScalar) {
    Random r{246813579u};
    const std::array<Vec2, 8> special = {Vec2{0.0f, 0.0f}, Vec2{-0.0f, -0.0f}, Vec2{1.0e-13f, -1.0e-13f}, Vec2{-1.0e-12f, 0.0f},
                                         Vec2{-2.0e-12f, 0.0f}, Vec2{3.0f, -4.0f}, Vec2{1.0e-30f, 0.0f}, Vec2{0.0f, -7.5f}};
    for (int round = 0; round < 66; ++round) {
        float x[4], y[4];
        for (int lane = 0; lane < 4; ++lane) {
            const Vec2 v = round < 2 ? special[4 * round + lane] : Vec2{r(-2.0f, 2.0f), r(-2.0f, 2.0f)};
            x[lane] = v.x;
            y[lane] = v.y;
        }
        const Vec2Lanes<Float4> n = normalize(Vec2Lanes<Float4>{Float4::load(x), Float4::load(y)});
        float nx[4], ny[4];
        n.x.store(nx);
        n.y.store(ny);
        for (int lane = 0; lane < 4; ++lane) {
            const Vec2 expected = normalize(Vec2{x[lane], y[lane]});
            EXPECT_TRUE(sameBits(nx[lane], expected.x) && sameBits(ny[lane], expected.y)) << "round " << round << " lane " << lane;
        }
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
