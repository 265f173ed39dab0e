// Contact constraints of a step, built from the contact cache: masses, softness, anchors, effective
// masses and the approach speeds restitution reads. Their rows (the substeps' passes and, after them,
// restitution) are in contact_solver_wide.{hpp,cpp}.
#include <algorithm>

#include "core/world_impl.hpp"

namespace perpdot {

namespace {

// 1/mA + 1/mB + perpDot(rA,d)²/IA + perpDot(rB,d)²/IB: the inverse effective mass along d.
float invEffectiveMass(const ContactConstraint& c, Vec2 rA, Vec2 rB, Vec2 d) {
    const float rnA = perpDot(rA, d), rnB = perpDot(rB, d);
    return c.invMassA + c.invMassB + c.invIA * rnA * rnA + c.invIB * rnB * rnB;
}

// The velocity a body would end the step with if nothing touched it: its state plus the substeps'
// forces still to come. Restitution reverses the approach speed at the end of the step, forces
// included: in the discrete fall a ball hits the ground with that speed, and an e = 1 bounce then
// climbs exactly as many steps as it fell (docs/stress.md).
BodyState velocityWithoutContact(const World::Impl& w, const StepContext& ctx, int slot) {
    BodyState s = w.scratch.states[slot];
    const SubstepForces& f = w.scratch.substepForces[slot];
    s.v += static_cast<float>(ctx.substeps) * f.dv;
    s.w += static_cast<float>(ctx.substeps) * f.dw;
    return s;
}

// The constraint of a touching contact: masses, softness, anchors and effective masses.
void prepareContact(const World::Impl& w, const StepContext& ctx, ContactConstraint& c) {
    const Contact& contact = w.contactCache.contacts[c.contact];
    const Body& ba = w.bodies[contact.bodyA];
    const Body& bb = w.bodies[contact.bodyB];
    c.indexA = ba.solverIndex;
    c.indexB = bb.solverIndex;
    c.invMassA = ba.invMass;
    c.invIA = ba.invInertia;
    c.invMassB = bb.invMass;
    c.invIB = bb.invInertia;
    c.normal = contact.normal;
    c.friction = contact.friction;
    c.restitution = contact.restitution;
    c.rollingResistance = contact.rollingResistance;
    c.tangentSpeed = contact.tangentSpeed;
    c.rollingImpulse = ctx.enableWarmStarting ? contact.rollingImpulse : 0.0f;
    const float kRolling = c.invIA + c.invIB;
    c.rollingMass = c.rollingResistance > 0.0f && kRolling > 0.0f ? 1.0f / kRolling : 0.0f;
    const bool againstStatic = ba.invMass == 0.0f || bb.invMass == 0.0f;
    const Softness& softness = againstStatic ? ctx.staticSoftness : ctx.contactSoftness;
    c.biasRate = softness.biasRate;
    c.massScale = softness.massScale;
    c.impulseScale = softness.impulseScale;
    c.pointCount = contact.pointCount;
    c.turnsA = roundingRadius(w.shapes[contact.a.shape]) == 0.0f ? 1.0f : 0.0f;
    c.turnsB = roundingRadius(w.shapes[contact.b.shape]) == 0.0f ? 1.0f : 0.0f;

    const Vec2 n = contact.normal, t = perp(n);
    const BodyState sa = velocityWithoutContact(w, ctx, c.indexA), sb = velocityWithoutContact(w, ctx, c.indexB);
    for (int i = 0; i < contact.pointCount; ++i) {
        const ContactPointState& p = contact.points[i];
        ContactPointRows<float>& cp = c.points[i];
        cp.anchorA = p.anchorA;
        cp.anchorB = p.anchorB;
        cp.baseSeparation = p.separation - dot(p.anchorB - p.anchorA, n);
        const float scale = ctx.enableWarmStarting ? 1.0f : 0.0f;
        cp.normalImpulse = scale * p.normalImpulse;
        cp.tangentImpulse = scale * p.tangentImpulse;
        cp.maxNormalImpulse = 0.0f;
        const float kn = invEffectiveMass(c, p.anchorA, p.anchorB, n);
        const float kt = invEffectiveMass(c, p.anchorA, p.anchorB, t);
        cp.normalMass = kn > 0.0f ? 1.0f / kn : 0.0f;
        cp.tangentMass = kt > 0.0f ? 1.0f / kt : 0.0f;
        cp.relativeVelocity = dot(relativeVelocity(sa, sb, p.anchorA, p.anchorB), n);
    }
    for (int i = contact.pointCount; i < 2; ++i) c.points[i] = {};  // a reused slot keeps no old point
}

}  // namespace

// The touching contacts with an awake body, in pool order, selected and prepared by the workers.
void prepareContacts(World::Impl& w, const StepContext& ctx) {
    StepScratch& s = w.scratch;
    auto constrains = [&](int index) {
        const Contact& contact = w.contactCache.contacts[index];
        return contact.alive && contact.touching && (w.bodies[contact.bodyA].awake || w.bodies[contact.bodyB].awake);
    };
    w.workers.parallelSelect(
        w.contactCache.contacts.capacity(), constrains,
        [&](int total) {
            s.constraints.resize(total);
            s.constraintSlots.resize(total);
        },
        [&](int k, int index) {
            ContactConstraint& c = s.constraints[k];
            c.contact = index;
            prepareContact(w, ctx, c);
            s.constraintSlots[k] = {c.indexA, c.indexB};
        });
    findContactGroups(w, ctx);
    prepareContactBlocks(w);
}

}  // namespace perpdot
