/// @file
/// Cross-check: run one Scene in perpdot's World and in Box2D 2.4's own b2World, in lockstep,
/// and measure how far they drift apart; record and compare pinned ("golden") trajectories;
/// time both engines side by side. Box2D itself stays behind this header.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "perpdot/math.hpp"
#include "perpdot/scene.hpp"

/// Cross-checks against Box2D 2.4's b2World (the perpdot::crosscheck library).
namespace perpdot::crosscheck {

/// Which engine runs a scene.
enum class Engine { Perpdot, Box2D };
const char* engineName(Engine engine);  ///< "perpdot" or "box2d"

/// One row of the trajectory CSV (scene-format.md): body origin, accumulated angle,
/// velocity of the centre of mass, angular velocity.
struct BodyState {
    Vec2 position{};  ///< body origin, world
    float angle = 0.0f;  ///< accumulated, rad
    Vec2 linearVelocity{};  ///< of the centre of mass
    float angularVelocity = 0.0f;  ///< ω, rad/s
    /// Exact equality of every field.
    friend bool operator==(const BodyState&, const BodyState&) = default;
};

/// States of the scene's non-static bodies, in scene order, at steps 0..frameCount()-1
/// (frame 0 = before the first step).
struct Trajectory {
    float timestep = 1.0f / 60.0f;  ///< s per step
    std::vector<std::string> bodies{};  ///< body names, scene order
    std::vector<BodyState> states{};  ///< frame-major: states[frame * bodies.size() + body]

    /// Frames recorded (steps + 1).
    int frameCount() const { return bodies.empty() ? 0 : int(states.size() / bodies.size()); }
    /// The state of body `body` at frame `frame`.
    const BodyState& at(int frame, int body) const { return states[size_t(frame) * bodies.size() + size_t(body)]; }
};

/// Runs `steps` steps (-1: the scene's) in one engine and records every frame.
Trajectory record(const Scene& scene, Engine engine, int steps = -1);

/// CSV: `step,time,body,x,y,angle,vx,vy,omega`, with a trailing `engine` column when `engine` is given.
void writeCsv(std::ostream& out, const Trajectory& trajectory, const char* engine = nullptr);
/// The pieces writeCsv is made of, for writers that stream (perpdot run --csv). A body name that
/// cannot stand in a CSV field (comma, line break) is a perpdot::Error.
void writeCsvHeader(std::ostream& out, bool engineColumn);
/// One row of the CSV (see writeCsvHeader()).
void writeCsvRow(std::ostream& out, int step, float timestep, const std::string& body, const BodyState& state,
                 const char* engine = nullptr);
/// Reads the CSV written by writeCsv(…, nullptr); perpdot::Error naming the line if it is malformed.
Trajectory readCsv(std::istream& in);

/// How run() compares the engines.
struct Options {
    int steps = -1;                  ///< -1: the scene's own step count
    float tolerance = 1.0e-2f;       ///< metres; a body diverges when its position error exceeds it
    float angleTolerance = 1.0e-2f;  ///< radians; ... or when its angle error exceeds this
    bool recordTrajectories = false; ///< keep both trajectories in the Report
};

/// Max, root-mean-square and the frame of the max, of an error over all frames.
struct ErrorStats {
    float max = 0.0f;  ///< largest error
    float rms = 0.0f;  ///< root mean square over the frames
    int maxStep = 0;  ///< frame of the largest error
};

/// How far one body's two trajectories drift apart.
struct BodyMetrics {
    std::string name{};  ///< the body's scene name
    ErrorStats position{};       ///< |x_a - x_b| of the body origins, metres
    ErrorStats angle{};          ///< |θ_a - θ_b| of the accumulated angles, radians
    ErrorStats velocity{};       ///< |v_a - v_b| of the centre-of-mass velocities, m/s
    ErrorStats angularVelocity{};  ///< |ω_a - ω_b|, rad/s
    int divergenceStep = -1;     ///< first frame beyond a tolerance; -1: never
    std::vector<float> positionError{};  ///< per frame
};

/// Per-frame aggregates of one engine over its dynamic bodies.
struct EngineSeries {
    std::vector<float> kineticEnergy{};  ///< Σ ½ m v² + ½ I ω²
    std::vector<float> potentialEnergy{};  ///< Σ -m s g·x_cm, s = gravity scale
    std::vector<Vec2> linearMomentum{};  ///< Σ m v
    std::vector<float> angularMomentum{};  ///< Σ m perpDot(x_cm, v) + I ω, about the world origin
    std::vector<int> contactCount{};     ///< touching, non-sensor contacts
    std::vector<float> mass{};           ///< per non-static body (scene order), for diagnosis
    std::vector<float> rotationalInertia{};  ///< per non-static body, for diagnosis
};

/// The result of run(): per-body errors, per-engine series, the verdict.
struct Report {
    std::string scene{};  ///< the scene's name
    float timestep = 0.0f;  ///< s per step
    int steps = 0;  ///< steps run
    Options options{};  ///< the options of the run
    std::vector<BodyMetrics> bodies{};  ///< the scene's non-static bodies, in scene order
    EngineSeries perpdot{};           ///< perpdot's series
    EngineSeries box2d{};             ///< Box2D's series
    int divergenceStep = -1;          ///< earliest over the bodies; -1: within tolerance throughout
    std::string divergedBody{};       ///< the body that diverged first
    Trajectory perpdotTrajectory{};   ///< filled when options.recordTrajectories
    Trajectory box2dTrajectory{};     ///< filled when options.recordTrajectories

