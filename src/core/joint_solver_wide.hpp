// The revolute joint's point rows, written once over a lane type F: float solves one joint
// (joint_revolute.cpp, which adds the motor and limit rows), simd::Float4 solves four revolute
// joints without motor or limit, of one graph colour, at once (a RevoluteBlock). The rows hold
// B's anchor on A's with the 2x2 K of joint_rows.hpp; the lanes run the same operations in the
// same order as the scalar joint (no FMA, exact division), so they agree bit for bit.
#pragma once

#include <array>
#include <span>

#include "core/body_lanes.hpp"
#include "core/joint_revolute.hpp"
#include "core/joint_rows.hpp"

namespace perpdot {

// What the point rows of a revolute joint carry through a step.
template <class F>
struct RevoluteRows {
    Vec2T<F> anchorA, anchorB;  // rA, rB at step start
    Vec2T<F> deltaCenter;       // cB − cA at step start
    Vec2T<F> linearImpulse;     // λ of the point rows
    F angularImpulse{};         // motor + lower − upper on ωB − ωA: re-applied by the warm start
};

// The point rows of one prepared revolute joint.
inline RevoluteRows<float> revoluteRows(const PreparedJoint& j) {
    const RevoluteJoint& r = j.data.as<RevoluteJoint>();
    return {j.anchorA, j.anchorB, j.deltaCenter, r.linearImpulse, r.motorImpulse + r.lowerImpulse - r.upperImpulse};
}

// Re-apply last step's impulses: λ at the anchors, then the angular impulse.
template <class F>
void warmStartRevoluteRows(const RevoluteRows<F>& r, JointPairT<F>& p) {
    const JointFrameT<F> f = currentFrame(p, r.anchorA, r.anchorB, r.deltaCenter);
    applyPoint(p, f.rA, f.rB, r.linearImpulse);
    applyRow(p, angularRowOf<F>(), r.angularImpulse);
}

// One pass of the point rows on C = pB − pA, with the substep pass's softness.
template <class F>
void solveRevolutePoint(RevoluteRows<F>& r, JointPairT<F>& p, const Softness& soft) {
    const JointFrameT<F> f = currentFrame(p, r.anchorA, r.anchorB, r.deltaCenter);
    solvePointRows(p, f.rA, f.rB, f.d, soft, r.linearImpulse);
}

// A revolute joint without motor or limit: its rows are the point rows alone.
inline bool solvesInLanes(const PreparedJoint& j) {
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
};

// Four prepared joints as lanes; joints[i] = -1 marks an empty lane, whose PreparedJoint should
// have no mass (it then moves nothing).
RevoluteBlock packRevoluteBlock(const std::array<const PreparedJoint*, 4>& lanes, const std::array<int, 4>& joints);
// Each lane's accumulated point impulse back to its joint.
void unpackRevoluteImpulses(const RevoluteBlock& block, std::span<Joint> joints);

}  // namespace perpdot
