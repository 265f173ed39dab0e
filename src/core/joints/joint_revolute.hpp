// The revolute joint's data, shared by its file (joint_revolute.cpp) with the joint trees
// (joint_tree.cpp) and the tests, and its field list.
#pragma once

#include <tuple>

#include "core/snapshot/field_list.hpp"
#include "core/joints/joint_store.hpp"
#include "perpdot/math.hpp"

namespace perpdot {

struct RevoluteJoint {
    bool enableLimit = false, enableMotor = false;
    float lowerAngle = 0, upperAngle = 0;
    float motorSpeed = 0, maxMotorTorque = 0;
    float axialMass = 0;  // 1 / (1/IA + 1/IB)
    Vec2 linearImpulse;   // point rows
    float motorImpulse = 0, lowerImpulse = 0, upperImpulse = 0;
};

static_assert(reviewedLayout<RevoluteJoint, 44>);
constexpr auto fields(const RevoluteJoint*) {
    using J = RevoluteJoint;
    return std::tuple{field("enableLimit", &J::enableLimit),
                      field("enableMotor", &J::enableMotor),
                      field("lowerAngle", &J::lowerAngle).anyBits(),
                      field("upperAngle", &J::upperAngle).anyBits(),
                      field("motorSpeed", &J::motorSpeed).anyBits(),
                      field("maxMotorTorque", &J::maxMotorTorque).anyBits(),
                      field("axialMass", &J::axialMass).anyBits(),
                      field("linearImpulse", &J::linearImpulse).anyBits(),
                      field("motorImpulse", &J::motorImpulse).anyBits(),
                      field("lowerImpulse", &J::lowerImpulse).anyBits(),
                      field("upperImpulse", &J::upperImpulse).anyBits()};
}

// A revolute joint without motor or limit: its point rows alone (a joint tree solves the motor
// row of the others first, joint_tree.hpp).
inline bool pointRowsOnly(const PreparedJoint& j) {
    if (j.type != JointType::Revolute) return false;
    const RevoluteJoint& r = j.data.as<RevoluteJoint>();
    return !r.enableMotor && !r.enableLimit;
}

}  // namespace perpdot