    /// Whether no body diverged.
    bool withinTolerance() const { return divergenceStep < 0; }
};

/// Steps buildWorld(scene) and the scene's b2World in lockstep and compares them frame by frame.
Report run(const Scene& scene, const Options& options = {});

/// What writeReport() wrote.
struct ReportFiles {
    std::vector<std::string> written{};  ///< paths
    std::string plotProblem{};         ///< empty, or why there are no plots (e.g. gnuplot missing)
};
/// Writes DIR/report.json (every metric and series), DIR/trajectories.csv (both engines, when the
/// report kept its trajectories), DIR/series.csv and, drawn by gnuplot, DIR/position_error.png and
/// DIR/energy.png. Creates DIR. Throws perpdot::Error when a file cannot be written.
ReportFiles writeReport(const Report& report, const std::string& directory);

/// Compares two trajectories of the same bodies (a: measured, b: reference). perpdot::Error when
/// their bodies, frame counts or time steps do not match.
std::vector<BodyMetrics> compare(const Trajectory& a, const Trajectory& b, const Options& options);
/// Earliest divergence over `bodies` (index into it, or -1) — the verdict of run() and compare().
int firstDiverged(const std::vector<BodyMetrics>& bodies);

/// The cross-check as a finding in words, a few lines: where bodies end at rest in both engines,
/// how much lower perpdot rests them and why (Box2D 2.4's polygon skin); how far the trajectories
/// drift apart; and, unless the scene already rests on the skin, the same for the like-for-like
/// run with Scene::solver.box2dSkin. `steps` -1: the scene's.
std::string summarize(const Scene& scene, int steps = -1);

/// Side-by-side timing (`perpdot bench`): each repeat builds both worlds afresh (untimed), then
/// times the steps with a steady clock, alternating which engine goes first.
struct TimingOptions {
    int steps = -1;   ///< -1: the scene's
    int repeats = 3;  ///< the median is reported
    bool perpdot = true;  ///< time perpdot (false: its EngineTiming stays zero)
    bool box2d = true;    ///< time Box2D (false: its EngineTiming stays zero)
    int workers = 1;      ///< perpdot's WorldDef::workerCount (Box2D 2.4 has one thread)
};
/// One engine's timing of one scene.
struct EngineTiming {
    double msPerStep = 0.0;  ///< median over the repeats
    int contacts = 0;        ///< touching contacts after the last step
    float stability = 0.0f;  ///< the scene's stability figure after the last step (Timing::stabilityLabel)
};
/// The result of time(): both engines' timings of one scene.
struct Timing {
    std::string scene{};  ///< the scene's name
    int bodies = 0;  ///< non-static, alive after the last step (a scene's script may spawn and destroy)
    int steps = 0;  ///< steps timed per repeat
    EngineTiming perpdot{};  ///< perpdot's timing
    EngineTiming box2d{};  ///< Box2D's timing
    /// What EngineTiming::stability measures for this scene (docs/crosscheck.md): "top fell" (m),
    /// "escaped" (bodies), "momentum error" (of p0, the initial momentum) or "below floor" (bodies).
    std::string stabilityLabel{};
    std::string stabilityUnit{};  ///< the unit of EngineTiming::stability
};
/// Times the scene in both engines (see TimingOptions).
Timing time(const Scene& scene, const TimingOptions& options = {});

}  // namespace perpdot::crosscheck
