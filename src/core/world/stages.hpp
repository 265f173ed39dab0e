// The stages of World::step (step.cpp), in the order it runs them, each a function of the world
// and the step's context: the units the speed issue's threads will run. The contact and joint
// stages are defined beside their rows (contact_solver*.cpp, joint*.cpp), the body stages in
// integrate.cpp; pairs and narrowphase are the contact cache's (contact_cache.hpp), continuous
// collision has its own header (continuous.hpp).
#pragma once

#include "core/bodies/integrate.hpp"
#include "core/joints/joint.hpp"
#include "core/solver/contact_solver.hpp"
#include "core/world/world_impl.hpp"

namespace perpdot {

// The step's constants: substep, softness of contact and joint rows, thresholds.
StepContext makeStepContext(const World::Impl& w, float h);

// Integrate velocities: gather the awake bodies into the solver arrays; free bodies take the
// whole step's forces now, constrained ones per substep.
void integrateVelocities(World::Impl& w, const StepContext& ctx);
// Re-fit ahead (refit_ahead.cpp): start re-fitting, on a worker of its own, the proxies of the
// bodies whose predicted end pose leaves their fat AABB; finish before the bodies take their poses.
void startTreeRefit(World::Impl& w, const StepContext& ctx);
void finishTreeRefit(World::Impl& w);
// Whether the body's boxes at pose xf (centre of mass `center`) are inside their fat AABBs: by its
// box room when that tells, else measured into it. When not, the caller re-fits with refitEscaped.
bool boxesInside(World::Impl& w, int body, Vec2 center, const Transform& xf);
// Re-fit the body's proxies whose box at xf sticks out of their fat AABB, and only those (grown
// along `displacement`), and measure its boxes in their new fat AABBs.
void refitEscaped(World::Impl& w, int body, Vec2 center, const Transform& xf, Vec2 displacement);
// Store the solver state in the bodies and sweep the fast ones (continuous collision).
void finalizeBodies(World::Impl& w, const StepContext& ctx);
// Sleep: islands of touching contacts and joints whose every body was still for timeToSleep fall
// asleep as a whole (sleep.cpp).
void updateSleep(World::Impl& w, float h);

}  // namespace perpdot
