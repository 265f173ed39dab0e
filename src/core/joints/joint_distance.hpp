// The distance joint's data, shared by its file (joint_distance.cpp) with the tests, and its field list.
#pragma once

#include <tuple>

#include "core/snapshot/field_list.hpp"
#include "core/solver/softness.hpp"
#include "perpdot/math.hpp"

namespace perpdot {

struct DistanceJoint {
    float length = 1, minLength = 0, maxLength = 0;
    float hertz = 0, dampingRatio = 0;
    Softness spring;
    Vec2 axis;            // B's anchor from A's, unit, at step start
    float axialMass = 0;
    float impulse = 0, lowerImpulse = 0, upperImpulse = 0;
};

static_assert(reviewedLayout<DistanceJoint, 56>);
constexpr auto fields(const DistanceJoint*) {
    using J = DistanceJoint;
    return std::tuple{field("length", &J::length).anyBits(),
                      field("minLength", &J::minLength).anyBits(),
                      field("maxLength", &J::maxLength).anyBits(),
                      field("hertz", &J::hertz).anyBits(),
                      field("dampingRatio", &J::dampingRatio).anyBits(),
                      field("spring", &J::spring).anyBits(),
                      field("axis", &J::axis).anyBits(),
                      field("axialMass", &J::axialMass).anyBits(),
                      field("impulse", &J::impulse).anyBits(),
                      field("lowerImpulse", &J::lowerImpulse).anyBits(),
                      field("upperImpulse", &J::upperImpulse).anyBits()};
}

}  // namespace perpdot
