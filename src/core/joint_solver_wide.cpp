// Packing revolute joints into the lanes of a RevoluteBlock, and their impulses back out.
#include "core/joint_solver_wide.hpp"

namespace perpdot {

using simd::Float4;

namespace {

// The lanes of one float of four values.
template <class T, class Field>
Float4 lanesOf(const std::array<T, 4>& lanes, Field field) {
    float x[4];
    for (int i = 0; i < 4; ++i) x[i] = field(lanes[i]);
    return Float4::load(x);
}

}  // namespace

RevoluteRows<Float4> packRevoluteRows(const std::array<RevoluteRows<float>, 4>& lanes) {
    using R = RevoluteRows<float>;
    RevoluteRows<Float4> r;
    r.anchorA = {lanesOf(lanes, [](const R& j) { return j.anchorA.x; }), lanesOf(lanes, [](const R& j) { return j.anchorA.y; })};
    r.anchorB = {lanesOf(lanes, [](const R& j) { return j.anchorB.x; }), lanesOf(lanes, [](const R& j) { return j.anchorB.y; })};
    r.deltaCenter = {lanesOf(lanes, [](const R& j) { return j.deltaCenter.x; }),
                     lanesOf(lanes, [](const R& j) { return j.deltaCenter.y; })};
    r.linearImpulse = {lanesOf(lanes, [](const R& j) { return j.linearImpulse.x; }),
                       lanesOf(lanes, [](const R& j) { return j.linearImpulse.y; })};
    r.angularImpulse = lanesOf(lanes, [](const R& j) { return j.angularImpulse; });
    return r;
}

JointMassT<Float4> packJointMasses(const std::array<JointMass, 4>& lanes) {
    return {lanesOf(lanes, [](const JointMass& m) { return m.mA; }), lanesOf(lanes, [](const JointMass& m) { return m.iA; }),
            lanesOf(lanes, [](const JointMass& m) { return m.mB; }), lanesOf(lanes, [](const JointMass& m) { return m.iB; })};
}

void unpackRevoluteImpulses(const RevoluteBlock& block, std::vector<Joint>& joints) {
    float x[4], y[4];
    block.rows.linearImpulse.x.store(x);
    block.rows.linearImpulse.y.store(y);
    for (int lane = 0; lane < 4; ++lane)
        if (block.joint[lane] >= 0) joints[block.joint[lane]].data.revolute.linearImpulse = {x[lane], y[lane]};
}

}  // namespace perpdot
