// A cross-check Report on disk: report.json (every metric and per-frame series), the two
// trajectories in one CSV with an `engine` column, and the gnuplot plots.
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "crosscheck/plots.hpp"
#include "perpdot/crosscheck.hpp"
#include "perpdot/error.hpp"

namespace perpdot::crosscheck {
namespace {

using nlohmann::json;

json toJson(const ErrorStats& e) { return {{"max", e.max}, {"rms", e.rms}, {"max_step", e.maxStep}}; }

json toJson(const EngineSeries& s) {
    json momentum = json::array();
    for (Vec2 p : s.linearMomentum) momentum.push_back({p.x, p.y});
    return {{"kinetic_energy", s.kineticEnergy}, {"potential_energy", s.potentialEnergy},
            {"linear_momentum", momentum},       {"angular_momentum", s.angularMomentum},
            {"contact_count", s.contactCount}};
}

json toJson(const Report& r) {
    json bodies = json::array();
    for (size_t i = 0; i < r.bodies.size(); ++i) {
        const BodyMetrics& m = r.bodies[i];
        bodies.push_back({{"name", m.name},
                          {"divergence_step", m.divergenceStep},
                          {"position_error", toJson(m.position)},
                          {"angle_error", toJson(m.angle)},
                          {"velocity_error", toJson(m.velocity)},
                          {"angular_velocity_error", toJson(m.angularVelocity)},
                          {"mass", {{"perpdot", r.perpdot.mass[i]}, {"box2d", r.box2d.mass[i]}}},
                          {"rotational_inertia", {{"perpdot", r.perpdot.rotationalInertia[i]}, {"box2d", r.box2d.rotationalInertia[i]}}},
                          {"position_error_series", m.positionError}});
    }
    return {{"scene", r.scene},
            {"timestep", r.timestep},
            {"steps", r.steps},
            {"tolerance", r.options.tolerance},
            {"angle_tolerance", r.options.angleTolerance},
            {"verdict", r.withinTolerance() ? "within tolerance" : "diverged"},
            {"divergence_step", r.divergenceStep},
            {"diverged_body", r.divergedBody},
            {"bodies", bodies},
            {"engines", {{"perpdot", toJson(r.perpdot)}, {"box2d", toJson(r.box2d)}}}};
}

std::ofstream openForWriting(const std::string& path) {
    std::ofstream out(path);
    if (!out) throw Error(path + ": cannot write");
    return out;
}

}  // namespace

ReportFiles writeReport(const Report& report, const std::string& directory) {
    std::error_code ec;
    std::filesystem::create_directories(directory, ec);
    if (ec) throw Error(directory + ": cannot create directory: " + ec.message());
    ReportFiles files;

    const std::string jsonPath = directory + "/report.json";
    openForWriting(jsonPath) << toJson(report).dump(1) << '\n';
    files.written.push_back(jsonPath);

    if (report.perpdotTrajectory.frameCount() > 0) {
        const std::string csvPath = directory + "/trajectories.csv";
        std::ofstream csv = openForWriting(csvPath);
        writeCsv(csv, report.perpdotTrajectory, engineName(Engine::Perpdot));
        std::ostringstream box2d;  // same header once: drop Box2D's header line
        writeCsv(box2d, report.box2dTrajectory, engineName(Engine::Box2D));
        const std::string rows = box2d.str();
        csv << rows.substr(rows.find('\n') + 1);
        files.written.push_back(csvPath);
    }

    files.plotProblem = writePlots(report, directory, files.written);
    return files;
}

}  // namespace perpdot::crosscheck
