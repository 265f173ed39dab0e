// Pinned ("golden") trajectories:
//   perpdot record SCENE --out FILE.csv [--engine perpdot|box2d] [--steps N]
//   perpdot compare SCENE --against FILE.csv [--tolerance M] [--angle-tolerance RAD]
// compare re-runs perpdot for as many steps as the file holds: exit 0 within tolerance,
// 1 diverged, 2 when the file is malformed or does not belong to the scene.
#include <cstdio>
#include <fstream>

#include "cli/commands.hpp"
#include "cli/flags.hpp"
#include "cli/metrics_table.hpp"
#include "perpdot/crosscheck.hpp"
#include "perpdot/error.hpp"
#include "perpdot/scene.hpp"

namespace perpdot::cli {

int recordCommand(Args args) {
    const Flags flags(args, {"--out", "--engine", "--steps"});
    if (flags.positional().size() != 1) throw UsageError{"expected one scene name or file"};
    const auto path = flags.text("--out");
    if (!path) throw UsageError{"--out FILE.csv is required"};
    const crosscheck::Engine engine = parseEngine(flags.text("--engine").value_or("perpdot"));
    const Scene scene = findScene(flags.positional()[0]);
    const crosscheck::Trajectory t = crosscheck::record(scene, engine, flags.integer("--steps", -1, 0));
    std::ofstream out(*path);
    if (!out) throw Error(*path + ": cannot write");
    crosscheck::writeCsv(out, t);
    out.close();
    if (!out) throw Error(*path + ": write failed");
    std::printf("recorded %d steps of %s (%s, %zu bodies) to %s\n", t.frameCount() - 1, scene.name.c_str(),
                crosscheck::engineName(engine), t.bodies.size(), path->c_str());
    return 0;
}

int compareCommand(Args args) {
    const Flags flags(args, {"--against", "--tolerance", "--angle-tolerance"});
    if (flags.positional().size() != 1) throw UsageError{"expected one scene name or file"};
    const auto path = flags.text("--against");
    if (!path) throw UsageError{"--against FILE.csv is required"};
    crosscheck::Options options;
    options.tolerance = flags.number("--tolerance", 1.0e-4f, 0.0f);
    options.angleTolerance = flags.number("--angle-tolerance", options.tolerance, 0.0f);
    const Scene scene = findScene(flags.positional()[0]);

    std::ifstream in(*path);
    if (!in) throw Error(*path + ": cannot open");
    crosscheck::Trajectory golden;
    try {
        golden = crosscheck::readCsv(in);
    } catch (const Error& e) {
        throw Error(*path + ": " + e.what());
    }
    if (golden.frameCount() < 2) throw Error(*path + ": holds no step after step 0");

    const crosscheck::Trajectory now = crosscheck::record(scene, crosscheck::Engine::Perpdot, golden.frameCount() - 1);
    std::vector<crosscheck::BodyMetrics> metrics;
    try {
        metrics = crosscheck::compare(now, golden, options);
    } catch (const Error& e) {
        throw Error(*path + " does not belong to scene '" + scene.name + "': " + e.what());
    }
    std::printf("compare %s: %d steps against %s\n", scene.name.c_str(), golden.frameCount() - 1, path->c_str());
    printMetrics(stdout, metrics);
    return printVerdict(stdout, metrics, options, scene.timestep);
}

}  // namespace perpdot::cli
