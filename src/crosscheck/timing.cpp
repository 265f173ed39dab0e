// `perpdot bench`: the same scene timed in perpdot and in Box2D, median of a few repeats, with
// each engine's stability figure (stability.hpp). Building a world is not timed; the engines take
// turns going first so neither always runs on a cold cache or a warmed-up CPU clock.
#include <algorithm>
#include <chrono>

#include "crosscheck/stability.hpp"
#include "crosscheck/stepper.hpp"
#include "perpdot/crosscheck.hpp"
#include "perpdot/error.hpp"

namespace perpdot::crosscheck {
namespace {

struct Run {
    double msPerStep;
    int contacts;
    int bodies;
    float stability;
};

Run timeOnce(Engine engine, const Scene& scene, int steps, int workerCount, const StabilityProbe& probe) {
    const auto stepper = makeStepper(engine, scene, makeSceneScript(scene.name), workerCount);
    std::vector<BodySample> first, last;
    stepper->sampleAll(first);

    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < steps; ++i) stepper->step();
    const auto stop = std::chrono::steady_clock::now();

    stepper->sampleAll(last);
    const double ms = std::chrono::duration<double, std::milli>(stop - start).count();
    return {steps > 0 ? ms / steps : 0.0, stepper->contactCount(), int(last.size()), probe.measure(first, last)};
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const size_t n = values.size();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

}  // namespace

Timing time(const Scene& scene, const TimingOptions& options) {
    if (options.repeats < 1) throw Error("repeats: must be at least 1");
    if (!options.perpdot && !options.box2d) throw Error("engines: at least one must run");
    const int steps = options.steps < 0 ? scene.steps : options.steps;
    const StabilityProbe probe(scene);
    Timing timing{.scene = scene.name, .bodies = 0, .steps = steps, .perpdot = {}, .box2d = {},
                  .stabilityLabel = probe.label(), .stabilityUnit = probe.unit()};
    std::vector<double> perpdotMs, box2dMs;
    for (int r = 0; r < options.repeats; ++r) {
        const bool perpdotFirst = r % 2 == 0;
        for (const Engine engine : {perpdotFirst ? Engine::Perpdot : Engine::Box2D, perpdotFirst ? Engine::Box2D : Engine::Perpdot}) {
            if (!(engine == Engine::Perpdot ? options.perpdot : options.box2d)) continue;
            const Run run = timeOnce(engine, scene, steps, options.workers, probe);
            EngineTiming& out = engine == Engine::Perpdot ? timing.perpdot : timing.box2d;
            (engine == Engine::Perpdot ? perpdotMs : box2dMs).push_back(run.msPerStep);
            out.contacts = run.contacts;
            out.stability = run.stability;
            if (engine == Engine::Perpdot || !options.perpdot) timing.bodies = run.bodies;
        }
    }
    if (options.perpdot) timing.perpdot.msPerStep = median(perpdotMs);
    if (options.box2d) timing.box2d.msPerStep = median(box2dMs);
    return timing;
}

}  // namespace perpdot::crosscheck
