// The rows of the joints a direct solve takes (contact groups, contact_groups.hpp; joint trees,
// joint_tree.hpp): revolute, rigid weld and prismatic joints, motor aside. A joint's rows come in
// one order, its equality rows first, then its limits:
//   revolute   point x, point y, lower, upper
//   weld       point x, point y, angle
//   prismatic  across the axis, angle, lower, upper
#pragma once

#include "core/joints/joint.hpp"
#include "core/joints/joint_rows.hpp"

namespace perpdot {

// How many rows a joint of `type` has, with or without its limits, and how many are equalities.
int equalityRowCount(JointType type);
inline int directRowCount(JointType type, bool limited) { return equalityRowCount(type) + (limited ? 2 : 0); }

// The joint's rows with its bodies where they are now (pair p): its count of them.
int jointRowsNow(const PreparedJoint& j, const JointPair& p, DirectJointRow* rows);
// Their position errors C now (a limit's: how far inside it), in the same order.
void jointRowErrors(const PreparedJoint& j, const JointPair& p, float* C);
// Where row `row` keeps its accumulated λ.
float& jointRowImpulse(PreparedJoint& j, int row);

}  // namespace perpdot
