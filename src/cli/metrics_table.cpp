#include "cli/metrics_table.hpp"

#include <algorithm>
#include <numeric>

namespace perpdot::cli {

using crosscheck::BodyMetrics;

void printMetrics(std::FILE* out, const std::vector<BodyMetrics>& bodies, size_t maxRows) {
    std::vector<size_t> order(bodies.size());
    std::iota(order.begin(), order.end(), size_t{0});
    auto divergence = [&](size_t i) { return bodies[i].divergenceStep < 0 ? 1 << 30 : bodies[i].divergenceStep; };
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
        if (divergence(a) != divergence(b)) return divergence(a) < divergence(b);
        return bodies[a].position.max > bodies[b].position.max;
    });
    std::fprintf(out, "%-16s %12s %12s %8s %12s %12s %12s %11s\n", "body", "max |dx| m", "rms |dx| m", "at step",
                 "max |da| rad", "max |dv| m/s", "max |dw| r/s", "diverged at");
    for (size_t row = 0; row < order.size() && row < maxRows; ++row) {
        const BodyMetrics& m = bodies[order[row]];
        char diverged[16] = "-";
        if (m.divergenceStep >= 0) std::snprintf(diverged, sizeof diverged, "%d", m.divergenceStep);
        std::fprintf(out, "%-16s %12.3e %12.3e %8d %12.3e %12.3e %12.3e %11s\n", m.name.c_str(), double(m.position.max),
                     double(m.position.rms), m.position.maxStep, double(m.angle.max), double(m.velocity.max),
                     double(m.angularVelocity.max), diverged);
    }
    if (order.size() > maxRows) std::fprintf(out, "... and %zu more bodies\n", order.size() - maxRows);
}

int printVerdict(std::FILE* out, const std::vector<BodyMetrics>& bodies, const crosscheck::Options& options, float timestep) {
    const int first = crosscheck::firstDiverged(bodies);
    if (first < 0) {
        float worst = 0.0f;
        for (const BodyMetrics& m : bodies) worst = std::max(worst, m.position.max);
        std::fprintf(out, "verdict: within tolerance (%.3g m, %.3g rad): max position error %.3e m\n",
                     double(options.tolerance), double(options.angleTolerance), double(worst));
        return 0;
    }
    const BodyMetrics& m = bodies[size_t(first)];
    std::fprintf(out, "verdict: DIVERGED at step %d (t = %.3f s): body '%s' beyond %.3g m or %.3g rad\n", m.divergenceStep,
                 double(float(m.divergenceStep) * timestep), m.name.c_str(), double(options.tolerance),
                 double(options.angleTolerance));
    return 1;
}

}  // namespace perpdot::cli
