// The wheel joint's data, shared by its file (joint_wheel.cpp) with the tests, and its field list.
#pragma once

#include <tuple>

#include "core/snapshot/field_list.hpp"
#include "core/solver/softness.hpp"
#include "perpdot/math.hpp"

namespace perpdot {

struct WheelJoint {
    Vec2 localAxisA;
    float hertz = 0, dampingRatio = 0;  // 0 hertz: rigid suspension
    bool enableMotor = false;
    float motorSpeed = 0, maxMotorTorque = 0;
    Softness spring;
    Vec2 axisA;
    float axialMass = 0, motorMass = 0;
    float perpImpulse = 0, springImpulse = 0, motorImpulse = 0;
};

static_assert(reviewedLayout<WheelJoint, 68>);
constexpr auto fields(const WheelJoint*) {
    using J = WheelJoint;
    return std::tuple{field("localAxisA", &J::localAxisA).anyBits(),
                      field("hertz", &J::hertz).anyBits(),
                      field("dampingRatio", &J::dampingRatio).anyBits(),
                      field("enableMotor", &J::enableMotor),
                      field("motorSpeed", &J::motorSpeed).anyBits(),
                      field("maxMotorTorque", &J::maxMotorTorque).anyBits(),
                      field("spring", &J::spring).anyBits(),
                      field("axisA", &J::axisA).anyBits(),
                      field("axialMass", &J::axialMass).anyBits(),
                      field("motorMass", &J::motorMass).anyBits(),
                      field("perpImpulse", &J::perpImpulse).anyBits(),
                      field("springImpulse", &J::springImpulse).anyBits(),
                      field("motorImpulse", &J::motorImpulse).anyBits()};
}

}  // namespace perpdot
