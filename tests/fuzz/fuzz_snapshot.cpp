// libFuzzer harness for the snapshot loader: any bytes through World::restore. Corrupt bytes must
// end in perpdot::Error; a snapshot that loads must step, and restore and snapshot must be
// inverses: a current-format input saves back to the same bytes, and an older-format input saves
// as a current-format snapshot that saves back to itself. Anything else aborts the harness.
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
    // The format version is the u32 after the 8-byte magic; the input loaded, so both have it.
    constexpr size_t versionAt = 8;
    if (std::equal(data + versionAt, data + versionAt + 4, saved.begin() + versionAt)) {
        if (saved != std::vector<uint8_t>(data, data + size)) std::abort();
    } else {
        perpdot::World reloaded;
        reloaded.restore(saved);
        if (reloaded.snapshot() != saved) std::abort();
    }
    for (int i = 0; i < 4; ++i) world.step(1.0f / 60.0f);
    world.restore(world.snapshot());
    return 0;
}
