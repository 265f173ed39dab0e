// The snapshot format's version and the field lists (field_list.hpp) of the math types every
// persisted struct is made of, joint types' data included: what a joint type's file needs of the
// snapshot, without the world (snapshot_fields.hpp holds the world's structs).
#pragma once

#include <cstdint>
#include <tuple>

#include "core/snapshot/field_list.hpp"
#include "core/solver/softness.hpp"
#include "perpdot/math.hpp"

namespace perpdot {

// 1: joint type data as raw struct bytes. 2: every struct through its field list. 3: end events
// raised between steps (a body or shape destroyed), which the next step reports. 4: kept
// manifolds (manifold_reuse.hpp), WorldDef::contactReuseDistance and box2dSkin (older: true),
// joints' break limits. 5: bodies and shapes taken out of the simulation (World::setEnabled); a
// chain's loop byte also holds its solid side and whether ghost vertices follow (bits 2, 4, 8: 0 in
// older files, whose chains were solid on the left).
constexpr uint32_t formatVersion = 6;

constexpr auto fields(const Rot*) { return std::tuple{field("c", &Rot::c), field("s", &Rot::s)}; }
constexpr auto fields(const Transform*) { return std::tuple{field("p", &Transform::p), field("q", &Transform::q)}; }
constexpr auto fields(const Softness*) {
    return std::tuple{field("biasRate", &Softness::biasRate), field("massScale", &Softness::massScale),
                      field("impulseScale", &Softness::impulseScale)};
}

}  // namespace perpdot
