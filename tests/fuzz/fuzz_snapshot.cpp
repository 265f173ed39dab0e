// libFuzzer harness for the snapshot loader: any bytes through World::restore. Corrupt bytes must
// end in perpdot::Error; a snapshot that loads must step, and must save back to the same bytes
// (restore and snapshot are inverses), else the harness aborts.
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
    if (world.snapshot() != std::vector<uint8_t>(data, data + size)) std::abort();
    for (int i = 0; i < 4; ++i) world.step(1.0f / 60.0f);
    world.restore(world.snapshot());
    return 0;
}
