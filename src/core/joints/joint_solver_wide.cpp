// Four joints of one type into the lanes of a JointBlock.
#include "core/joints/joint_solver_wide.hpp"

#include <cstddef>

namespace perpdot {

// The slots and masses lane by lane (field by field, row_lanes.hpp), then the rows by the type's
// gather (its row set's).
void packJointBlock(JointBlock& block, const std::array<const PreparedJoint*, 4>& lanes, const std::array<int, 4>& joints,
                    bool optionalRows) {
    block.head.type = lanes[0]->type;
    block.head.optionalRows = optionalRows;
    for (int lane = 0; lane < 4; ++lane) {
        const bool used = joints[lane] >= 0;
        const PreparedJoint& j = *lanes[lane];
        block.item[lane] = joints[lane];
        block.bodyA[lane] = used ? j.indexA : 0;
        block.bodyB[lane] = used ? j.indexB : 0;
        const JointMass m = used ? j.mass : JointMass{};
        const RowLane<4> mass{floatsOf(block.head.mass) + lane};
        mass.set(offsetof(JointMass, mA), m.mA);
        mass.set(offsetof(JointMass, iA), m.iA);
        mass.set(offsetof(JointMass, mB), m.mB);
        mass.set(offsetof(JointMass, iB), m.iB);
    }
    stagesOf(block.head.type).lanes->gather(block, lanes);
}

}  // namespace perpdot
