// `perpdot list`, `perpdot run` and `perpdot export`: scenes from the command line.
#include <chrono>
#include <cinttypes>
#include <cstdio>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/flags.hpp"
#include "cli/run_snapshot.hpp"
#include "perpdot/crosscheck.hpp"
#include "perpdot/error.hpp"
#include "perpdot/feature_scenes.hpp"
#include "perpdot/scene.hpp"
#include "perpdot/state_hash.hpp"
#include "scene/scene_limits.hpp"

namespace perpdot::cli {
namespace {

struct RunOptions {
    std::string scene{};
    std::optional<int> steps{};
    std::string csvPath{};
    int every = 1;
    std::optional<SaveAt> saveAt{};
    std::string loadPath{};
    int workers = 1;
};

RunOptions parseRunOptions(Args args) {
    std::optional<SaveAt> saveAt;
    const std::vector<std::string> rest = takeSaveAt(args, saveAt);
    const Flags flags(rest, {"--steps", "--csv", "--every", "--load", "--workers"});
    if (flags.positional().empty()) throw UsageError{"no scene given"};
    if (flags.positional().size() > 1) throw UsageError{"more than one scene given"};
    RunOptions options{.scene = flags.positional()[0], .csvPath = flags.text("--csv").value_or("")};
    if (flags.text("--steps")) {
        options.steps = flags.integer("--steps", 0, 0);
        if (*options.steps > maxSceneSteps) throw UsageError{"--steps must be at most " + std::to_string(maxSceneSteps)};
    }
    options.every = flags.integer("--every", 1, 1);
    options.saveAt = saveAt;
    options.loadPath = flags.text("--load").value_or("");
    options.workers = flags.integer("--workers", 1, 1);
    return options;
}

// The trajectory CSV of scene-format.md, streamed: non-static bodies in scene order.
class TrajectoryWriter {
public:
    TrajectoryWriter(const std::string& path, const SceneWorld& built) : path_(path), file_(path) {
        if (!file_) throw Error(path + ": cannot open for writing");
        for (size_t i = 0; i < built.bodies.size(); ++i)
            if (built.scene.bodies[i].type != BodyType::Static) recorded_.push_back({built.bodies[i], built.scene.bodies[i].name});
        crosscheck::writeCsvHeader(file_, false);
    }

    void write(const SceneWorld& built, int step) {
        const World& w = built.world;
        for (const auto& [body, name] : recorded_)
            crosscheck::writeCsvRow(file_, step, built.scene.timestep, name,
                                    {w.position(body), w.angle(body), w.linearVelocity(body), w.angularVelocity(body)});
    }

    void close() {
        file_.close();
        if (!file_) throw Error(path_ + ": write failed");
    }

private:
    struct Recorded {
        BodyId body;
        std::string name;
    };
    std::string path_;
    std::ofstream file_;
    std::vector<Recorded> recorded_;
};

}  // namespace

int listCommand(Args args) {
    if (!args.empty()) throw UsageError{"list takes no arguments"};
    for (const BuiltinScene& scene : builtinScenes()) std::printf("%-16s %s\n", scene.name.c_str(), scene.description.c_str());
    return 0;
}

int runCommand(Args args) {
    const RunOptions options = parseRunOptions(args);
    Scene scene = findScene(options.scene);
    if (options.steps) scene.steps = *options.steps;
    SceneWorld built = buildWorldWithBehaviour(scene, options.workers);
    if (!options.loadPath.empty()) loadRun(options.loadPath, built);  // continue from its step
    const int first = built.stepIndex + 1;
    if (options.saveAt && (options.saveAt->step < built.stepIndex || options.saveAt->step > scene.steps))
        throw UsageError{"--save-at must be a step in [" + std::to_string(built.stepIndex) + ", " + std::to_string(scene.steps) + "]"};
    const auto saveIfDue = [&] {
        if (options.saveAt && built.stepIndex == options.saveAt->step) saveRun(options.saveAt->path, built);
    };
    saveIfDue();

    std::optional<TrajectoryWriter> csv;
    if (!options.csvPath.empty()) {
        csv.emplace(options.csvPath, built);
        csv->write(built, built.stepIndex);
    }
    using Clock = std::chrono::steady_clock;
    Clock::duration stepping{};
    for (int step = first; step <= scene.steps; ++step) {
        const auto start = Clock::now();
        built.step();
        stepping += Clock::now() - start;  // time the physics only, not the CSV
        saveIfDue();
        if (csv && step % options.every == 0) csv->write(built, step);
    }
    if (csv) csv->close();

    const double ms = std::chrono::duration<double, std::milli>(stepping).count();
    std::printf("scene=%s steps=%d bodies=%zu ms_per_step=%.3f state_hash=%016" PRIx64 "\n", scene.name.c_str(),
                scene.steps, built.bodies.size(), scene.steps >= first ? ms / (scene.steps - first + 1) : 0.0, stateHash(built.world));
    return 0;
}

int exportCommand(Args args) {
    if (args.size() != 2) throw UsageError{"expected a scene and an output file"};
    const Scene scene = findScene(args[0]);
    saveScene(scene, args[1]);
    std::printf("wrote %s (%zu bodies) to %s\n", scene.name.c_str(), scene.bodies.size(), args[1].c_str());
    return 0;
}

}  // namespace perpdot::cli
