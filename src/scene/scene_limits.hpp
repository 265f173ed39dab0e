// Limits and names shared by the scene reader, writer and CLI (private to the library).
#pragma once

#include <cstddef>
#include <string>

namespace perpdot {

inline constexpr const char* sceneFormat = "perpdot-scene/1";

inline constexpr int maxSceneSteps = 10'000'000;  // "steps" and action step indices
inline constexpr int maxSubsteps = 64;
inline constexpr int maxIterations = 1000;        // Box2D velocity/position iterations
inline constexpr float maxTimestep = 1.0f;        // seconds; a larger step is surely a unit mistake
inline constexpr float minEdgeLength = 0.005f;    // Box2D's linear slop: shorter segments are degenerate

// The name a body gets when the file gives none: "body<index>".
std::string defaultBodyName(size_t index);

}  // namespace perpdot
