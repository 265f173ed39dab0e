// perpdot bench [SCENE…] [--steps N] [--repeat R]
// The same scenes timed in perpdot and in Box2D 2.4 (the scene's iterations, 8/3 by default;
// sleeping as the scene says), median of R repeats, with each engine's end state beside it:
// touching contacts and the scene's stability figure (crosscheck/stability.hpp).
// Without SCENE: pyramid and large_pyramid, a run of seconds; the seven benchmark scenes take
// minutes and are named explicitly (docs/crosscheck.md).
#include <cstdio>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/flags.hpp"
#include "perpdot/crosscheck.hpp"
#include "perpdot/scene.hpp"

namespace perpdot::cli {

int benchCommand(Args args) {
    const Flags flags(args, {"--steps", "--repeat"});
    std::vector<std::string> names = flags.positional();
    if (names.empty()) names = {"pyramid", "large_pyramid"};
    crosscheck::TimingOptions options;
    options.steps = flags.integer("--steps", -1, 1);
    options.repeats = flags.integer("--repeat", 3, 1);

    std::vector<Scene> scenes;
    for (const std::string& name : names) scenes.push_back(findScene(name));  // bad names fail before any timing

    std::printf("%-16s %6s %6s %12s %12s %7s %18s  %s\n", "scene", "bodies", "steps", "perpdot ms", "box2d ms", "ratio",
                "contacts p / b2", "stability p / b2");
    for (const Scene& scene : scenes) {
        const crosscheck::Timing t = crosscheck::time(scene, options);
        const double ratio = t.box2d.msPerStep > 0.0 ? t.perpdot.msPerStep / t.box2d.msPerStep : 0.0;
        char ratioText[16], contacts[32];
        std::snprintf(ratioText, sizeof ratioText, "%.2fx", ratio);
        std::snprintf(contacts, sizeof contacts, "%d / %d", t.perpdot.contacts, t.box2d.contacts);
        std::printf("%-16s %6d %6d %12.4f %12.4f %7s %18s  %s: %.4g / %.4g %s\n", t.scene.c_str(), t.bodies, t.steps,
                    t.perpdot.msPerStep, t.box2d.msPerStep, ratioText, contacts, t.stabilityLabel.c_str(),
                    double(t.perpdot.stability), double(t.box2d.stability), t.stabilityUnit.c_str());
        std::fflush(stdout);
    }
    std::printf("ms = milliseconds per step, median of %d repeat(s); ratio = perpdot / box2d (below 1x: perpdot faster)\n",
                options.repeats);
    return 0;
}

}  // namespace perpdot::cli
