// Snapshot sections that live next to the data they save (snapshot.cpp writes the rest).
#pragma once

#include "core/snapshot/byte_io.hpp"
#include "core/world/world_impl.hpp"

namespace perpdot {

// World::snapshot()'s bytes; futureOnly leaves out (as zeros) the contact values that the next
// step recomputes before reading them (compact snapshots, snapshot_compact.cpp).
std::vector<uint8_t> writeSnapshot(const World::Impl& world, bool futureOnly);

void writeJoints(ByteWriter& out, const World::Impl& world);
// Reads the joints into `world`, whose bodies are already restored, and checks every link and
// each body's jointCount against them; Error (via `in`) on any inconsistency.
void readJoints(ByteReader& in, World::Impl& world);

}  // namespace perpdot
