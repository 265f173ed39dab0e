// perpdot crosscheck SCENE|FILE [--steps N] [--tolerance METRES] [--angle-tolerance RAD] [--report DIR]
//                    [--box2d-skin]
// Runs the scene in perpdot and in Box2D's b2World in lockstep; exit 0 within tolerance, 1 diverged.
#include <cstdio>

#include "cli/commands.hpp"
#include "cli/flags.hpp"
#include "cli/metrics_table.hpp"
#include "perpdot/crosscheck.hpp"
#include "perpdot/scene.hpp"

namespace perpdot::cli {
namespace {

void printAggregates(const crosscheck::Report& r) {
    const size_t last = r.perpdot.kineticEnergy.size() - 1;
    std::printf("%-8s %14s %14s %14s %22s %14s %9s\n", "at end", "kinetic J", "potential J", "total J", "momentum kg m/s",
                "ang. mom.", "contacts");
    for (const crosscheck::Engine engine : {crosscheck::Engine::Perpdot, crosscheck::Engine::Box2D}) {
        const crosscheck::EngineSeries* s = engine == crosscheck::Engine::Perpdot ? &r.perpdot : &r.box2d;
        const char* name = crosscheck::engineName(engine);
        std::printf("%-8s %14.6g %14.6g %14.6g %10.4g,%-11.4g %14.6g %9d\n", name, double(s->kineticEnergy[last]),
                    double(s->potentialEnergy[last]), double(s->kineticEnergy[last] + s->potentialEnergy[last]),
                    double(s->linearMomentum[last].x), double(s->linearMomentum[last].y), double(s->angularMomentum[last]),
                    s->contactCount[last]);
    }
}

}  // namespace

int crosscheckCommand(Args args) {
    const Flags flags(args, {"--steps", "--tolerance", "--angle-tolerance", "--report"}, {"--box2d-skin"});
    if (flags.positional().size() != 1) throw UsageError{"expected one scene name or file"};
    Scene scene = findScene(flags.positional()[0]);
    if (flags.has("--box2d-skin")) scene.solver.box2dSkin = true;  // like-for-like rest heights
    crosscheck::Options options;
    options.steps = flags.integer("--steps", -1, 0);
    options.tolerance = flags.number("--tolerance", options.tolerance, 0.0f);
    options.angleTolerance = flags.number("--angle-tolerance", options.angleTolerance, 0.0f);
    const auto reportDir = flags.text("--report");
    options.recordTrajectories = reportDir.has_value();

    const crosscheck::Report report = crosscheck::run(scene, options);
    std::printf("crosscheck %s: %d steps of %.6g s, %zu moving bodies, perpdot vs Box2D 2.4 (%d/%d iterations)\n",
                report.scene.c_str(), report.steps, double(report.timestep), report.bodies.size(),
                scene.solver.velocityIterations, scene.solver.positionIterations);
    printMetrics(stdout, report.bodies);
    if (!report.bodies.empty()) printAggregates(report);
    if (reportDir) {
        const crosscheck::ReportFiles files = crosscheck::writeReport(report, *reportDir);
        for (const std::string& path : files.written) std::printf("wrote %s\n", path.c_str());
        if (!files.plotProblem.empty()) std::fprintf(stderr, "perpdot crosscheck: %s\n", files.plotProblem.c_str());
    }
    return printVerdict(stdout, report.bodies, options, report.timestep);
}

}  // namespace perpdot::cli
