// The revolute joint's rows, written once over a lane type F: float solves one joint
// (joint_revolute.cpp: the overflow colour and revolute trees that do not factor), simd::Float4
// solves four revolute joints of one graph colour at once (a RevoluteBlock), with or without motor
// and limit. The point rows hold B's anchor on A's with the 2x2 K of joint_rows.hpp; the motor and
// the two limits are rows on the angle θB − θA − θref with effective mass 1/(1/IA + 1/IB). A lane
// whose joint has no motor (no limit) computes those rows and then takes its velocities and
// impulses back (solveWhere), so it ends as the scalar joint that skips them. The lanes run the
// same operations in the same order as the scalar joint (no FMA, exact division), so they agree
// bit for bit.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "core/body_lanes.hpp"
#include "core/joint_revolute.hpp"
#include "core/joint_rows.hpp"

namespace perpdot {

// What the rows of a revolute joint carry through a step and re-apply in the warm start.
template <class F>
struct RevoluteRows {
    Vec2T<F> anchorA, anchorB;  // rA, rB at step start
    Vec2T<F> deltaCenter;       // cB − cA at step start
    Vec2T<F> linearImpulse;     // λ of the point rows
    F motorImpulse{}, lowerImpulse{}, upperImpulse{};  // λ of the angle rows
};

// The angle rows' constants: the motor's, the limits', and whether the joint has them.
template <class F>
struct RevoluteAngleRows {
    F deltaAngle{};  // θB − θA − θref at step start
    F axialMass{};   // 1 / (1/IA + 1/IB)
    F motorSpeed{}, maxMotorTorque{};
    F lowerAngle{}, upperAngle{};
    F motor{}, limit{};  // 1 where enabled, else 0
};

// The rows of one prepared revolute joint, and their impulses back into its data.
inline RevoluteRows<float> revoluteRows(const PreparedJoint& j) {
    const RevoluteJoint& r = j.data.as<RevoluteJoint>();
    return {j.anchorA, j.anchorB, j.deltaCenter, r.linearImpulse, r.motorImpulse, r.lowerImpulse, r.upperImpulse};
}
inline RevoluteAngleRows<float> revoluteAngleRows(const PreparedJoint& j) {
    const RevoluteJoint& r = j.data.as<RevoluteJoint>();
    return {j.deltaAngle, r.axialMass, r.motorSpeed, r.maxMotorTorque, r.lowerAngle, r.upperAngle,
            r.enableMotor ? 1.0f : 0.0f, r.enableLimit ? 1.0f : 0.0f};
}
inline void storeImpulses(const RevoluteRows<float>& rows, RevoluteJoint& r) {
    r.linearImpulse = rows.linearImpulse;
    r.motorImpulse = rows.motorImpulse;
    r.lowerImpulse = rows.lowerImpulse;
    r.upperImpulse = rows.upperImpulse;
}

// Re-apply last step's impulses: λ at the anchors, then motor + lower − upper on ωB − ωA.
template <class F>
void warmStartRevoluteRows(const RevoluteRows<F>& r, JointPairT<F>& p) {
    const JointFrameT<F> f = currentFrame(p, r.anchorA, r.anchorB, r.deltaCenter);
    applyPoint(p, f.rA, f.rB, r.linearImpulse);
    applyRow(p, angularRowOf<F>(), r.motorImpulse + r.lowerImpulse - r.upperImpulse);
}

// One pass of the point rows on C = pB − pA, with the substep pass's softness.
template <class F>
void solveRevolutePoint(RevoluteRows<F>& r, JointPairT<F>& p, const Softness& soft) {
    const JointFrameT<F> f = currentFrame(p, r.anchorA, r.anchorB, r.deltaCenter);
    solvePointRows(p, f.rA, f.rB, f.d, soft, r.linearImpulse);
}

// One pass of all the rows: the motor drives ωB − ωA to motorSpeed (|λ| ≤ maxMotorTorque·hs), the
// limits keep θ − lower ≥ 0 and upper − θ ≥ 0, θ = (θB − θA − θref)₀ + p.rotation; then the point,
// solved last so that the stiffest part wins.
template <class F>
void solveRevoluteRows(RevoluteRows<F>& r, const RevoluteAngleRows<F>& a, JointPairT<F>& p, const StepContext& ctx, bool useBias) {
    const RowT<F> angular = angularRowOf<F>();
    solveWhere(
        a.motor != F(0.0f), p,
        [&] { solveMotorRow(p, angular, a.axialMass, a.motorSpeed, a.maxMotorTorque * F(ctx.hs), r.motorImpulse); },
        r.motorImpulse);
    solveWhere(
        a.limit != F(0.0f), p,
        [&] {
            const F angle = a.deltaAngle + p.rotation;
            solveLimitRow(p, angular, a.axialMass, angle - a.lowerAngle, ctx, useBias, r.lowerImpulse);
            solveLimitRow(p, negated(angular), a.axialMass, a.upperAngle - angle, ctx, useBias, r.upperImpulse);
        },
        r.lowerImpulse, r.upperImpulse);
    solveRevolutePoint(r, p, rigidSoftness(ctx, useBias));
}

// Revolute joints solve in lanes; those without motor or limit (the point rows alone) are also
// what revolute trees are made of (joint_tree.hpp) and fill their colour's first blocks.
inline bool solvesInLanes(const PreparedJoint& j) { return j.type == JointType::Revolute; }
inline bool pointRowsOnly(const PreparedJoint& j) {
    if (j.type != JointType::Revolute) return false;
    const RevoluteJoint& r = j.data.as<RevoluteJoint>();
    return !r.enableMotor && !r.enableLimit;
}

// Four revolute joints of one graph colour (no two share a dynamic body) as the lanes of one row set.
struct RevoluteBlock {
    RevoluteRows<simd::Float4> rows;
    JointMassT<simd::Float4> mass;
    int joint[4] = {-1, -1, -1, -1};   // index in JointStore::joints; -1: an empty lane
    int bodyA[4] = {}, bodyB[4] = {};  // solver slots; an empty lane uses the static slot 0
    bool angleRows = false;            // whether a lane has a motor or a limit
    // Packed only where angleRows; last, away from what every block reads.
    RevoluteAngleRows<simd::Float4> angle;
};

// Four prepared joints as lanes; joints[i] = -1 marks an empty lane, whose PreparedJoint should
// have no mass (it then moves nothing).
RevoluteBlock packRevoluteBlock(const std::array<const PreparedJoint*, 4>& lanes, const std::array<int, 4>& joints);
// (θB − θA) turned since the step began, of each lane's bodies.
inline simd::Float4 laneRotation(const RevoluteBlock& block, const std::vector<float>& stepRotation) {
    float a[4], b[4];
    for (int lane = 0; lane < 4; ++lane) {
        a[lane] = stepRotation[block.bodyA[lane]];
        b[lane] = stepRotation[block.bodyB[lane]];
    }
    return simd::Float4::load(b) - simd::Float4::load(a);
}
// One pass of a block's rows (p.rotation is set here): all of them where a lane has a motor or a
// limit, else the point rows alone.
inline void solveRevoluteBlock(RevoluteBlock& block, JointPairT<simd::Float4>& p, const std::vector<float>& stepRotation,
                               const StepContext& ctx, bool useBias) {
    if (block.angleRows) {
        p.rotation = laneRotation(block, stepRotation);
        solveRevoluteRows(block.rows, block.angle, p, ctx, useBias);
    } else {
        solveRevolutePoint(block.rows, p, rigidSoftness(ctx, useBias));
    }
}
// Each lane's accumulated impulses back to its joint.
void unpackRevoluteImpulses(const RevoluteBlock& block, std::span<Joint> joints);

}  // namespace perpdot
