// What the two continuous-collision passes share (continuous.cpp: fast bodies against static
// shapes; continuous_impacts.cpp: bullets against moving bodies).
#pragma once

#include "core/world/world_impl.hpp"

namespace perpdot {

// Solid shapes are swept; sensors and (massless) segments and chains on a moving body are not.
inline bool sweeps(const ShapeData& s) { return !s.sensor && s.minExtent > 0.0f; }
// A body moving less than this share of its swept shapes' least extent in a step cannot tunnel.
constexpr float safetyFactor = 0.5f;

// The body's box room with its shapes' measures known (refit_ahead.cpp): its reach, and the
// fastTravel and sweepRadius isFast compares a move with.
BoxRoom& knownShapes(World::Impl& w, int body);

// Against static shapes (continuous.cpp): a body is fast when its move from (centre c0, angle a0)
// to (c1, a1) may tunnel; solveContinuous sweeps it from its step-start pose (c0, a0) to its
// current one and moves it back to the earliest time of impact.
bool isFast(World::Impl& w, int body, Vec2 c0, float a0, Vec2 c1, float a1);
void solveContinuous(World::Impl& w, int body, Vec2 c0, float a0);
// The earliest time of impact in [0, 1] of the body's shapes along `sweep` with static shapes.
float staticImpact(const World::Impl& w, int body, const collide::Sweep& sweep);

// Bullets against moving bodies (continuous_impacts.cpp): the step scratch's `movers` holds the
// fast bodies of this step (bullets not yet synchronised); finds their impacts in time order,
// resolves each with Hecker's collision impulse and moves the pair on for the rest of the step.
void solveMovingImpacts(World::Impl& w, const StepContext& ctx);

}  // namespace perpdot
