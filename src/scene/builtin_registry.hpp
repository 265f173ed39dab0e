// The built-in scenes come from several files; each contributes one list, and
// builtin_registry.cpp joins them. To add a group: declare it here, define it in its own
// file, and add one line to builtinScenes(). Each entry's make() need not set the scene's
// name and description: the registry copies them from the entry.
#pragma once

#include <memory>
#include <vector>

#include "perpdot/scene.hpp"
#include "scene/scene_script.hpp"

namespace perpdot {

std::vector<BuiltinScene> coreScenes();   // core_scenes.cpp: single bodies, stacks, friction, restitution
std::vector<BuiltinScene> benchScenes();  // bench_scenes.cpp: the large scenes of the benchmarks
BuiltinScene ragdollRainScene();          // ragdoll_rain.cpp: the benchmark whose script spawns ragdolls
BuiltinScene junkyardScene();             // junkyard.cpp: the benchmark whose script drives a pusher
std::unique_ptr<SceneScript> makeRagdollRainScript();  // their scripts, for makeSceneScript (scene_script.cpp)
std::unique_ptr<SceneScript> makeJunkyardScript();
std::vector<BuiltinScene> demoScenes();  // builtin_demo_scenes.cpp: showcases for the viewer (card house, dominoes, ...)
std::vector<BuiltinScene> jointScenes();  // builtin_joint_scenes.cpp: pendulums, chain, bridge, ragdoll, car, joint grid, windmill, slider
std::vector<BuiltinScene> coupledJointScenes();  // builtin_coupled_joint_scenes.cpp: gears, pulley
std::vector<BuiltinScene> stressScenes();   // stress_scenes.cpp: the torture suite of `perpdot stress`
std::vector<BuiltinScene> featureScenes();  // builtin_feature_scenes.cpp: one-way platforms, sensors, bullets, conveyors, laser, capsules, mover course

}  // namespace perpdot
