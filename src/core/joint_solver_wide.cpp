// Packing revolute joints into the lanes of a RevoluteBlock, and their impulses back out.
#include "core/joint_solver_wide.hpp"

namespace perpdot {

using simd::Float4;

namespace {

// The lanes of one float of four joints.
template <class Field>
Float4 lanesOf(const std::array<RevoluteRows<float>, 4>& rows, Field field) {
    float x[4];
    for (int i = 0; i < 4; ++i) x[i] = field(rows[i]);
    return Float4::load(x);
}

}  // namespace

RevoluteBlock packRevoluteBlock(const std::array<const PreparedJoint*, 4>& lanes, const std::array<int, 4>& joints) {
    RevoluteBlock block;
    std::array<RevoluteRows<float>, 4> rows;
    float mA[4], iA[4], mB[4], iB[4];
    for (int i = 0; i < 4; ++i) {
        const PreparedJoint& j = *lanes[i];
        block.joint[i] = joints[i];
        block.bodyA[i] = j.indexA;
        block.bodyB[i] = j.indexB;
        mA[i] = j.mass.mA;
        iA[i] = j.mass.iA;
        mB[i] = j.mass.mB;
        iB[i] = j.mass.iB;
        rows[i] = revoluteRows(j);
    }
    block.mass = {Float4::load(mA), Float4::load(iA), Float4::load(mB), Float4::load(iB)};
    using R = RevoluteRows<float>;
    RevoluteRows<Float4>& r = block.rows;
    r.anchorA = {lanesOf(rows, [](const R& j) { return j.anchorA.x; }), lanesOf(rows, [](const R& j) { return j.anchorA.y; })};
    r.anchorB = {lanesOf(rows, [](const R& j) { return j.anchorB.x; }), lanesOf(rows, [](const R& j) { return j.anchorB.y; })};
    r.deltaCenter = {lanesOf(rows, [](const R& j) { return j.deltaCenter.x; }),
                     lanesOf(rows, [](const R& j) { return j.deltaCenter.y; })};
    r.linearImpulse = {lanesOf(rows, [](const R& j) { return j.linearImpulse.x; }),
                       lanesOf(rows, [](const R& j) { return j.linearImpulse.y; })};
    r.angularImpulse = lanesOf(rows, [](const R& j) { return j.angularImpulse; });
    return block;
}

void unpackRevoluteImpulses(const RevoluteBlock& block, std::span<Joint> joints) {
    float x[4], y[4];
    block.rows.linearImpulse.x.store(x);
    block.rows.linearImpulse.y.store(y);
    for (int lane = 0; lane < 4; ++lane)
        if (block.joint[lane] >= 0) joints[block.joint[lane]].data.as<RevoluteJoint>().linearImpulse = {x[lane], y[lane]};
}

}  // namespace perpdot
