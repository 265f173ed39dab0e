// Snapshot sections that live next to the data they save (snapshot.cpp writes the rest).
#pragma once

#include "core/byte_io.hpp"
#include "core/world_impl.hpp"

namespace perpdot {

void writeJoints(ByteWriter& out, const World::Impl& world);
// Reads the joints into `world`, whose bodies are already restored, and checks every link and
// each body's jointCount against them; Error (via `in`) on any inconsistency.
void readJoints(ByteReader& in, World::Impl& world);

}  // namespace perpdot
