// Packing revolute joints into the lanes of a RevoluteBlock, and their impulses back out.
#include "core/joint_solver_wide.hpp"

#include <algorithm>

#include "core/pack_lanes.hpp"

namespace perpdot {

// Rows and masses packed by the 4x4 transposes of pack_lanes.hpp; the angle rows only
// for a block that has a motor or a limit.
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
        block.angleRows = block.angleRows || !pointRowsOnly(j);
        rows[i] = revoluteRows(j);
        rowLanes[i] = &rows[i];
        massLanes[i] = &j.mass;
    }
    packLanes(rowLanes, block.rows);
    packLanes(massLanes, block.mass);
    if (block.angleRows) {
        RevoluteAngleRows<float> angle[4];
        const RevoluteAngleRows<float>* angleLanes[4];
        float motor = 0.0f, limit = 0.0f;  // 1 if a lane has one
        for (int i = 0; i < 4; ++i) {
            angle[i] = revoluteAngleRows(*lanes[i]);
            angleLanes[i] = &angle[i];
            motor = std::max(motor, angle[i].motor);
            limit = std::max(limit, angle[i].limit);
        }
        // An empty lane moves nothing whichever rows it solves: it takes those of the block, so
        // that a block of joints alike solves all its lanes without taking any back (solveWhere).
        for (int i = 0; i < 4; ++i) {
            if (joints[i] >= 0) continue;
            angle[i].motor = motor;
            angle[i].limit = limit;
        }
        packLanes(angleLanes, block.angle);
    }
    return block;
}

// The point rows' λ back to each lane's joint; where the block has angle rows, theirs too, and for
// a joint with a motor or a limit the axial mass prepareRevolute wrote, which snapshots carry and
// such a joint has always kept (one with the point rows alone never has).
void unpackRevoluteImpulses(const RevoluteBlock& block, std::span<Joint> joints) {
    float x[4], y[4];
    block.rows.linearImpulse.x.store(x);
    block.rows.linearImpulse.y.store(y);
    for (int lane = 0; lane < 4; ++lane)
        if (block.joint[lane] >= 0) joints[block.joint[lane]].data.as<RevoluteJoint>().linearImpulse = {x[lane], y[lane]};
    if (!block.angleRows) return;  // the point rows alone leave the angle rows' λ as they were
    float motor[4], lower[4], upper[4], axialMass[4];
    block.rows.motorImpulse.store(motor);
    block.rows.lowerImpulse.store(lower);
    block.rows.upperImpulse.store(upper);
    block.angle.axialMass.store(axialMass);
    for (int lane = 0; lane < 4; ++lane) {
        if (block.joint[lane] < 0) continue;
        RevoluteJoint& r = joints[block.joint[lane]].data.as<RevoluteJoint>();
        r.motorImpulse = motor[lane];
        r.lowerImpulse = lower[lane];
        r.upperImpulse = upper[lane];
        if (r.enableMotor || r.enableLimit) r.axialMass = axialMass[lane];
    }
}

}  // namespace perpdot
