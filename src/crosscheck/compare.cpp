// The cross-check proper: record, compare frame by frame, and sum each engine's energy and momenta.
#include <cmath>
#include <limits>

#include "crosscheck/stepper.hpp"
#include "perpdot/crosscheck.hpp"
#include "perpdot/error.hpp"

namespace perpdot::crosscheck {
namespace {

int stepsOf(const Scene& scene, int steps) {
    if (steps < 0) steps = scene.steps;
    if (steps < 0) throw Error("steps: must not be negative");
    return steps;
}

void appendStates(Trajectory& t, const std::vector<BodySample>& samples) {
    for (const BodySample& s : samples) t.states.push_back(s.state);
}

// Energy and momenta of one frame over the dynamic bodies (kinematic ones have mass 0 here):
// T = Σ ½ m v² + ½ I ω², V = Σ -m s g·x_cm, p = Σ m v, L = Σ m perpDot(x_cm, v) + I ω.
void appendAggregates(EngineSeries& series, const std::vector<BodySample>& samples, Vec2 gravity, int contacts) {
    float kinetic = 0.0f, potential = 0.0f, angular = 0.0f;
    Vec2 momentum;
    for (const BodySample& s : samples) {
        const Vec2 v = s.state.linearVelocity;
        const float omega = s.state.angularVelocity;
        kinetic += 0.5f * s.mass * dot(v, v) + 0.5f * s.inertia * omega * omega;
        potential -= s.mass * s.gravityScale * dot(gravity, s.center);
        momentum += s.mass * v;
        angular += s.mass * perpDot(s.center, v) + s.inertia * omega;
    }
    series.kineticEnergy.push_back(kinetic);
    series.potentialEnergy.push_back(potential);
    series.linearMomentum.push_back(momentum);
    series.angularMomentum.push_back(angular);
    series.contactCount.push_back(contacts);
}

void setMassProperties(EngineSeries& series, const std::vector<BodySample>& samples) {
    for (const BodySample& s : samples) {
        series.mass.push_back(s.mass);
        series.rotationalInertia.push_back(s.inertia);
    }
}

// Accumulates one error over frames; a non-finite error (a blown-up body) counts as infinite.
struct ErrorAccumulator {
    ErrorStats stats;
    double sumSquares = 0.0;
    int frames = 0;

    float add(float error, int frame) {
        if (!std::isfinite(error)) error = std::numeric_limits<float>::infinity();
        if (error > stats.max || frame == 0) stats.max = error, stats.maxStep = frame;
        sumSquares += double(error) * double(error);
        ++frames;
        return error;
    }
    ErrorStats finish() {
        stats.rms = frames ? float(std::sqrt(sumSquares / frames)) : 0.0f;
        return stats;
    }
};

}  // namespace

Trajectory record(const Scene& scene, Engine engine, int steps) {
    steps = stepsOf(scene, steps);
    const auto stepper = makeStepper(engine, scene);
    Trajectory t{.timestep = scene.timestep, .bodies = movingBodyNames(scene), .states = {}};
    t.states.reserve(t.bodies.size() * size_t(steps + 1));
    std::vector<BodySample> samples;
    for (int frame = 0;; ++frame) {
        stepper->sample(samples);
        appendStates(t, samples);
        if (frame == steps) break;
        stepper->step();
    }
    return t;
}

std::vector<BodyMetrics> compare(const Trajectory& a, const Trajectory& b, const Options& options) {
    if (a.bodies != b.bodies) throw Error("trajectories do not list the same bodies in the same order");
    if (a.frameCount() != b.frameCount()) {
        throw Error("trajectories differ in length: " + std::to_string(a.frameCount()) + " vs " +
                    std::to_string(b.frameCount()) + " frames");
    }
    if (std::abs(a.timestep - b.timestep) > 1.0e-6f * std::abs(b.timestep)) {
        throw Error("trajectories differ in time step: " + std::to_string(a.timestep) + " vs " + std::to_string(b.timestep));
    }
    std::vector<BodyMetrics> metrics;
    for (size_t body = 0; body < a.bodies.size(); ++body) {
        BodyMetrics m;
        m.name = a.bodies[body];
        ErrorAccumulator position, angle, velocity, angularVelocity;
        for (int frame = 0; frame < a.frameCount(); ++frame) {
            const BodyState& sa = a.at(frame, int(body));
            const BodyState& sb = b.at(frame, int(body));
            const float dx = position.add(distance(sa.position, sb.position), frame);
            const float dtheta = angle.add(std::abs(sa.angle - sb.angle), frame);
            velocity.add(distance(sa.linearVelocity, sb.linearVelocity), frame);
            angularVelocity.add(std::abs(sa.angularVelocity - sb.angularVelocity), frame);
            m.positionError.push_back(dx);
            if (m.divergenceStep < 0 && (dx > options.tolerance || dtheta > options.angleTolerance)) {
                m.divergenceStep = frame;
            }
        }
        m.position = position.finish();
        m.angle = angle.finish();
        m.velocity = velocity.finish();
        m.angularVelocity = angularVelocity.finish();
        metrics.push_back(std::move(m));
    }
    return metrics;
}

int firstDiverged(const std::vector<BodyMetrics>& bodies) {
    int first = -1;
    for (size_t i = 0; i < bodies.size(); ++i) {
        const int step = bodies[i].divergenceStep;
        if (step >= 0 && (first < 0 || step < bodies[size_t(first)].divergenceStep)) first = int(i);
    }
    return first;
}

Report run(const Scene& scene, const Options& options) {
    Report report;
    report.scene = scene.name;
    report.timestep = scene.timestep;
    report.steps = stepsOf(scene, options.steps);
    report.options = options;
    const auto perpdot = makeStepper(Engine::Perpdot, scene);
    const auto box2d = makeStepper(Engine::Box2D, scene);
    Trajectory pt{.timestep = scene.timestep, .bodies = movingBodyNames(scene), .states = {}};
    Trajectory bt = pt;
    std::vector<BodySample> ps, bs;
    for (int frame = 0;; ++frame) {
        perpdot->sample(ps);
        box2d->sample(bs);
        if (frame == 0) setMassProperties(report.perpdot, ps), setMassProperties(report.box2d, bs);
        appendStates(pt, ps);
        appendStates(bt, bs);
        appendAggregates(report.perpdot, ps, scene.gravity, perpdot->contactCount());
        appendAggregates(report.box2d, bs, scene.gravity, box2d->contactCount());
        if (frame == report.steps) break;
        perpdot->step();
        box2d->step();
    }
    report.bodies = compare(pt, bt, options);
    if (const int first = firstDiverged(report.bodies); first >= 0) {
        report.divergenceStep = report.bodies[size_t(first)].divergenceStep;
        report.divergedBody = report.bodies[size_t(first)].name;
    }
    if (options.recordTrajectories) {
        report.perpdotTrajectory = std::move(pt);
        report.box2dTrajectory = std::move(bt);
    }
    return report;
}

}  // namespace perpdot::crosscheck
