/// @file
/// Handles: an index into the world's pool plus the generation of the slot it was issued for,
/// so a handle to something destroyed is detected (perpdot::Error) instead of touching a reused slot.
#pragma once

#include <cstdint>

namespace perpdot {

/// A handle of one kind of object (the Tag keeps body, shape and joint handles apart).
template <class Tag>
struct Id {
    int32_t index = -1;       ///< slot in the world's pool; -1: the null handle
    uint32_t generation = 0;  ///< the slot's generation when the handle was issued

    /// Whether this is the default-constructed null handle.
    constexpr bool isNull() const { return index < 0; }
    /// Same slot and generation.
    friend constexpr bool operator==(Id, Id) = default;
};

using BodyId = Id<struct BodyTag>;    ///< handle of a body
using ShapeId = Id<struct ShapeTag>;  ///< handle of a shape
using JointId = Id<struct JointTag>;  ///< handle of a joint

}  // namespace perpdot
