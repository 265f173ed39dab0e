/// @file
/// Handles: an index into the world's pool, the generation of the slot it was issued for, and the
/// identity of the World that issued it, so that a handle to something destroyed, or one from
/// another World, is refused (perpdot::Error) instead of touching a slot it does not name.
///
/// World identity: every World made by its constructor gets an identity of its own (a serial,
/// never 0), and a moved World keeps it. A snapshot carries the identity of the World it was taken
/// of, and a World that restores it takes that identity on: the handles that were valid when the
/// snapshot was taken are valid in every World it is restored into (a rollback, a copy for
/// prediction, a client given a server's state), and the World goes on accepting the handles of
/// its own, first identity too. Handles of any other World are refused.
#pragma once

#include <cstdint>

namespace perpdot {

/// A handle of one kind of object (the Tag keeps body, shape and joint handles apart). Trivially
/// copyable, 12 bytes; compare with ==.
template <class Tag>
struct Id {
    int32_t index = -1;       ///< slot in the world's pool; -1: the null handle
    uint32_t generation = 0;  ///< the slot's generation when the handle was issued
    uint32_t world = 0;       ///< identity of the World that issued it (0: none)

    /// Whether this is the default-constructed null handle.
    constexpr bool isNull() const { return index < 0; }
    /// Same slot, generation and world.
    friend constexpr bool operator==(Id, Id) = default;
};

using BodyId = Id<struct BodyTag>;    ///< handle of a body
using ShapeId = Id<struct ShapeTag>;  ///< handle of a shape
using JointId = Id<struct JointTag>;  ///< handle of a joint

}  // namespace perpdot
