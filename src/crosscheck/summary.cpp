// The cross-check as a finding in words (the main job's line): where both engines bring bodies to
// rest, how far apart their rest heights are and why; then the like-for-like run, perpdot on
// Box2D's skin, and how far the trajectories drift apart there.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "perpdot/crosscheck.hpp"

namespace perpdot::crosscheck {
namespace {

constexpr float restSpeed = 0.01f;  // m/s: a body slower than this at the end is at rest

std::string format(const char* pattern, double a, double b = 0.0, double c = 0.0) {
    char text[256];
    std::snprintf(text, sizeof text, pattern, a, b, c);
    return text;
}

// Bodies at rest at the end in both engines, and how much lower perpdot rests them than Box2D.
struct RestHeights {
    int bodies = 0;
    float meanLower = 0.0f;  // Box2D's height minus perpdot's, mean
    float maxApart = 0.0f;   // largest |difference|
};

RestHeights restHeights(const Report& r) {
    RestHeights h;
    const int last = r.perpdotTrajectory.frameCount() - 1;
    for (size_t i = 0; i < r.bodies.size(); ++i) {
        const BodyState& p = r.perpdotTrajectory.at(last, int(i));
        const BodyState& b = r.box2dTrajectory.at(last, int(i));
        if (length(p.linearVelocity) > restSpeed || length(b.linearVelocity) > restSpeed) continue;
        ++h.bodies;
        h.meanLower += b.position.y - p.position.y;
        h.maxApart = std::max(h.maxApart, std::fabs(b.position.y - p.position.y));
    }
    if (h.bodies > 0) h.meanLower /= float(h.bodies);
    return h;
}

// The largest position difference on the way, and whether the run stayed within tolerance.
std::string drift(const Report& r) {
    const BodyMetrics* worst = nullptr;
    for (const BodyMetrics& b : r.bodies)
        if (!worst || b.position.max > worst->position.max) worst = &b;
    std::string text = format("trajectories differ by at most %.3g m (", worst->position.max) + worst->name +
                       format(", step %.0f)", worst->position.maxStep);
    if (r.withinTolerance()) return text + format(", within %.3g m / %.3g rad throughout", r.options.tolerance, r.options.angleTolerance);
    return text + format(", more than %.3g m from step %.0f", r.options.tolerance, r.divergenceStep) + " (" + r.divergedBody + ")";
}

}  // namespace

std::string summarize(const Scene& scene, int steps) {
    Options options;
    options.steps = steps;
    options.recordTrajectories = true;
    const Report own = run(scene, options);
    if (own.bodies.empty()) return "crosscheck vs Box2D 2.4: no moving bodies\n";
    std::string text = format("crosscheck vs Box2D 2.4 over %.0f steps, %.0f moving bodies:\n", own.steps, double(own.bodies.size()));
    const RestHeights rest = restHeights(own);
    if (!scene.solver.box2dSkin && rest.bodies > 0)
        text += format("  rest heights: perpdot rests %.0f bodies %.3g m lower on average (at most %.3g m apart): ",
                       rest.bodies, rest.meanLower, rest.maxApart) +
                "Box2D 2.4 rests polygons on a 1 cm skin each, perpdot on their true surfaces\n";
    text += "  " + drift(own) + "\n";
    Report like = own;
    if (!scene.solver.box2dSkin) {
        Scene skinned = scene;
        skinned.solver.box2dSkin = true;
        like = run(skinned, options);
        text += "  like for like (perpdot on Box2D's skin, --box2d-skin): ";
    } else {
        text += "  on Box2D's skin (box2d_skin): ";
    }
    const RestHeights likeRest = restHeights(like);
    if (likeRest.bodies > 0) text += format("rest heights agree within %.3g m (%.0f bodies at rest); ", likeRest.maxApart, likeRest.bodies);
    return text + drift(like) + "\n";
}

}  // namespace perpdot::crosscheck
