// The stability figure `perpdot bench` prints beside the timings: one number per engine that says
// whether the fast run is also a sound one. Which figure depends on the scene (docs/crosscheck.md):
//   pyramids, joint_grid, any other scene   top fell        m       how far the initially highest dynamic body went down
//   bench_tumbler, spinner, washer          escaped         bodies  centres of mass outside the body named "container"
//   smash                                   momentum error  of p0   |Σ m v (end) − Σ m v (start)| / |Σ m v (start)|
//   ragdoll_rain, junkyard, compounds       below floor     bodies  centres of mass below the lowest shape centre of "ground"
#pragma once

#include <vector>

#include "crosscheck/stepper.hpp"
#include "perpdot/scene.hpp"

namespace perpdot::crosscheck {

class StabilityProbe {
public:
    // Picks the scene's figure and what it needs from the scene (the top body, the container's
    // outline, the floor). perpdot::Error when the scene lacks it (no body named "container").
    explicit StabilityProbe(const Scene& scene);

    const char* label() const;  // e.g. "top fell"
    const char* unit() const;   // e.g. "m"

    // The figure from two frames of one engine, each as Stepper::sampleAll() gives it (the
    // scene's non-static bodies first, in scene order, then any the scene's script spawned).
    float measure(const std::vector<BodySample>& first, const std::vector<BodySample>& last) const;

private:
    enum class Kind { TopFell, Escaped, MomentumError, BelowFloor };
    float escaped(const std::vector<BodySample>& last) const;

    Kind kind_ = Kind::TopFell;
    int top_ = -1;                      // TopFell: sample index of the initially highest dynamic body; -1: none
    int container_ = -1;                // Escaped: sample index of a moving container; -1: it is static
    Transform containerFrame_{};        // Escaped: the static container's frame
    std::vector<Vec2> outline_;         // Escaped: the container's inside, in its body frame
    float floor_ = 0.0f;                // BelowFloor: height, metres
};

}  // namespace perpdot::crosscheck
