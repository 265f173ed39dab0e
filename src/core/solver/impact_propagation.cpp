// Impacts through chains of touching bodies (impact_propagation.hpp): Hecker's impulse, pair by
// pair, in sweeps over the elastic manifold points.
#include "core/solver/impact_propagation.hpp"

#include <algorithm>

#include "core/solver/contact_prepare.hpp"

namespace perpdot {

namespace {

// A point meets this step when it approaches faster than the restitution threshold (v_rel·n <
// −threshold, v_rel of the free velocities, as restitution reads it), would rebound faster than
// it too (−e v_rel·n > threshold: a slower rebound is a plastic impact, which the substeps solve
// for a whole pile at once), and closes its gap within the step (s ≤ −v_rel·n h). Returns
// v_rel·n, or 0 when the point does not meet.
float meetingSpeed(const ImpactPoint& p, const BodyState& a, const BodyState& b, const StepContext& ctx) {
    const float vn = dot(relativeVelocity(a, b, p.rA, p.rB), p.normal);
    const bool bounces = vn < -ctx.restitutionThreshold && -p.restitution * vn > ctx.restitutionThreshold;
    return bounces && p.separation <= -vn * ctx.h ? vn : 0.0f;
}

// Impulse P at anchor r of a body: v += P/m, ω += perpDot(r, P)/I.
void kick(BodyState& body, float invI, Vec2 r, Vec2 P) {
    body.v = body.v + body.invMass * P;
    body.w = body.w + invI * perpDot(r, P);
}

// Point p takes its impact if it meets: j = −(1 + e) v_rel·n / K alone, and Coulomb friction
// along t = perp(n), |jt| ≤ μ j, on the free velocities and the solver states alike. With e = 1 and
// no friction a pair of equal masses swaps its velocities along n, and kinetic energy is kept.
bool impact(SolverBodies& bodies, Impacts& impacts, ImpactPoint& p, int sweep, const StepContext& ctx) {
    BodyState &a = bodies.freeVelocities[p.slotA], &b = bodies.freeVelocities[p.slotB];
    const float vn = meetingSpeed(p, a, b, ctx);
    if (vn == 0.0f) return false;
    const RowMasses m = rowMasses(bodies, p.slotA, p.slotB);
    auto apply = [&](Vec2 P) {
        kick(a, m.invIA, p.rA, -P);
        kick(b, m.invIB, p.rB, P);
        kick(bodies.states[p.slotA], m.invIA, p.rA, -P);
        kick(bodies.states[p.slotB], m.invIB, p.rB, P);
    };
    p.impactSpeed = std::max(p.impactSpeed, -vn);
    const float j = -(1.0f + p.restitution) * vn * effectiveMass(m, p.rA, p.rB, p.normal);
    apply(j * p.normal);
    const Vec2 t = perp(p.normal);
    const float maxFriction = p.friction * j;
    const float jt = -dot(relativeVelocity(a, b, p.rA, p.rB), t) * effectiveMass(m, p.rA, p.rB, t);
    apply(std::clamp(jt, -maxFriction, maxFriction) * t);
    impacts.lastKick[p.slotA] = impacts.lastKick[p.slotB] = sweep;
    return true;
}

// The first sweep, which finds the points as it goes: the manifold points of the step's elastic
// contacts between two moving bodies, in contact order. A contact with a body outside the solver,
// static, kinematic or asleep, has nothing to pass an impact on to: the restitution pass bounces
// it. Returns the number of impacts.
size_t firstSweep(const SolverWorld& w, const StepContext& ctx) {
    const SolverWorld::Scratch& s = w.scratch;
    size_t impacts = 0;
    for (int k = 0; k < static_cast<int>(s.contacts.constraints.size()); ++k) {
        const ContactConstraint& c = s.contacts.constraints[k];
        if (c.indexA == 0 || c.indexB == 0) continue;
        if (s.bodies.states[c.indexA].invMass == 0.0f || s.bodies.states[c.indexB].invMass == 0.0f) continue;
        const Contact& contact = w.contactCache.contacts[c.contact];
        if (contact.restitution == 0.0f) continue;
        for (int i = 0; i < c.pointCount; ++i) {
            const ContactPointState& p = contact.points[i];
            ImpactPoint& point = s.contacts.impacts.points.emplace_back(ImpactPoint{.constraint = k,
                                                                           .point = i,
                                                                           .slotA = c.indexA,
                                                                           .slotB = c.indexB,
                                                                           .rA = p.anchorA,
                                                                           .rB = p.anchorB,
                                                                           .normal = contact.normal,
                                                                           .separation = p.separation,
                                                                           .restitution = contact.restitution,
                                                                           .friction = contact.friction});
            impacts += impact(s.bodies, s.contacts.impacts, point, 0, ctx) ? 1 : 0;
        }
    }
    return impacts;
}

}  // namespace

void propagateImpacts(const SolverWorld& w, const StepContext& ctx) {
    const SolverWorld::Scratch& s = w.scratch;
    std::vector<ImpactPoint>& points = s.contacts.impacts.points;
    points.clear();
    if (!w.anyRestitution) return;  // no shape has ever been elastic: nothing to look for
    // In order of impact: sweeps in contact order until no point meets, at most 4 impacts per
    // point; what still approaches then is left to the substeps and the restitution pass. After
    // the first sweep a point whose bodies no impact has changed since it was last looked at (in
    // this sweep or the one before) cannot meet either: it is skipped, as a full sweep would pass it.
    s.contacts.impacts.lastKick.assign(s.bodies.states.size(), -1);
    size_t impacts = firstSweep(w, ctx);
    const size_t maxImpacts = 4 * points.size();
    for (int sweep = 1, met = impacts > 0; met && impacts < maxImpacts; ++sweep) {
        met = 0;
        for (ImpactPoint& p : points) {
            const std::vector<int>& lastKick = s.contacts.impacts.lastKick;
            if (lastKick[p.slotA] < sweep - 1 && lastKick[p.slotB] < sweep - 1) continue;
            if (!impact(s.bodies, s.contacts.impacts, p, sweep, ctx)) continue;
            met = 1;
            if (++impacts == maxImpacts) break;
        }
    }
}

}  // namespace perpdot
