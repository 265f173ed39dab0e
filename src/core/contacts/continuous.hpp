// What the two continuous-collision passes share (continuous.cpp: fast bodies against static
// shapes; continuous_impacts.cpp: bullets against moving bodies).
#pragma once

#include <cmath>

#include "collide/collision.hpp"
#include "core/base/pool.hpp"
#include "core/bodies/body_store.hpp"
#include "core/joints/joint.hpp"
#include "core/shapes/broadphase.hpp"
#include "core/shapes/shape_store.hpp"
#include "core/world/step_context.hpp"
#include "core/world/step_scratch.hpp"

namespace perpdot {

// Continuous collision's view of the world (built by World::step, step.cpp), with World::Impl's
// names: the bodies it sweeps and moves, the shapes and broadphase it sweeps them through, and
// the step's scratch it starts from. Passed as `const ContinuousWorld&`; its parts are writable.
struct ContinuousWorld {
    Pool<Body>& bodies;
    const ShapeStore& shapes;
    Broadphase& broadphase;    // the tree it queries, the box rooms, the proxies it re-fits
    const JointStore& joints;  // collideConnected
    struct Scratch {
        SolverBodies& bodies;  // the awake bodies' solver state, slots and step-start poses
        MoverScratch& continuous;
    } scratch;
    int& frozenBodies;  // counts the bodies frozen (freeze, body_store.hpp)
};

// Solid shapes are swept; sensors and (massless) segments and chains on a moving body are not.
inline bool sweeps(const ShapeData& s) { return !s.sensor && s.minExtent > 0.0f; }
// A body moving less than this share of its swept shapes' least extent in a step cannot tunnel.
constexpr float safetyFactor = 0.5f;

// The body's box room with its shapes' measures known (refit_ahead.cpp): its reach, and the
// fastTravel and sweepRadius isFast compares a move with.
BoxRoom& knownShapes(Broadphase& broadphase, const Pool<Body>& bodies, const ShapeStore& shapes, int body);

// Against static shapes (continuous.cpp): a body is fast when its move from (centre c0, angle a0)
// to (c1, a1) may tunnel; solveContinuous sweeps it from its step-start pose (c0, a0) to its
// current one and moves it back to the earliest time of impact.
// isFast is inline: finalizeBodies asks it of every awake body.
inline bool isFast(Broadphase& broadphase, const Pool<Body>& bodies, const ShapeStore& shapes, int body, Vec2 c0,
                   float a0, Vec2 c1, float a1) {
    if (bodies[body].type != BodyType::Dynamic) return false;
    const BoxRoom& known = knownShapes(broadphase, bodies, shapes, body);
    // Largest distance any point travelled: |Δc| + |Δθ|·(radius about the centre of mass).
    const float travel = distance(c0, c1) + std::fabs(a1 - a0) * known.sweepRadius;
    return travel > known.fastTravel;
}
void solveContinuous(const ContinuousWorld& world, int body, Vec2 c0, float a0);
// Against bodies it strikes (continuous.cpp), once every body is final: a fast body also stops at a
// jointed body, awake or asleep, at least hitRatio times lighter (contact_cache.hpp) that it would
// pass into, at that body's end pose, keeping its velocity for the next step's contact (which solves
// the struck body's joints with it, contact_groups.cpp). `lightest`: lightestJointed, the largest
// 1/m of a jointed dynamic body (none if no body is that much lighter). Says whether it moved the
// body back.
bool solveStrikes(const ContinuousWorld& world, int body, Vec2 c0, float a0, float lightest);
float lightestJointed(const ContinuousWorld& world);
// The earliest time of impact in [0, 1] of the body's shapes along `sweep` with static shapes.
float staticImpact(const ContinuousWorld& world, int body, const collide::Sweep& sweep);

// Bullets against moving bodies (continuous_impacts.cpp): scratch.continuous.movers holds the fast
// bodies of this step (bullets not yet synchronised); finds their impacts in time order, resolves
// each with Hecker's collision impulse and moves the pair on for the rest of the step.
void solveMovingImpacts(const ContinuousWorld& world, const StepContext& ctx);

}  // namespace perpdot
