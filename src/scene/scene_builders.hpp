// Small helpers for writing scenes in C++ (built-in scenes, tests, demos).
#pragma once

#include <vector>

#include "perpdot/scene.hpp"

namespace perpdot {

SceneShape boxShape(float hx, float hy, Vec2 center = {}, float angle = 0.0f);
SceneShape circleShape(float radius, Vec2 center = {});
SceneShape segmentShape(Vec2 v1, Vec2 v2);
SceneShape polygonShape(std::vector<Vec2> vertices, float radius = 0.0f);
SceneShape capsuleShape(Vec2 center1, Vec2 center2, float radius);

// Appends `body` (named "body<index>" if it has no name) and returns it.
SceneBody& addBody(Scene& scene, SceneBody body);

// A static box body whose top face is the line y = top, from x = -halfWidth to +halfWidth.
SceneBody& addGround(Scene& scene, float halfWidth, float top = 0.0f);

// A static bin named "ground", built as Box2D v3's benchmark builds its junkyard and compound
// scenes: a floor of 2·halfSpan + 1 boxes of 1.1 × 1 m centred on y = 0 from x = -halfSpan to
// +halfSpan, 1 m apart, and at x = ±halfSpan a wall of `wallBoxes` boxes of 1 × 1.1 m from y = 1
// up, 1 m apart (neighbouring boxes overlap, so the surfaces have no seams).
SceneBody& addBin(Scene& scene, int halfSpan, int wallBoxes);

// A pyramid of square boxes (half extent h) with `baseCount` boxes in its bottom row resting on
// y = baseY, the bottom row starting at x = leftX; each row is offset by half a box
// (Box2D v3's benchmark layout). Bodies are dynamic, density 1, default friction.
void addPyramid(Scene& scene, int baseCount, float h, float leftX, float baseY, bool allowSleep = true);

}  // namespace perpdot
