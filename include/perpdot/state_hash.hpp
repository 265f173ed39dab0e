/// @file
/// A fingerprint of a world's state, for pinning trajectories in regression tests.
#pragma once

#include <cstdint>

#include "perpdot/world.hpp"

namespace perpdot {

/// 64-bit FNV-1a over the raw bits of every live body's position (x, y), angle, linear velocity
/// (x, y) and angular velocity, in body creation order. Equal hashes mean bit-identical states.
uint64_t stateHash(const World& world);

}  // namespace perpdot
