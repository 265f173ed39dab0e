// `perpdot bench`: the same scene timed in perpdot and in Box2D, median of a few repeats.
// Building a world is not timed; the engines take turns going first so neither always runs on
// a cold cache or a warmed-up CPU clock.
#include <algorithm>
#include <chrono>

#include "crosscheck/stepper.hpp"
#include "perpdot/crosscheck.hpp"
#include "perpdot/error.hpp"

namespace perpdot::crosscheck {
namespace {

// Index among the scene's non-static bodies of the dynamic body that starts highest; -1: none.
int topBody(const Scene& scene) {
    int top = -1, moving = 0;
    float topY = 0.0f;
    for (const SceneBody& b : scene.bodies) {
        if (b.type == BodyType::Static) continue;
        if (b.type == BodyType::Dynamic && (top < 0 || b.position.y > topY)) top = moving, topY = b.position.y;
        ++moving;
    }
    return top;
}

struct Run {
    double msPerStep;
    int contacts;
    float topDrop;
};

Run timeOnce(Engine engine, const Scene& scene, int steps, int top) {
    const auto stepper = makeStepper(engine, scene);
    std::vector<BodySample> samples;
    stepper->sample(samples);
    const float y0 = top >= 0 ? samples[size_t(top)].state.position.y : 0.0f;

    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < steps; ++i) stepper->step();
    const auto stop = std::chrono::steady_clock::now();

    stepper->sample(samples);
    const double ms = std::chrono::duration<double, std::milli>(stop - start).count();
    return {steps > 0 ? ms / steps : 0.0, stepper->contactCount(), top >= 0 ? y0 - samples[size_t(top)].state.position.y : 0.0f};
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const size_t n = values.size();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

}  // namespace

Timing time(const Scene& scene, const TimingOptions& options) {
    if (options.repeats < 1) throw Error("repeats: must be at least 1");
    const int steps = options.steps < 0 ? scene.steps : options.steps;
    const int top = topBody(scene);
    Timing timing{.scene = scene.name, .bodies = int(movingBodyNames(scene).size()), .steps = steps, .perpdot = {}, .box2d = {}};
    std::vector<double> perpdotMs, box2dMs;
    for (int r = 0; r < options.repeats; ++r) {
        const bool perpdotFirst = r % 2 == 0;
        for (const Engine engine : {perpdotFirst ? Engine::Perpdot : Engine::Box2D, perpdotFirst ? Engine::Box2D : Engine::Perpdot}) {
            const Run run = timeOnce(engine, scene, steps, top);
            EngineTiming& out = engine == Engine::Perpdot ? timing.perpdot : timing.box2d;
            (engine == Engine::Perpdot ? perpdotMs : box2dMs).push_back(run.msPerStep);
            out.contacts = run.contacts;
            out.topDrop = run.topDrop;
        }
    }
    timing.perpdot.msPerStep = median(perpdotMs);
    timing.box2d.msPerStep = median(box2dMs);
    return timing;
}

}  // namespace perpdot::crosscheck
