// World::step, stage by stage (stages.hpp). The soft step of Box2D v3: the rows run `substeps`
// times per step — forces, warm start, solve with soft bias, x += hs v, relax without bias — then
// one restitution pass, and the impulses are kept for the next step's warm start.
#include <algorithm>
#include <cmath>
#include <string>

#include "core/contacts/contact_world.hpp"
#include "core/world/events.hpp"
#include "core/world/stages.hpp"
#include "core/world/world_impl.hpp"

namespace perpdot {

StepContext makeStepContext(const WorldDef& def, bool hitEvents, float h) {
    StepContext ctx;
    ctx.h = h;
    ctx.invH = 1.0f / h;
    ctx.substeps = def.substeps;
    ctx.hs = h / static_cast<float>(def.substeps);
    ctx.invHs = 1.0f / ctx.hs;
    // Contact stiffness is capped at a quarter of the substep rate; static contacts are twice as stiff.
    const float contactHertz = std::min(def.contactHertz, 0.25f * ctx.invHs);
    ctx.contactSoftness = makeSoftness(contactHertz, def.contactDampingRatio, ctx.hs);
    ctx.staticSoftness = makeSoftness(2.0f * contactHertz, def.contactDampingRatio, ctx.hs);
    ctx.jointSoftness = makeSoftness(std::min(def.jointHertz, 0.25f * ctx.invHs), def.jointDampingRatio, ctx.hs);
    ctx.restitutionThreshold = def.restitutionThreshold;
    ctx.hitEvents = hitEvents;
    ctx.maxBiasVelocity = def.contactPushMaxVelocity;
    ctx.maxLinearSpeed = def.maxLinearSpeed;
    ctx.pushSlop = def.box2dSkin ? collide::linearSlop : 0.0f;
    ctx.enableWarmStarting = def.enableWarmStarting;
    return ctx;
}

namespace {

// The solver's view of the world (solver_world.hpp): its stages see these parts and no others.
SolverWorld solverWorld(World::Impl& w) {
    StepScratch& s = w.scratch;
    return {.bodies = w.bodies,
            .contactCache = w.contactCache,
            .joints = *w.joints,
            .scratch = {.bodies = s.bodies, .contacts = s.contacts, .coloring = s.coloring, .joints = *s.joints},
            .workers = w.workers,
            .gravity = w.def.gravity,
            .anyRestitution = w.shapes.anyRestitution};
}

// The tree re-fit's view (stages.hpp).
RefitWorld refitWorld(World::Impl& w) {
    return {.broadphase = w.broadphase,
            .bodies = w.bodies,
            .shapes = w.shapes,
            .contactCache = w.contactCache,
            .scratch = {.bodies = w.scratch.bodies},
            .workers = w.workers};
}

// Continuous collision's view (continuous.hpp).
ContinuousWorld continuousWorld(World::Impl& w) {
    return {.bodies = w.bodies,
            .shapes = w.shapes,
            .broadphase = w.broadphase,
            .joints = *w.joints,
            .scratch = {.bodies = w.scratch.bodies, .continuous = w.scratch.continuous},
            .frozenBodies = w.frozenBodies};
}

}  // namespace

void World::step(float timeStep) {
    Impl& w = *impl_;
    if (w.locked) throw Error("World::step: called during step() (from a callback); step after it returns");
    if (!(timeStep >= 0.0f) || !std::isfinite(timeStep))
        throw Error("World::step: the time step must be finite and >= 0, not " + std::to_string(timeStep));
    // Unlocks however step() ends: an exception thrown by the user's pre-solve callback leaves
    // the step unfinished but the world usable.
    struct Lock {
        bool& locked;
        explicit Lock(bool& l) : locked(l) { locked = true; }
        ~Lock() { locked = false; }
    } lock(w.locked);
    // Waits for the tree's re-fits however step() ends (finishTreeRefit is the usual wait), before
    // the view the re-fit task reads goes.
    RefitWorld refit = refitWorld(w);
    struct RefitWait {
        Workers& workers;
        ~RefitWait() { finishTreeRefit(workers); }
    } refitWait{w.workers};
    w.events.beginStep();

    const ContactWorld contacts = contactWorld(w);
    updatePairs(contacts);     // pairs: proxies that left their fat AABB meet new partners
    updateContacts(contacts);  // narrowphase: each contact keeps its manifold or takes a new one
    if (timeStep == 0.0f) {  // Box2D 2.4's Step(0): the contacts and their events, no motion
        releaseApartContacts(w.contactCache);
        w.events.endStep();
        return;
    }

    StepContext ctx = makeStepContext(w.def, w.shapes.anyHitEvents, timeStep);
    integrateVelocities(w.scratch.bodies, w.bodies, w.contactCache, w.def.gravity, w.workers, ctx);
    const SolverWorld solver = solverWorld(w);
    prepareJoints(solver, ctx);   // prepare: effective masses, anchors, warm-start impulses
    startTreeRefit(refit, ctx);   // the broadphase follows the predicted poses on a worker of its own,
    selectContacts(solver, ctx);  // beside the touching contacts, their groups (which take their bodies' joints)
    colorJoints(solver, ctx);     // and the joints' serial colouring
    prepareContactBlocks(solver, ctx);
    // Per substep: its forces, warm start, solve with soft bias, x += hs v, relax without bias;
    // then restitution, Hecker's bounce, once (solver_stages.hpp: the rows colour by colour, on
    // the workers).
    w.scratch.solverStages.build(solver);
    w.scratch.solverStages.run(solver, ctx);
    projectJoints(*w.scratch.joints, w.scratch.bodies);         // project: the joints of joint trees hold again
    storeContactImpulses(w.scratch.contacts, w.contactCache);  // store: impulses for the next step's warm start (the lanes' stored by the solver)
    storeJointImpulses(solver, ctx);
    reportHitEvents(w.events, w.scratch.contacts, w.contactCache, w.shapes, w.identity, w.def.hitEventThreshold);
    finishTreeRefit(w.workers);
    finalizeBodies(continuousWorld(w), w.workers, w.def.enableContinuous, ctx);  // positions back into the bodies; continuous collision
    breakJoints(jointRemoval(w), *w.scratch.joints, w.events, w.identity, w.workers, ctx);  // joints whose reaction over the step passed their break limits

    if (w.def.enableSleep)  // sleep: islands at rest
        updateSleep(w.bodies, w.contactCache, *w.joints, w.scratch.bodies.awakeBodies, w.scratch.islands, timeStep);
    w.events.endStep();
}

}  // namespace perpdot
