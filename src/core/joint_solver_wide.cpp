// Packing revolute joints into the lanes of a RevoluteBlock, and their impulses back out.
#include "core/joint_solver_wide.hpp"

#include "core/pack_lanes.hpp"

namespace perpdot {

// Rows and masses by the one packing idiom of the wide rows (pack_lanes.hpp).
RevoluteBlock packRevoluteBlock(const std::array<const PreparedJoint*, 4>& lanes, const std::array<int, 4>& joints) {
    RevoluteBlock block;
    RevoluteRows<float> rows[4];
    const RevoluteRows<float>* rowLanes[4];
    const JointMassT<float>* massLanes[4];
    for (int i = 0; i < 4; ++i) {
        const PreparedJoint& j = *lanes[i];
        block.joint[i] = joints[i];
        block.bodyA[i] = j.indexA;
        block.bodyB[i] = j.indexB;
        rows[i] = revoluteRows(j);
        rowLanes[i] = &rows[i];
        massLanes[i] = &j.mass;
    }
    packLanes(rowLanes, block.rows);
    packLanes(massLanes, block.mass);
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
