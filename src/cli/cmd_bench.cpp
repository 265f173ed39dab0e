// perpdot bench [SCENE…] [--steps N] [--repeat R] [--engine perpdot|box2d] [--workers N]
// The same scenes timed in perpdot and in Box2D 2.4 (the scene's iterations, 8/3 by default;
// sleeping as the scene says), median of R repeats, with each engine's end state beside it:
// touching contacts and the scene's stability figure (crosscheck/stability.hpp).
// Without SCENE: pyramid and large_pyramid, a run of seconds; the seven benchmark scenes take
// minutes and are named explicitly (docs/crosscheck.md). --engine times one engine alone (its
// stability over a whole scene where the other is too slow); the other's columns show "-".
// --workers N steps perpdot on N threads (WorldDef::workerCount); Box2D 2.4 has one.
#include <cstdio>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/flags.hpp"
#include "perpdot/crosscheck.hpp"
#include "perpdot/scene.hpp"

namespace perpdot::cli {

int benchCommand(Args args) {
    const Flags flags(args, {"--steps", "--repeat", "--engine", "--workers"});
    std::vector<std::string> names = flags.positional();
    if (names.empty()) names = {"pyramid", "large_pyramid"};
    crosscheck::TimingOptions options;
    options.steps = flags.integer("--steps", -1, 1);
    options.repeats = flags.integer("--repeat", 3, 1);
    options.workers = flags.integer("--workers", 1, 1);
    if (const auto only = flags.text("--engine")) {
        const crosscheck::Engine engine = parseEngine(*only);
        options.perpdot = engine == crosscheck::Engine::Perpdot;
        options.box2d = engine == crosscheck::Engine::Box2D;
    }

    std::vector<Scene> scenes;
    for (const std::string& name : names) scenes.push_back(findScene(name));  // bad names fail before any timing

    std::printf("%-16s %6s %6s %12s %12s %7s %18s  %s\n", "scene", "bodies", "steps", "perpdot ms", "box2d ms", "ratio",
                "contacts p / b2", "stability p / b2");
    // One engine's column, or "-" when it did not run.
    const auto column = [](bool ran, const char* format, auto value) {
        char text[32] = "-";
        if (ran) std::snprintf(text, sizeof text, format, value);
        return std::string(text);
    };
    for (const Scene& scene : scenes) {
        const crosscheck::Timing t = crosscheck::time(scene, options);
        const bool both = options.perpdot && options.box2d && t.box2d.msPerStep > 0.0;
        const std::string ratio = column(both, "%.2fx", both ? t.perpdot.msPerStep / t.box2d.msPerStep : 0.0);
        const std::string contacts = column(options.perpdot, "%d", t.perpdot.contacts) + " / " +
                                     column(options.box2d, "%d", t.box2d.contacts);
        const std::string stability = column(options.perpdot, "%.4g", double(t.perpdot.stability)) + " / " +
                                      column(options.box2d, "%.4g", double(t.box2d.stability));
        std::printf("%-16s %6d %6d %12s %12s %7s %18s  %s: %s %s\n", t.scene.c_str(), t.bodies, t.steps,
                    column(options.perpdot, "%.4f", t.perpdot.msPerStep).c_str(),
                    column(options.box2d, "%.4f", t.box2d.msPerStep).c_str(), ratio.c_str(), contacts.c_str(),
                    t.stabilityLabel.c_str(), stability.c_str(), t.stabilityUnit.c_str());
        std::fflush(stdout);
    }
    std::printf("ms = milliseconds per step, median of %d repeat(s), perpdot on %d worker(s); ratio = perpdot / box2d "
                "(below 1x: perpdot faster)\n",
                options.repeats, options.workers);
    return 0;
}

}  // namespace perpdot::cli
