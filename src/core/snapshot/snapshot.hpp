// Snapshot sections that live next to the data they save (snapshot.cpp writes the rest).
#pragma once

#include <cstdint>
#include <vector>

#include "core/bodies/body_store.hpp"
#include "core/joints/joint_store.hpp"
#include "core/snapshot/byte_io.hpp"

namespace perpdot {

// World::snapshot()'s bytes; futureOnly leaves out (as zeros) the contact values that the next
// step recomputes before reading them (compact snapshots, snapshot_compact.cpp).
std::vector<uint8_t> writeSnapshot(const World::Impl& world, bool futureOnly);

void writeJoints(ByteWriter& out, const JointStore& joints, const Pool<Body>& bodies);
// Reads the joints into `joints`, beside `bodies` already restored, and checks every link and
// each body's jointCount against them; Error (via `in`) on any inconsistency.
void readJoints(ByteReader& in, JointStore& joints, const Pool<Body>& bodies);

}  // namespace perpdot
