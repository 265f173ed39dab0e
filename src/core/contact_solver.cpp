// Contact rows solved with sequential impulses. Each row is Hecker's collision impulse
//   j = -(v_rel·n + bias) / (1/mA + 1/mB + perpDot(rA,n)²/IA + perpDot(rB,n)²/IB)
// accumulated and clamped (λn ≥ 0, |λt| ≤ μ λn), softened by the substep's Softness.
#include <algorithm>

#include "core/world_impl.hpp"

namespace perpdot {

namespace {

// 1/mA + 1/mB + perpDot(rA,d)²/IA + perpDot(rB,d)²/IB: the inverse effective mass along d.
float invEffectiveMass(const ContactConstraint& c, Vec2 rA, Vec2 rB, Vec2 d) {
    const float rnA = perpDot(rA, d), rnB = perpDot(rB, d);
    return c.invMassA + c.invMassB + c.invIA * rnA * rnA + c.invIB * rnB * rnB;
}

// Apply impulse P at the anchors: vA -= P/mA, ωA -= perpDot(rA,P)/IA, and + for B.
void applyImpulse(const ContactConstraint& c, BodyState& a, BodyState& b, Vec2 rA, Vec2 rB, Vec2 P) {
    a.v -= c.invMassA * P;
    a.w -= c.invIA * perpDot(rA, P);
    b.v += c.invMassB * P;
    b.w += c.invIB * perpDot(rB, P);
}

Vec2 relativeVelocity(const BodyState& a, const BodyState& b, Vec2 rA, Vec2 rB) {
    return pointVelocity(b.v, b.w, rB) - pointVelocity(a.v, a.w, rA);
}

}  // namespace

void prepareContacts(World::Impl& w, const StepContext& ctx) {
    std::vector<BodyState>& states = *ctx.states;
    w.constraints.clear();
    for (int index = 0; index < static_cast<int>(w.contacts.size()); ++index) {
        const Contact& contact = w.contacts[index];
        if (!contact.alive || !contact.touching) continue;
        const Body& ba = w.bodies[contact.bodyA];
        const Body& bb = w.bodies[contact.bodyB];
        if (!ba.awake && !bb.awake) continue;

        ContactConstraint& c = w.constraints.emplace_back();
        c.contact = index;
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
        c.softness = againstStatic ? ctx.staticSoftness : ctx.contactSoftness;
        c.pointCount = contact.pointCount;

        const Vec2 n = contact.normal, t = perp(n);
        const BodyState& sa = states[c.indexA];
        const BodyState& sb = states[c.indexB];
        for (int i = 0; i < contact.pointCount; ++i) {
            const ContactPointState& p = contact.points[i];
            ContactConstraintPoint& cp = c.points[i];
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
    }
}

void warmStartContacts(World::Impl& w, const StepContext& ctx) {
    std::vector<BodyState>& states = *ctx.states;
    for (const ContactConstraint& c : w.constraints) {
        BodyState& a = states[c.indexA];
        BodyState& b = states[c.indexB];
        const Vec2 t = perp(c.normal);
        for (int i = 0; i < c.pointCount; ++i) {
            const ContactConstraintPoint& cp = c.points[i];
            applyImpulse(c, a, b, cp.anchorA, cp.anchorB, cp.normalImpulse * c.normal + cp.tangentImpulse * t);
        }
        if (c.rollingImpulse != 0.0f) {
            a.w -= c.invIA * c.rollingImpulse;
            b.w += c.invIB * c.rollingImpulse;
        }
    }
}

void solveContacts(World::Impl& w, const StepContext& ctx, bool useBias) {
    std::vector<BodyState>& states = *ctx.states;
    for (ContactConstraint& c : w.constraints) {
        BodyState& a = states[c.indexA];
        BodyState& b = states[c.indexB];
        const Vec2 n = c.normal;
        const Vec2 dp = b.dp - a.dp;

        // Non-penetration: λn ≥ 0.
        float totalNormalImpulse = 0.0f;
        for (int i = 0; i < c.pointCount; ++i) {
            ContactConstraintPoint& cp = c.points[i];
            // Current separation without a new narrowphase: s = base + (ΔpB + rB' - ΔpA - rA')·n.
            const Vec2 rA = cp.anchorA, rB = cp.anchorB;
            const float s = cp.baseSeparation + dot(dp + rotate(b.dq, rB) - rotate(a.dq, rA), n);
            float bias = 0.0f, massScale = 1.0f, impulseScale = 0.0f;
            if (s > 0.0f) {
                bias = s * ctx.invHs;  // speculative: may close the gap this substep, no more
            } else if (useBias) {
                // Push out only what exceeds the linear slop, so resting contacts stay touching.
                bias = std::max(c.softness.biasRate * std::min(s + collide::linearSlop, 0.0f), -ctx.maxBiasVelocity);
                massScale = c.softness.massScale;
                impulseScale = c.softness.impulseScale;
            }
            const float vn = dot(relativeVelocity(a, b, rA, rB), n);
            float impulse = -cp.normalMass * massScale * (vn + bias) - impulseScale * cp.normalImpulse;
            const float newImpulse = std::max(cp.normalImpulse + impulse, 0.0f);
            impulse = newImpulse - cp.normalImpulse;
            cp.normalImpulse = newImpulse;
            cp.maxNormalImpulse = std::max(cp.maxNormalImpulse, impulse);
            totalNormalImpulse += newImpulse;
            applyImpulse(c, a, b, rA, rB, impulse * n);
        }

        // Coulomb friction along t = perp(n): |λt| ≤ μ λn. A conveyor's surfaces move clockwise
        // around their shapes, which is −tangentSpeed along perp(n): the row drives v_rel·t to it.
        const Vec2 t = perp(n);
        for (int i = 0; i < c.pointCount; ++i) {
            ContactConstraintPoint& cp = c.points[i];
            const Vec2 rA = cp.anchorA, rB = cp.anchorB;
            const float vt = dot(relativeVelocity(a, b, rA, rB), t) + c.tangentSpeed;
            const float maxFriction = c.friction * cp.normalImpulse;
            const float newImpulse = std::clamp(cp.tangentImpulse - cp.tangentMass * vt, -maxFriction, maxFriction);
            const float impulse = newImpulse - cp.tangentImpulse;
            cp.tangentImpulse = newImpulse;
            applyImpulse(c, a, b, rA, rB, impulse * t);
        }

        // Rolling resistance: an angular row on ωB − ωA, |λr| ≤ rollingResistance·Σλn.
        if (c.rollingResistance > 0.0f) {
            const float maxLambda = c.rollingResistance * totalNormalImpulse;
            const float lambda = c.rollingImpulse;
            c.rollingImpulse = std::clamp(lambda - c.rollingMass * (b.w - a.w), -maxLambda, maxLambda);
            const float impulse = c.rollingImpulse - lambda;
            a.w -= c.invIA * impulse;
            b.w += c.invIB * impulse;
        }
    }
}

// Hecker's bounce: drive v_rel·n to -e·(v_rel·n before the step), for approaches faster than
// the restitution threshold.
void applyRestitution(World::Impl& w, const StepContext& ctx) {
    std::vector<BodyState>& states = *ctx.states;
    for (ContactConstraint& c : w.constraints) {
        if (c.restitution == 0.0f) continue;
        BodyState& a = states[c.indexA];
        BodyState& b = states[c.indexB];
        for (int i = 0; i < c.pointCount; ++i) {
            ContactConstraintPoint& cp = c.points[i];
            if (cp.relativeVelocity > -ctx.restitutionThreshold || cp.maxNormalImpulse == 0.0f) continue;
            const Vec2 rA = cp.anchorA, rB = cp.anchorB;
            const float vn = dot(relativeVelocity(a, b, rA, rB), c.normal);
            float impulse = -cp.normalMass * (vn + c.restitution * cp.relativeVelocity);
            const float newImpulse = std::max(cp.normalImpulse + impulse, 0.0f);
            impulse = newImpulse - cp.normalImpulse;
            cp.normalImpulse = newImpulse;
            cp.maxNormalImpulse = std::max(cp.maxNormalImpulse, impulse);
            applyImpulse(c, a, b, rA, rB, impulse * c.normal);
        }
    }
}

void storeContactImpulses(World::Impl& w) {
    for (const ContactConstraint& c : w.constraints) {
        Contact& contact = w.contacts[c.contact];
        contact.rollingImpulse = c.rollingImpulse;
        for (int i = 0; i < c.pointCount; ++i) {
            contact.points[i].normalImpulse = c.points[i].normalImpulse;
            contact.points[i].tangentImpulse = c.points[i].tangentImpulse;
            contact.points[i].maxNormalImpulse = c.points[i].maxNormalImpulse;
        }
    }
}

}  // namespace perpdot
