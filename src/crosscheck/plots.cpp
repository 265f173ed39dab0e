// series.csv (per-frame aggregates both engines) + a gnuplot script for two PNGs:
// position error over time (worst bodies and the maximum over all bodies, log scale, with the
// tolerance drawn in) and, for each engine, total and kinetic energy over time in two panels.
#include "crosscheck/plots.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <numeric>

#include "perpdot/error.hpp"

extern char** environ;

namespace perpdot::crosscheck {
namespace {

constexpr size_t worstShown = 4;

// A body name inside a single-quoted gnuplot string.
std::string quoted(std::string name) {
    std::replace(name.begin(), name.end(), '\'', '`');
    return "'" + name + "'";
}

std::vector<size_t> worstBodies(const Report& report) {
    std::vector<size_t> order(report.bodies.size());
    std::iota(order.begin(), order.end(), size_t{0});
    std::stable_sort(order.begin(), order.end(),
                     [&](size_t a, size_t b) { return report.bodies[a].position.max > report.bodies[b].position.max; });
    order.resize(std::min(order.size(), worstShown));
    return order;
}

void writeSeries(const Report& report, const std::vector<size_t>& worst, const std::string& path) {
    std::ofstream out(path);
    if (!out) throw Error(path + ": cannot write");
    out << "step,time,max_position_error";
    for (size_t b : worst) out << ",error_" << report.bodies[b].name;
    out << ",perpdot_kinetic,perpdot_potential,perpdot_total,box2d_kinetic,box2d_potential,box2d_total"
           ",perpdot_contacts,box2d_contacts\n";
    const size_t frames = report.perpdot.kineticEnergy.size();
    for (size_t f = 0; f < frames; ++f) {
        float maxError = 0.0f;
        for (const BodyMetrics& m : report.bodies) maxError = std::max(maxError, m.positionError[f]);
        out << f << ',' << double(f) * double(report.timestep) << ',' << maxError;
        for (size_t b : worst) out << ',' << report.bodies[b].positionError[f];
        for (const EngineSeries* e : {&report.perpdot, &report.box2d}) {
            out << ',' << e->kineticEnergy[f] << ',' << e->potentialEnergy[f] << ',' << e->kineticEnergy[f] + e->potentialEnergy[f];
        }
        out << ',' << report.perpdot.contactCount[f] << ',' << report.box2d.contactCount[f] << '\n';
    }
}

void writeScript(const Report& report, const std::vector<size_t>& worst, const std::string& path) {
    std::ofstream gp(path);
    if (!gp) throw Error(path + ": cannot write");
    const size_t energyColumn = 4 + worst.size();  // first energy column, 1-based
    gp << "set datafile separator ','\n"
          "set terminal pngcairo size 1000,600 enhanced font 'sans,10'\n"
          "set key outside right top\n"
          "set grid\n"
          "set xlabel 'time (s)'\n"
          "clip(e) = e > 1e-9 ? e : 1e-9  # log scale: exact agreement is drawn at 1e-9\n"
          "\n"
          "set output 'position_error.png'\n"
       << "set title " << quoted(report.scene + ": perpdot vs Box2D, position error of the body origins") << "\n"
       << "set ylabel 'position error (m)'\n"
          "set logscale y\n"
       << "set arrow 1 from graph 0, first " << report.options.tolerance << " to graph 1, first "
       << report.options.tolerance << " nohead dashtype 2 linecolor rgb 'red'\n"
       << "plot 'series.csv' using 2:(clip($3)) skip 1 with lines linewidth 2 title 'max over bodies'";
    for (size_t i = 0; i < worst.size(); ++i) {
        gp << ", \\\n     '' using 2:(clip($" << 4 + i << ")) skip 1 with lines title " << quoted(report.bodies[worst[i]].name);
    }
    gp << "\n\nunset arrow 1\nunset logscale y\n"
          "set output 'energy.png'\nunset title\n"
          "set multiplot layout 2,1 title " << quoted(report.scene + ": energy of the dynamic bodies (potential = -m s g . x, s = gravity scale)") << "\n"
       << "set ylabel 'kinetic + potential (J)'\nunset xlabel\n"
       << "plot 'series.csv' using 2:" << energyColumn + 2 << " skip 1 with lines linewidth 2 linecolor rgb '#1f77b4' title 'perpdot', \\\n"
       << "     '' using 2:" << energyColumn + 5 << " skip 1 with lines linewidth 2 dashtype 2 linecolor rgb '#d62728' title 'box2d'\n"
       << "set ylabel 'kinetic (J)'\nset xlabel 'time (s)'\n"
       << "plot 'series.csv' using 2:" << energyColumn << " skip 1 with lines linewidth 2 linecolor rgb '#1f77b4' title 'perpdot', \\\n"
       << "     '' using 2:" << energyColumn + 3 << " skip 1 with lines linewidth 2 dashtype 2 linecolor rgb '#d62728' title 'box2d'\n"
       << "unset multiplot\n";
}

// Runs `gnuplot SCRIPT` with DIR as working directory; "" on success, otherwise why not.
std::string runGnuplot(const std::string& directory, const std::string& script) {
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addchdir_np(&actions, directory.c_str());
    posix_spawn_file_actions_addopen(&actions, 1, "gnuplot.log", O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
    std::string program = "gnuplot", file = script;
    char* argv[] = {program.data(), file.data(), nullptr};
    pid_t pid = 0;
    const int error = posix_spawnp(&pid, "gnuplot", &actions, nullptr, argv, environ);
    posix_spawn_file_actions_destroy(&actions);
    if (error == ENOENT) return "gnuplot is not installed (Debian: apt-get install gnuplot-nox); no PNG plots";
    if (error != 0) return std::string("could not start gnuplot: ") + std::strerror(error);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
    if (WIFEXITED(status) && WEXITSTATUS(status) == 127) return "gnuplot is not installed (Debian: apt-get install gnuplot-nox); no PNG plots";
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) return "gnuplot failed, see " + directory + "/gnuplot.log";
    return "";
}

}  // namespace

std::string writePlots(const Report& report, const std::string& directory, std::vector<std::string>& written) {
    const std::vector<size_t> worst = worstBodies(report);
    writeSeries(report, worst, directory + "/series.csv");
    written.push_back(directory + "/series.csv");
    writeScript(report, worst, directory + "/plots.gp");
    written.push_back(directory + "/plots.gp");
    if (report.perpdot.kineticEnergy.empty()) return "no frames to plot";
    std::string problem = runGnuplot(directory, "plots.gp");
    if (problem.empty()) {
        written.push_back(directory + "/position_error.png");
        written.push_back(directory + "/energy.png");
    }
    return problem;
}

}  // namespace perpdot::crosscheck
