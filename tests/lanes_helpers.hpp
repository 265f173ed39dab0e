// Shared by the tests that hold the 4-wide rows to the scalar ones bit for bit
// (contact_solver_wide_test, joint_solver_wide_test): random inputs and a bitwise comparison.
#pragma once

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>

#include "core/solver/row_lanes.hpp"
#include "core/world/step_context.hpp"

namespace perpdot::lanes_test {

// A linear congruential generator: the same numbers on every compiler and library.
struct Random {
    uint32_t x;
    float operator()(float lo, float hi) {
        x = x * 1664525u + 1013904223u;
        return lo + (hi - lo) * static_cast<float>(x >> 8) / 16777216.0f;
    }
};

// A body mid-substep: some velocity, a small displacement and turn since the step began.
inline BodyState randomBody(Random& r) {
    const float angle = r(-0.1f, 0.1f);
    return {{r(-2.0f, 2.0f), r(-2.0f, 2.0f)}, r(-3.0f, 3.0f), {r(-0.1f, 0.1f), r(-0.1f, 0.1f)}, Rot::fromAngle(angle), r(0.1f, 2.0f)};
}

inline bool sameBits(float a, float b) { return std::bit_cast<uint32_t>(a) == std::bit_cast<uint32_t>(b); }

// Four row sets as the lanes of one: field i of lane l at float 4i + l (row_lanes.hpp).
template <template <class> class Rows>
Rows<simd::Float4> lanesOf(const std::array<Rows<float>, 4>& rows) {
    Rows<simd::Float4> wide;
    for (std::size_t lane = 0; lane < 4; ++lane)
        for (std::size_t field = 0; field < rowFloatsOf<Rows>(); ++field) floatsOf(wide)[field * 4 + lane] = floatsOf(rows[lane])[field];
    return wide;
}

}  // namespace perpdot::lanes_test
