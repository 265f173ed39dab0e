// The lane layout of the wide rows, and the one way values get into it. A row set written over a
// lane type (contact rows, a joint type's rows) is nothing but floats, and in Rows<F> of N lanes
// field i of lane l is float i·N + l. A constraint's values are gathered straight into its lane
// field by field (RowLane<N>), and the same gather at N = 1 fills one constraint's own
// Rows<float> (the overflow colour, contact groups, scalar joints); impulses are read back from
// there the same way.
#pragma once

#include <cstddef>
#include <type_traits>

#include "simd/simd.hpp"
#include "core/solver/softness.hpp"
#include "perpdot/math.hpp"

namespace perpdot {

// How many floats Rows<float> holds; Rows<Float4> must be the same fields four wide.
template <template <class> class Rows>
constexpr std::size_t rowFloatsOf() {
    constexpr std::size_t floats = sizeof(Rows<float>) / sizeof(float);
    static_assert(std::is_standard_layout_v<Rows<float>> && std::is_standard_layout_v<Rows<simd::Float4>>);
    static_assert(sizeof(Rows<float>) == floats * sizeof(float) && sizeof(Rows<simd::Float4>) == floats * sizeof(simd::Float4),
                  "a row set must be floats only, the same fields at every lane width");
    return floats;
}

// A constraint's place in a row set of `lanes` lanes, from its first float: the field at byte
// offset `offset` of Rows<float> (its offsetof) is float (offset / 4)·lanes. Float is const float
// for reading.
template <std::size_t lanes, class Float = float>
struct RowLane {
    Float* first;

    Float& operator[](std::size_t offset) const { return first[offset / sizeof(float) * lanes]; }
    void set(std::size_t offset, float value) const { (*this)[offset] = value; }
    void set(std::size_t offset, Vec2 value) const {
        set(offset + offsetof(Vec2, x), value.x);
        set(offset + offsetof(Vec2, y), value.y);
    }
    void set(std::size_t offset, const Softness& value) const {
        set(offset + offsetof(Softness, biasRate), value.biasRate);
        set(offset + offsetof(Softness, massScale), value.massScale);
        set(offset + offsetof(Softness, impulseScale), value.impulseScale);
    }
    Vec2 vec(std::size_t offset) const { return {(*this)[offset + offsetof(Vec2, x)], (*this)[offset + offsetof(Vec2, y)]}; }
    Softness softness(std::size_t offset) const {
        return {(*this)[offset + offsetof(Softness, biasRate)], (*this)[offset + offsetof(Softness, massScale)],
                (*this)[offset + offsetof(Softness, impulseScale)]};
    }
};

// The rows of a block of N constraints (LaneBlock, lane_block.hpp): a row set Rows<F> of an N-lane
// F, at most `floats` floats a lane, kept as floats because only the AVX2 file may name its F, and
// read as the row set by as<Rows>().
template <std::size_t N, std::size_t floats>
struct alignas(N * sizeof(float)) LaneRows {
    float data[floats * N];

    template <class Rows>
    Rows& as() {
        static_assert(sizeof(Rows) <= sizeof data && alignof(Rows) <= alignof(LaneRows), "a row set of N lanes must fit");
        return *reinterpret_cast<Rows*>(data);
    }
};

// A row set's floats, where its lanes are gathered and read.
template <class Rows>
float* floatsOf(Rows& rows) {
    return reinterpret_cast<float*>(&rows);
}
template <class Rows>
const float* floatsOf(const Rows& rows) {
    return reinterpret_cast<const float*>(&rows);
}

}  // namespace perpdot
