// Run files: the magic "PDRUN001", the scene's step count (u32, little-endian), then the bytes of
// World::snapshot(), which carry their own magic, version and checks.
#include "cli/run_snapshot.hpp"

#include <charconv>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <span>

#include "perpdot/error.hpp"

namespace perpdot::cli {

namespace {
constexpr char runMagic[8] = {'P', 'D', 'R', 'U', 'N', '0', '0', '1'};
constexpr size_t headerSize = sizeof(runMagic) + 4;
}  // namespace

std::vector<std::string> takeSaveAt(Args args, std::optional<SaveAt>& saveAt) {
    std::vector<std::string> rest;
    for (size_t i = 0; i < args.size(); ++i) {
        if (args[i] != "--save-at") {
            rest.push_back(args[i]);
            continue;
        }
        if (i + 2 >= args.size()) throw UsageError{"--save-at needs a step and a file"};
        const std::string& text = args[i + 1];
        SaveAt s{.step = -1, .path = args[i + 2]};
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), s.step);
        if (error != std::errc() || end != text.data() + text.size() || s.step < 0)
            throw UsageError{"--save-at expects a step >= 0, got \"" + text + "\""};
        saveAt = s;
        i += 2;
    }
    return rest;
}

void saveRun(const std::string& path, const SceneWorld& built) {
    std::vector<uint8_t> bytes(runMagic, runMagic + sizeof(runMagic));
    for (int k = 0; k < 4; ++k) bytes.push_back(static_cast<uint8_t>(static_cast<uint32_t>(built.stepIndex) >> (8 * k)));
    const std::vector<uint8_t> world = built.world.snapshot();
    bytes.insert(bytes.end(), world.begin(), world.end());
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    if (!out.flush()) throw Error(path + ": cannot write the snapshot");
}

void loadRun(const std::string& path, SceneWorld& built) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(path + ": cannot open");
    const std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (bytes.size() < headerSize || !std::equal(runMagic, runMagic + sizeof(runMagic), bytes.begin()))
        throw Error(path + ": not a perpdot run snapshot");
    uint32_t step = 0;
    for (int k = 0; k < 4; ++k) step |= static_cast<uint32_t>(bytes[sizeof(runMagic) + k]) << (8 * k);
    if (step > static_cast<uint32_t>(built.scene.steps))
        throw Error(path + ": saved at step " + std::to_string(step) + ", after the run's last step " + std::to_string(built.scene.steps));
    try {
        built.world.restore(std::span(bytes).subspan(headerSize));
    } catch (const Error& e) {
        throw Error(path + ": " + e.what());
    }
    for (BodyId body : built.bodies)
        if (!built.world.isValid(body)) throw Error(path + ": the snapshot is not of scene \"" + built.scene.name + "\"");
    built.stepIndex = static_cast<int>(step);
}

}  // namespace perpdot::cli
