// The mouse joint's data, shared by its file (joint_mouse.cpp) with the run-time settings
// (joint_settings.cpp), and its field list.
#pragma once

#include <tuple>

#include "core/snapshot/field_list.hpp"
#include "core/solver/softness.hpp"
#include "perpdot/math.hpp"

namespace perpdot {

// The target is anchor A (fixed in the world during a step: A is meant to be static).
struct MouseJoint {
    float hertz = 0, dampingRatio = 0, maxForce = 0;
    Softness softness;
    Vec2 linearImpulse;
};

static_assert(reviewedLayout<MouseJoint, 32>);
constexpr auto fields(const MouseJoint*) {
    using J = MouseJoint;
    return std::tuple{field("hertz", &J::hertz).anyBits(),
                      field("dampingRatio", &J::dampingRatio).anyBits(),
                      field("maxForce", &J::maxForce).anyBits(),
                      field("softness", &J::softness).anyBits(),
                      field("linearImpulse", &J::linearImpulse).anyBits()};
}


}  // namespace perpdot
