// libFuzzer harness for the scene loader: any bytes through parseScene, buildWorld and a few
// steps. Bad input must end in perpdot::Error from the loader; step() must never throw (an
// exception escaping it aborts the harness), and a sanitizer report is a bug.
#include <cstddef>
#include <cstdint>
#include <optional>

#include "perpdot/error.hpp"
#include "perpdot/scene.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::optional<perpdot::SceneWorld> built;
    try {
        built.emplace(perpdot::buildWorld(perpdot::parseScene({reinterpret_cast<const char*>(data), size})));
    } catch (const perpdot::Error&) {
        return 0;
    }
    for (int i = 0; i < 8; ++i) built->step();
    return 0;
}
