// libFuzzer harness for the scene loader: any bytes through parseScene, buildWorld and a few
// steps. Bad input must end in perpdot::Error; anything else escaping, or a sanitizer report, is a bug.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "perpdot/error.hpp"
#include "perpdot/scene.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    try {
        perpdot::SceneWorld built = perpdot::buildWorld(perpdot::parseScene({reinterpret_cast<const char*>(data), size}));
        for (int i = 0; i < 8; ++i) built.step();
    } catch (const perpdot::Error&) {
    }
    return 0;
}
