// libFuzzer harness for the snapshot loader: any bytes through World::restore. Corrupt bytes must
// end in perpdot::Error; a snapshot that loads must step, and must save back to the same bytes
// (restore and snapshot are inverses; an older format version saves as the current one, which then
// round-trips, also restored into a world that held another state), else the harness aborts.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <vector>

#include "perpdot/error.hpp"
#include "perpdot/world.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    perpdot::World world;
    try {
        world.restore(std::span(data, size));
    } catch (const perpdot::Error&) {
        return 0;
    }
    const std::vector<uint8_t> saved = world.snapshot();
    const bool sameVersion = std::equal(saved.begin() + 8, saved.begin() + 12, data + 8);
    if (sameVersion && saved != std::vector<uint8_t>(data, data + size)) std::abort();
    if (!sameVersion) {
        perpdot::World current;
        current.restore(saved);
        if (current.snapshot() != saved) std::abort();
    }
    for (int i = 0; i < 4; ++i) world.step(1.0f / 60.0f);
    world.restore(world.snapshot());
    // Restored again, into the slots the stepped state leaves behind (a restore reads into the
    // memory of the state it replaced): nothing of that state may remain.
    world.restore(saved);
    if (world.snapshot() != saved) std::abort();
    return 0;
}
