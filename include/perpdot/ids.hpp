// Handles: an index into the world's pool plus the generation of the slot it was issued for,
// so a handle to something destroyed is detected (perpdot::Error) instead of touching a reused slot.
#pragma once

#include <cstdint>

namespace perpdot {

template <class Tag>
struct Id {
    int32_t index = -1;
    uint32_t generation = 0;

    constexpr bool isNull() const { return index < 0; }
    friend constexpr bool operator==(Id, Id) = default;
};

using BodyId = Id<struct BodyTag>;
using ShapeId = Id<struct ShapeTag>;
using JointId = Id<struct JointTag>;

}  // namespace perpdot
