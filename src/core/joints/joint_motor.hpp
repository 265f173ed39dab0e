// The motor joint's data, shared by its file (joint_motor.cpp) with the tests, and its field list.
#pragma once

#include <tuple>

#include "core/snapshot/field_list.hpp"
#include "perpdot/math.hpp"

namespace perpdot {

struct MotorJoint {
    float maxForce = 0, maxTorque = 0, correctionFactor = 0;
    float axialMass = 0;
    Vec2 linearImpulse;
    float angularImpulse = 0;
};

static_assert(reviewedLayout<MotorJoint, 28>);
constexpr auto fields(const MotorJoint*) {
    using J = MotorJoint;
    return std::tuple{field("maxForce", &J::maxForce).anyBits(),
                      field("maxTorque", &J::maxTorque).anyBits(),
                      field("correctionFactor", &J::correctionFactor).anyBits(),
                      field("axialMass", &J::axialMass).anyBits(),
                      field("linearImpulse", &J::linearImpulse).anyBits(),
                      field("angularImpulse", &J::angularImpulse).anyBits()};
}

}  // namespace perpdot
