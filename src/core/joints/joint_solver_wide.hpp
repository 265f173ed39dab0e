// Joints solved four at a time in SIMD lanes. A joint type that goes wide writes its rows once over
// a lane type F, as a row set (below): float solves one joint (the overflow colour),
// simd::Float4 solves a JointBlock of four joints of that type from one graph
// colour. A joint's values are gathered straight into its lane field by field (row_lanes.hpp, as
// the contacts' are), the same gather at one lane fills a scalar joint's own rows, and the impulses
// are read back from the lanes into the joints. A row some joints of the type lack (a motor, a
// limit) is computed in every lane, and a lane whose joint lacks it takes its velocities and
// impulses back (solveWhere, joint_rows.hpp), so it ends as the scalar joint that skips it. The
// lanes run the same operations in the same order as the scalar joint (no FMA, exact division), so
// they agree bit for bit.
//
// A row set RowSet (joint_revolute.cpp, joint_weld.cpp, joint_prismatic.cpp, joint_wheel.cpp,
// joint_distance.cpp, joint_motor.cpp) has
//   template <class F> struct Rows;                  its fields, floats only (row_lanes.hpp)
//   static bool optionalRows(const PreparedJoint&);   whether the joint has rows others of its type lack
//   static bool usesRotation(bool optionalRows);      whether solve reads p.rotation
//   template <std::size_t lanes> static void gather(const PreparedJoint&, RowLane<lanes>, bool optionalRows);
//   template <class F> static void warmStart(const Rows<F>&, JointPairT<F>&);
//   template <class F> static void solve(Rows<F>&, JointPairT<F>&, const StepContext&, bool useBias, bool optionalRows);
//   template <std::size_t lanes> static void store(RowLane<lanes, const float>, JointData&, bool optionalRows);
// store writes the impulses back, and what the type's prepare wrote where the joint's snapshots
// have carried it (the bytes a scalar solve leaves). optionalRows says, for a block, whether any
// lane has such rows (gather and solve may leave them out where none has); it is true for one joint.
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include "core/solver/body_lanes.hpp"
#include "core/joints/joint_rows.hpp"
#include "core/solver/row_lanes.hpp"

