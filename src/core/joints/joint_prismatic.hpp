// The prismatic joint's data, shared by its file (joint_prismatic.cpp) with the tests, its field
// list, and what the gear joint (joint_gear.cpp) reads of it.
#pragma once

#include <tuple>

#include "core/snapshot/field_list.hpp"
#include "core/joints/joint_store.hpp"

namespace perpdot {

struct PrismaticJoint {
    Vec2 localAxisA;
    bool enableLimit = false, enableMotor = false;
    float lower = 0, upper = 0;
    float motorSpeed = 0, maxMotorForce = 0;
    Vec2 axisA;           // world axis at step start
    float axialMass = 0;  // of the row along the axis
    Vec2 impulse;         // (perpendicular, angular) rows
    float motorImpulse = 0, lowerImpulse = 0, upperImpulse = 0;
};

static_assert(reviewedLayout<PrismaticJoint, 60>);
constexpr auto fields(const PrismaticJoint*) {
    using J = PrismaticJoint;
    return std::tuple{field("localAxisA", &J::localAxisA).anyBits(),
                      field("enableLimit", &J::enableLimit),
                      field("enableMotor", &J::enableMotor),
                      field("lower", &J::lower).anyBits(),
                      field("upper", &J::upper).anyBits(),
                      field("motorSpeed", &J::motorSpeed).anyBits(),
                      field("maxMotorForce", &J::maxMotorForce).anyBits(),
                      field("axisA", &J::axisA).anyBits(),
                      field("axialMass", &J::axialMass).anyBits(),
                      field("impulse", &J::impulse).anyBits(),
                      field("motorImpulse", &J::motorImpulse).anyBits(),
                      field("lowerImpulse", &J::lowerImpulse).anyBits(),
                      field("upperImpulse", &J::upperImpulse).anyBits()};
}

// The prismatic joint's axis in body A's frame.
Vec2 prismaticLocalAxis(const Joint& prismatic);

}  // namespace perpdot
