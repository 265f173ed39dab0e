// The lane layout of the wide rows: a row set written over a lane type (contact rows, revolute
// joint rows, joint masses) is nothing but floats, and in Rows<F> of N lanes field i of lane l is
// float i·N + l. Revolute rows and joint masses are packed into it by 4x4 transposes (packLanes);
// contact rows are gathered into their lanes field by field (contact_solver.cpp).
#pragma once

#include <algorithm>
#include <cstddef>
#include <type_traits>

#include "core/simd.hpp"

namespace perpdot {

// How many floats Rows<float> holds; Rows<Float4> must be the same fields four wide.
template <template <class> class Rows>
constexpr std::size_t rowFloatsOf() {
    constexpr std::size_t floats = sizeof(Rows<float>) / sizeof(float);
    static_assert(std::is_standard_layout_v<Rows<float>> && std::is_standard_layout_v<Rows<simd::Float4>>);
    static_assert(sizeof(Rows<float>) == floats * sizeof(float) && sizeof(Rows<simd::Float4>) == floats * sizeof(simd::Float4),
                  "a row set must be floats only, the same fields at every lane width");
    static_assert(floats >= 4, "the transposes take four floats at a time");
    return floats;
}

// Four row sets as the lanes of one (an empty lane: a default Rows<float>, which moves nothing).
template <template <class> class Rows>
[[gnu::always_inline]] inline void packLanes(const Rows<float>* const (&lanes)[4], Rows<simd::Float4>& packed) {
    constexpr std::size_t floats = rowFloatsOf<Rows>();
    auto* out = reinterpret_cast<simd::Float4*>(&packed);
    for (std::size_t k = 0; k < floats; k += 4) {
        const std::size_t first = std::min(k, floats - 4);  // the last run overlaps the one before
        simd::Float4 run[4];
        for (int i = 0; i < 4; ++i) run[i] = simd::Float4::loadBytes(reinterpret_cast<const float*>(lanes[i]) + first);
        simd::transpose(run);
        std::copy(run, run + 4, out + first);
    }
}

}  // namespace perpdot