namespace perpdot {

// What the joint store calls for a type's blocks (JointStages::lanes; null for a scalar type).
struct JointLaneStages {
    bool (*optionalRows)(const PreparedJoint& joint);
    void (*gather)(JointBlock& block, const std::array<const PreparedJoint*, 4>& lanes);
    void (*warmStart)(JointBlock* blocks, int count, std::vector<BodyState>& states);
    void (*solve)(JointBlock* blocks, int count, std::vector<BodyState>& states, const std::vector<float>& stepRotation,
                  const StepContext& ctx, bool useBias);
    void (*store)(const JointBlock& block, std::span<Joint> joints);
};

// Four prepared joints of one type as the lanes of `block` (every field the passes read is
// rewritten): their slots, masses and rows; optionalRows: whether one of them has optional rows.
// joints[i] = -1 marks an empty lane: the static slot, no mass, and lanes[i]'s rows (colorJoints
// passes the block's first joint, so that a block of joints alike solves every lane alike).
void packJointBlock(JointBlock& block, const std::array<const PreparedJoint*, 4>& lanes, const std::array<int, 4>& joints,
                    bool optionalRows);

// (θB − θA) turned since the step began, of each lane's bodies.
inline simd::Float4 laneRotation(const JointBlock& block, const std::vector<float>& stepRotation) {
    float a[4], b[4];
    for (int lane = 0; lane < 4; ++lane) {
        a[lane] = stepRotation[block.bodyA[lane]];
        b[lane] = stepRotation[block.bodyB[lane]];
    }
    return simd::Float4::load(b) - simd::Float4::load(a);
}

// The frame at step start every row set begins with (rA, rB and cB − cA: R's anchorA, anchorB
// and deltaCenter), gathered from the prepared joint.
template <class R, std::size_t lanes>
void gatherFrame(const PreparedJoint& j, RowLane<lanes> out) {
    out.set(offsetof(R, anchorA), j.anchorA);
    out.set(offsetof(R, anchorB), j.anchorB);
    out.set(offsetof(R, deltaCenter), j.deltaCenter);
}

// Point rows and one angle row (weld and motor joints), as R's linearImpulse, angularImpulse,
// deltaAngle (θB − θA − θref at step start) and axialMass (the angle row's 1 / (1/IA + 1/IB))
// after the frame, gathered from the prepared joint and its data s.
template <class R, std::size_t lanes, class T>
void gatherPointAndAngle(const PreparedJoint& j, const T& s, RowLane<lanes> out) {
    gatherFrame<R>(j, out);
    out.set(offsetof(R, linearImpulse), s.linearImpulse);
    out.set(offsetof(R, angularImpulse), s.angularImpulse);
    out.set(offsetof(R, deltaAngle), j.deltaAngle);
    out.set(offsetof(R, axialMass), s.axialMass);
}

// Their warm start: last step's λ at the anchors, then the angle's on ωB − ωA.
template <class Rows, class F>
void warmStartPointAndAngle(const Rows& r, JointPairT<F>& p) {
    const JointFrameT<F> f = currentFrame(p, r.anchorA, r.anchorB, r.deltaCenter);
    applyPoint(p, f.rA, f.rB, r.linearImpulse);
    applyRow(p, angularRowOf<F>(), r.angularImpulse);
}

// And what goes back into the data: the impulses and the axial mass prepare wrote.
template <class R, std::size_t lanes, class T>
void storePointAndAngle(RowLane<lanes, const float> rows, T& s) {
    s.axialMass = rows[offsetof(R, axialMass)];
    s.linearImpulse = rows.vec(offsetof(R, linearImpulse));
    s.angularImpulse = rows[offsetof(R, angularImpulse)];
}

// A motor's and limits' constants (joint_rows.hpp), gathered at `offset` in the rows.
template <std::size_t lanes>
void gatherMotorLimits(RowLane<lanes> out, std::size_t offset, const MotorLimitsT<float>& c) {
    using M = MotorLimitsT<float>;
    out.set(offset + offsetof(M, motorSpeed), c.motorSpeed);
    out.set(offset + offsetof(M, maxMotor), c.maxMotor);
    out.set(offset + offsetof(M, lower), c.lower);
    out.set(offset + offsetof(M, upper), c.upper);
    out.set(offset + offsetof(M, motor), c.motor);
    out.set(offset + offsetof(M, limit), c.limit);
}

namespace joint_lanes {

template <class RowSet>
using WideRows = typename RowSet::template Rows<simd::Float4>;

template <class RowSet>
void gather(JointBlock& block, const std::array<const PreparedJoint*, 4>& lanes) {
    static_assert(rowFloatsOf<RowSet::template Rows>() <= jointRowCapacity, "a row set must fit: raise jointRowCapacity");
    for (int lane = 0; lane < 4; ++lane) RowSet::gather(*lanes[lane], RowLane<4>{block.rows.data + lane}, block.head.optionalRows);
}

// `rows(rows, pair, block)` on each block (forBlocks, body_lanes.hpp), its bodies in lanes.
template <class RowSet, class Rows>
void forJointBlocks(JointBlock* blocks, int count, std::vector<BodyState>& states, Rows rows) {
    forBlocks<simd::Float4, 0>(
        blocks, 0, count, states.data(),
        [&](JointBlock& block, BodyLanes<simd::Float4>& a, BodyLanes<simd::Float4>& b) {
            JointPairT<simd::Float4> p{a, b, block.head.mass};
            rows(block.rows.as<WideRows<RowSet>>(), p, block);
        },
        EveryBlock{});
}

template <class RowSet>
void warmStart(JointBlock* blocks, int count, std::vector<BodyState>& states) {
    forJointBlocks<RowSet>(blocks, count, states, [](const WideRows<RowSet>& rows, JointPairT<simd::Float4>& p, const JointBlock&) {
        RowSet::warmStart(rows, p);
    });
}

template <class RowSet>
void solve(JointBlock* blocks, int count, std::vector<BodyState>& states, const std::vector<float>& stepRotation,
           const StepContext& ctx, bool useBias) {
    forJointBlocks<RowSet>(blocks, count, states, [&](WideRows<RowSet>& rows, JointPairT<simd::Float4>& p, const JointBlock& block) {
        if (RowSet::usesRotation(block.head.optionalRows)) p.rotation = laneRotation(block, stepRotation);
        RowSet::solve(rows, p, ctx, useBias, block.head.optionalRows);
    });
}

template <class RowSet>
void store(const JointBlock& block, std::span<Joint> joints) {
    for (int lane = 0; lane < 4; ++lane)
        if (block.item[lane] >= 0)
            RowSet::store(RowLane<4, const float>{block.rows.data + lane}, joints[block.item[lane]].data, block.head.optionalRows);
}

}  // namespace joint_lanes

// A row set's stages for its type's blocks, for its JointStages.
template <class RowSet>
constexpr JointLaneStages jointLaneStages() {
    return {RowSet::optionalRows, joint_lanes::gather<RowSet>, joint_lanes::warmStart<RowSet>, joint_lanes::solve<RowSet>,
            joint_lanes::store<RowSet>};
}

// The same rows for one joint: gathered into its own Rows<float>, and for solve its impulses
// stored back into its data.
template <class RowSet>
void warmStartJoint(PreparedJoint& j, JointPair& p) {
    typename RowSet::template Rows<float> rows;
    RowSet::gather(j, RowLane<1>{floatsOf(rows)}, true);
    RowSet::warmStart(rows, p);
}

template <class RowSet>
void solveJoint(PreparedJoint& j, JointPair& p, const StepContext& ctx, bool useBias) {
    typename RowSet::template Rows<float> rows;
    RowSet::gather(j, RowLane<1>{floatsOf(rows)}, true);
    RowSet::solve(rows, p, ctx, useBias, true);
    RowSet::store(RowLane<1, const float>{floatsOf(rows)}, j.data, true);
}

}  // namespace perpdot
