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
// Larger magnitudes are unit mistakes: they overflow mass and inertia (m r²) to infinity, or put
// bodies where float spacing (7.8 mm at 1e5 m) exceeds Box2D's linear slop.
inline constexpr float maxCoordinate = 1.0e5f;    // m: positions, vertices, radii, half extents, angles (rad)
inline constexpr float maxSpeed = 1.0e4f;         // m/s and rad/s: initial velocities
inline constexpr float maxDensity = 1.0e6f;       // kg/m²
inline constexpr float maxMaterial = 1.0e3f;      // friction, restitution, damping, gravity scale
inline constexpr float maxGravity = 1.0e4f;       // m/s²

// The name a body gets when the file gives none: "body<index>".
std::string defaultBodyName(size_t index);

}  // namespace perpdot
