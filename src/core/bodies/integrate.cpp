// The body stages of the step (stages.hpp, and integrate.hpp for the two the substeps run): gather
// awake bodies and integrate their forces, apply a substep's forces, x += hs v, and write the
// solver state back (with continuous collision).
//
// Forces are integrated semi-implicitly (v first, then x). A body with no touching contact and
// no joint is integrated once per step in Box2D 2.4's order — v += h (g·gravityScale + F/m),
// ω += h τ/I, then damping v /= (1 + h c) — so free flight agrees with Box2D to rounding.
// A constrained body takes the same forces in substep-sized pieces, as Box2D v3's soft step
// does, which is what keeps tall stacks and heavy loads standing.
#include <algorithm>
#include <atomic>
#include <cmath>

#include "core/bodies/speed_limits.hpp"
#include "core/world/stages.hpp"

namespace perpdot {

namespace {

// Marks the bodies with a touching contact: one pass over the contacts' dense touching points and
// bodies (ContactCache::touchingPoints, bodiesOf), rather than a walk of each body's contact list
// (a turning container has thousands, most of them not touching), on the workers: a mark is only
// ever set to 1, so two workers marking one body agree (relaxed stores).
void markTouching(std::vector<uint8_t>& touchingBodies, int bodyCapacity, const ContactCache& cache, Workers& workers) {
    touchingBodies.assign(bodyCapacity, 0);
    workers.parallelFor(cache.contacts.capacity(), 1024, [&](int begin, int end, int) {
        for (int index = begin; index < end; ++index) {
            if (cache.touchingPoints[index] == 0) continue;  // free or not touching
            const auto [bodyA, bodyB] = cache.bodiesOf[index];
            std::atomic_ref(touchingBodies[bodyA]).store(1, std::memory_order_relaxed);
            std::atomic_ref(touchingBodies[bodyB]).store(1, std::memory_order_relaxed);
        }
    });
}

}  // namespace

// Gather awake bodies into the solver arrays and integrate forces: whole step for free bodies,
// substep pieces (SubstepForces) for constrained ones.
void integrateVelocities(SolverBodies& solverBodies, const Pool<Body>& bodies, const ContactCache& cache, Vec2 gravity,
                         Workers& workers, const StepContext& ctx) {
    markTouching(solverBodies.touchingBodies, bodies.capacity(), cache, workers);
    // Slot k + 1 for the k-th awake body in store order; 0 (the static slot) for the others.
    solverBodies.bodySlots.assign(static_cast<size_t>(bodies.capacity()), 0);
    const int count = workers.parallelSelect(
        bodies.capacity(),
        [&](int i) {
            const Body& b = bodies[i];
            return b.alive && b.type != BodyType::Static && b.awake;
        },
        [&](int total) { solverBodies.awakeBodies.resize(static_cast<size_t>(total)); },
        [&](int k, int i) {
            solverBodies.awakeBodies[static_cast<size_t>(k)] = i;
            solverBodies.bodySlots[static_cast<size_t>(i)] = k + 1;
        });
    solverBodies.states.resize(static_cast<size_t>(count) + 1);
    solverBodies.states[0] = BodyState{};
    solverBodies.substepForces.resize(static_cast<size_t>(count) + 1);
    solverBodies.substepForces[0] = SubstepForces{};
    solverBodies.inverseInertias.resize(static_cast<size_t>(count) + 1);
    solverBodies.inverseInertias[0] = 0.0f;
    workers.parallelFor(count, 256, [&](int begin, int end, int) {
        for (int k = begin; k < end; ++k) {
            const int i = solverBodies.awakeBodies[k];
            const Body& b = bodies[i];
            Vec2 v = b.v;
            float omega = b.w;
            SubstepForces f;
            if (b.type == BodyType::Dynamic) {
                const Vec2 force = (b.gravityScale * b.mass) * gravity + b.force;
                if (b.jointCount > 0 || solverBodies.touchingBodies[i]) {
                    f.dv = (ctx.hs * b.invMass) * force;
                    f.dw = ctx.hs * b.invInertia * b.torque;
                    f.linearDamping = 1.0f / (1.0f + ctx.hs * b.linearDamping);
                    f.angularDamping = 1.0f / (1.0f + ctx.hs * b.angularDamping);
                } else {
                    v += (ctx.h * b.invMass) * force;
                    omega += ctx.h * b.invInertia * b.torque;
                    // dv/dt = -c v, integrated implicitly: v /= (1 + h c).
                    v *= 1.0f / (1.0f + ctx.h * b.linearDamping);
                    omega *= 1.0f / (1.0f + ctx.h * b.angularDamping);
                }
            }
            solverBodies.states[k + 1] = {v, omega, {}, {}, b.invMass};
            solverBodies.substepForces[k + 1] = f;
            solverBodies.inverseInertias[k + 1] = b.invInertia;
        }
    });
    solverBodies.stepRotation.assign(solverBodies.states.size(), 0.0f);
}

void applySubstepForces(SolverBodies& bodies, int begin, int end) {
    for (int i = begin; i < end; ++i) {
        BodyState& s = bodies.states[i];
        const SubstepForces& f = bodies.substepForces[i];
        s.v = f.dv + f.linearDamping * s.v;
        s.w = f.dw + f.angularDamping * s.w;
    }
}

// x += hs v, θ += hs ω for one substep, with speeds clamped against blow-ups.
void integratePositions(SolverBodies& bodies, const StepContext& ctx, int begin, int end) {
    const float maxSpin = maxAngularSpeed(ctx.invHs);
    for (int i = begin; i < end; ++i) {
        BodyState& s = bodies.states[i];
        s.v = clampSpeed(s.v, ctx.maxLinearSpeed);
        s.w = clampAngularSpeed(s.w, maxSpin);
        s.dp += ctx.hs * s.v;
        bodies.stepRotation[i] += ctx.hs * s.w;
        s.dq = integrateRotation(s.dq, ctx.hs * s.w);
    }
}

// Write the solver state back: c = c0 + Δp, θ = θ0 + Δθ, origin = c - R(θ) localCenter.
// The workers write the bodies that are not non-finite, sweep the fast ones from their step-start
// pose against static shapes, and check which of them stay inside their fat AABBs; then, one by
// one, the non-finite ones are frozen and the broadphase follows the other bodies; bullets wait
// until every other body is final, then meet moving bodies too (continuous_impacts.cpp).
void finalizeBodies(const ContinuousWorld& w, Workers& workers, bool enableContinuous, const StepContext& ctx) {
    // MovedInside, FastInside: its proxies stay as they are; Fast: a bullet, or a fast body whose
    // proxies re-fit after its sweep.
    enum Motion : uint8_t { Moved, MovedInside, Fast, FastInside, NonFinite };
    // The solver's velocities, within the speed limits (restitution comes after the last clamp of
    // integratePositions), and the pose (c1, a1) into the body.
    const float maxSpin = maxAngularSpeed(ctx.invHs);
    const auto moveTo = [&](Body& b, const BodyState& s, Vec2 c1, float a1) {
        b.v = clampSpeed(s.v, ctx.maxLinearSpeed);
        b.w = clampAngularSpeed(s.w, maxSpin);
        b.center = c1;
        b.angle = a1;
        b.xf = b.derivedTransform();
    };
    // The parts the loops read most, bound once: through the view each is one load further.
    Pool<Body>& bodies = w.bodies;
    SolverBodies& solverBodies = w.scratch.bodies;
    Broadphase& broadphase = w.broadphase;
    const ShapeStore& shapes = w.shapes;
    const int count = static_cast<int>(solverBodies.awakeBodies.size());
    solverBodies.bodyMotion.resize(static_cast<size_t>(count));
    solverBodies.stepStarts.resize(static_cast<size_t>(count));
    std::atomic<bool> anyBullet{false};  // only ever set: the same for any split
    workers.parallelFor(count, 256, [&](int begin, int end, int) {
        for (int k = begin; k < end; ++k) {
            Body& b = bodies[solverBodies.awakeBodies[k]];
            b.force = {};  // applied: forces last one step
            b.torque = 0.0f;
            const BodyState& s = solverBodies.states[k + 1];
            const float dAngle = solverBodies.stepRotation[k + 1];
            if (!isFinite(s.v) || !std::isfinite(s.w) || !isFinite(s.dp) || !std::isfinite(dAngle)) {
                solverBodies.bodyMotion[k] = NonFinite;
                continue;
            }
            if (b.bullet) anyBullet.store(true, std::memory_order_relaxed);
            const Vec2 c1 = b.center + s.dp;
            const float a1 = b.angle + dAngle;
            const int index = solverBodies.awakeBodies[k];
            if (enableContinuous && isFast(broadphase, bodies, shapes, index, b.center, b.angle, c1, a1)) {
                // Swept against static shapes, which no worker moves: side by side like the rest.
                const BodyPose start{b.center, b.angle};
                solverBodies.stepStarts[k] = start;
                moveTo(b, s, c1, a1);
                if (b.bullet) {
                    solverBodies.bodyMotion[k] = Fast;  // it waits for every other body (continuous_impacts.cpp)
                    continue;
                }
                solveContinuous(w, index, start.center, start.angle);
                solverBodies.bodyMotion[k] = boxesInside(broadphase, bodies, shapes, index, b.center, b.xf) ? FastInside : Fast;
                continue;
            }
            moveTo(b, s, c1, a1);
            solverBodies.bodyMotion[k] = boxesInside(broadphase, bodies, shapes, index, c1, b.xf) ? MovedInside : Moved;
        }
    });
    // The lightest body a fast body may strike (solveStrikes), found at the first that asks.
    float lightest = -1.0f;
    const auto strikes = [&](int index, const BodyPose& start) {
        if (lightest < 0.0f) lightest = lightestJointed(w);
        return solveStrikes(w, index, start.center, start.angle, lightest);
    };
    for (int k = 0; k < count; ++k) {
        const uint8_t motion = solverBodies.bodyMotion[k];
        if (motion == MovedInside) continue;  // most bodies: no more to do
        const int index = solverBodies.awakeBodies[k];
        Body& b = bodies[index];
        const BodyState& s = solverBodies.states[k + 1];
        if (motion == NonFinite) {
            freeze(b, w.frozenBodies);  // where it was before the step,
            broadphase.synchronizeProxies(shapes, bodies, index, b.xf, {});  // perhaps outside the boxes re-fitted ahead
            continue;
        }
        if (motion == Moved) {
            refitEscaped(broadphase, bodies, shapes, index, b.center, b.xf, s.dp);
            continue;
        }
        if (b.bullet) continue;  // Fast: it waits for every other body
        // Fast or FastInside: swept against the bodies it strikes, all of them final now, and
        // re-fitted where it ends when its boxes no longer hold it or it stopped at a strike.
        const BodyPose& start = solverBodies.stepStarts[k];
        if (strikes(index, start) || motion == Fast) refitEscaped(broadphase, bodies, shapes, index, b.center, b.xf, b.center - start.center);
    }
    // Bullets wait for every other body, then meet the fast ones too (continuous_impacts.cpp):
    // the fast bodies become movers, where there is a bullet.
    w.scratch.continuous.movers.clear();
    const bool listMovers = anyBullet.load(std::memory_order_relaxed);
    for (int k = 0; listMovers && k < count; ++k) {
        if (solverBodies.bodyMotion[k] != Fast && solverBodies.bodyMotion[k] != FastInside) continue;
        const Body& b = bodies[solverBodies.awakeBodies[k]];
        const BodyPose& start = solverBodies.stepStarts[k];
        w.scratch.continuous.movers.push_back({.body = solverBodies.awakeBodies[k], .c0 = start.center, .c1 = b.center, .a0 = start.angle,
                                    .a1 = b.angle, .v = b.v, .w = b.w, .stepStart = start.center, .fast = true});
    }
    if (!w.scratch.continuous.movers.empty()) solveMovingImpacts(w, ctx);
    // The forces of the bodies outside the solver (a body put to sleep with its forces) go too.
    for (int i = 0; i < bodies.capacity(); ++i) {
        if (solverBodies.bodySlots[static_cast<size_t>(i)] != 0) continue;
        bodies[i].force = {};
        bodies[i].torque = 0.0f;
    }
}

}  // namespace perpdot
