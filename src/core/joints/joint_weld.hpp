// The weld joint's data, shared by its file (joint_weld.cpp) with the tests, and its field list.
#pragma once

#include <tuple>

#include "core/snapshot/field_list.hpp"
#include "core/solver/softness.hpp"
#include "perpdot/math.hpp"

namespace perpdot {

struct WeldJoint {
    float hertz = 0, dampingRatio = 0;  // soft in the angle only, like Box2D 2.4's weld
    Softness angularSoftness;
    float axialMass = 0;
    Vec2 linearImpulse;
    float angularImpulse = 0;
};

static_assert(reviewedLayout<WeldJoint, 36>);
constexpr auto fields(const WeldJoint*) {
    using J = WeldJoint;
    return std::tuple{field("hertz", &J::hertz).anyBits(),
                      field("dampingRatio", &J::dampingRatio).anyBits(),
                      field("angularSoftness", &J::angularSoftness).anyBits(),
                      field("axialMass", &J::axialMass).anyBits(),
                      field("linearImpulse", &J::linearImpulse).anyBits(),
                      field("angularImpulse", &J::angularImpulse).anyBits()};
}

}  // namespace perpdot
