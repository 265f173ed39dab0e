// The stages of World::step (step.cpp), in the order it runs them, each a function of the parts of
// the world it reads and writes, or of a view of them built by step.cpp, and of the step's context.
// The contact and joint stages are defined beside their rows (contact_solver*.cpp, joint*.cpp), the
// body stages in integrate.cpp; pairs and narrowphase are the contact cache's (contact_world.hpp),
// continuous collision has its own header (continuous.hpp).
#pragma once

#include <span>

#include "core/base/pool.hpp"
#include "core/bodies/body_store.hpp"
#include "core/bodies/integrate.hpp"
#include "core/contacts/contact_cache.hpp"
#include "core/contacts/continuous.hpp"
#include "core/joints/joint.hpp"
#include "core/shapes/broadphase.hpp"
#include "core/shapes/shape_store.hpp"
#include "core/solver/contact_solver.hpp"
#include "core/threads/workers.hpp"
#include "perpdot/world.hpp"

namespace perpdot {

// The step's constants: substep, softness of contact and joint rows, thresholds; hitEvents: some
// shape reports hits.
StepContext makeStepContext(const WorldDef& def, bool hitEvents, float h);

// Integrate velocities: gather the awake bodies into the solver arrays; free bodies take the
// whole step's forces now, constrained ones per substep.
void integrateVelocities(SolverBodies& solverBodies, const Pool<Body>& bodies, const ContactCache& cache, Vec2 gravity,
                         Workers& workers, const StepContext& ctx);

// The tree re-fit's view of the world, with World::Impl's names: the awake bodies' predicted
// poses, the broadphase that follows them, and the contacts found apart that its task releases.
// The task reads it until finishTreeRefit returns.
struct RefitWorld {
    Broadphase& broadphase;
    const Pool<Body>& bodies;
    const ShapeStore& shapes;
    ContactCache& contactCache;
    struct Scratch {
        SolverBodies& bodies;  // the awake bodies, their velocities and predicted poses
    } scratch;
    Workers& workers;
};
// Re-fit ahead (refit_ahead.cpp): start re-fitting, on a worker of its own, the proxies of the
// bodies whose predicted end pose leaves their fat AABB; finish before the bodies take their poses.
void startTreeRefit(RefitWorld& world, const StepContext& ctx);
void finishTreeRefit(Workers& workers);
// Whether the body's boxes at pose xf (centre of mass `center`) are inside their fat AABBs: by its
// box room when that tells, else measured into it. When not, the caller re-fits with refitEscaped.
bool boxesInside(Broadphase& broadphase, const Pool<Body>& bodies, const ShapeStore& shapes, int body, Vec2 center,
                 const Transform& xf);
// Re-fit the body's proxies whose box at xf sticks out of their fat AABB, and only those (grown
// along `displacement`), and measure its boxes in their new fat AABBs.
void refitEscaped(Broadphase& broadphase, const Pool<Body>& bodies, const ShapeStore& shapes, int body, Vec2 center,
                  const Transform& xf, Vec2 displacement);
// Store the solver state in the bodies and, with enableContinuous, sweep the fast ones
// (continuous collision).
void finalizeBodies(const ContinuousWorld& world, Workers& workers, bool enableContinuous, const StepContext& ctx);
// Sleep: islands of touching contacts and joints whose every body was still for timeToSleep fall
// asleep as a whole (sleep.cpp).
void updateSleep(Pool<Body>& bodies, const ContactCache& cache, const JointStore& joints,
                 std::span<const int> awakeBodies, IslandScratch& islands, float h);

}  // namespace perpdot
