// The ragdoll figure shared by the `ragdoll` scene and `ragdoll_rain`'s script: a limp human of
// boxes (torso, head, upper and lower arms and legs) held by limited revolute joints at the neck,
// shoulders, elbows, hips and knees.
#pragma once

#include <string>

#include "perpdot/scene.hpp"

namespace perpdot {

inline constexpr int ragdollBodyCount = 10;
inline constexpr int ragdollJointCount = 9;

// Appends one figure whose torso centre is at `torso`: bodies named `prefix` + "torso", "head",
// "upper_arm_left", … (the prefix keeps several figures in one scene apart).
void addRagdoll(Scene& scene, Vec2 torso, const std::string& prefix = "");

}  // namespace perpdot
