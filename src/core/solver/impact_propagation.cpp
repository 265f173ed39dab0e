#include "core/solver/impact_propagation.hpp"

#include <algorithm>

#include "core/solver/contact_prepare.hpp"
#include "core/world/world_impl.hpp"

namespace perpdot {

namespace {

// The manifold points of the step's elastic contacts between two moving bodies, in contact order.
// A contact with a body outside the solver, static, kinematic or asleep, has nothing to pass an
// impact on to: the restitution pass bounces it.
void findImpactPoints(const World::Impl& w, std::vector<ImpactPoint>& points) {
    const StepScratch& s = w.scratch;
    for (int k = 0; k < static_cast<int>(s.constraints.size()); ++k) {
        const ContactConstraint& c = s.constraints[k];
        if (c.indexA == 0 || c.indexB == 0) continue;
        const RowMasses m = rowMasses(s, c.indexA, c.indexB);
        if (m.invMassA == 0.0f || m.invMassB == 0.0f) continue;
        const Contact& contact = w.contactCache.contacts[c.contact];
        if (contact.restitution == 0.0f) continue;
        for (int i = 0; i < c.pointCount; ++i) {
            const ContactPointState& p = contact.points[i];
            points.push_back({.constraint = k,
                              .point = i,
                              .slotA = c.indexA,
                              .slotB = c.indexB,
                              .rA = p.anchorA,
                              .rB = p.anchorB,
                              .normal = contact.normal,
                              .separation = p.separation,
                              .restitution = contact.restitution,
                              .friction = contact.friction,
                              .invIA = m.invIA,
                              .invIB = m.invIB,
                              .normalMass = effectiveMass(m, p.anchorA, p.anchorB, contact.normal),
                              .tangentMass = effectiveMass(m, p.anchorA, p.anchorB, perp(contact.normal))});
        }
    }
}

// Impulse P at anchor r of a body: v += P/m, ω += perpDot(r, P)/I.
void kick(BodyState& body, float invI, Vec2 r, Vec2 P) {
    body.v = body.v + body.invMass * P;
    body.w = body.w + invI * perpDot(r, P);
}

}  // namespace

void propagateImpacts(World::Impl& w, const StepContext& ctx) {
    StepScratch& s = w.scratch;
    std::vector<ImpactPoint>& points = s.impactPoints;
    points.clear();
    if (!w.shapes.anyRestitution) return;  // no shape has ever been elastic: nothing to look for
    findImpactPoints(w, points);
    // In order of impact: a point meets when it approaches faster than the restitution threshold
    // (v_rel·n < −threshold, v_rel of the free velocities, as restitution reads it) and closes its
    // gap within the step (s ≤ −v_rel·n h); it takes j = −(1 + e) v_rel·n / K alone, and Coulomb
    // friction along t = perp(n), |jt| ≤ μ j. With e = 1 and no friction a pair of equal masses
    // swaps its velocities along n, and kinetic energy is kept at every impact. Sweeps in contact order until none meets, at most 4 impacts per point: what is still
    // approaching then is left to the substeps and the restitution pass.
    const size_t maxImpacts = 4 * points.size();
    size_t impacts = 0;
    for (bool met = true; met && impacts < maxImpacts;) {
        met = false;
        for (ImpactPoint& p : points) {
            BodyState &a = s.freeVelocities[p.slotA], &b = s.freeVelocities[p.slotB];
            const float vn = dot(relativeVelocity(a, b, p.rA, p.rB), p.normal);
            if (vn >= -ctx.restitutionThreshold || p.separation > -vn * ctx.h) continue;
            auto apply = [&](Vec2 P) {
                kick(a, p.invIA, p.rA, -P);
                kick(b, p.invIB, p.rB, P);
                kick(s.states[p.slotA], p.invIA, p.rA, -P);
                kick(s.states[p.slotB], p.invIB, p.rB, P);
            };
            p.impactSpeed = std::max(p.impactSpeed, -vn);
            const float j = -(1.0f + p.restitution) * vn * p.normalMass;
            apply(j * p.normal);
            const Vec2 t = perp(p.normal);
            const float maxFriction = p.friction * j;
            apply(std::clamp(-dot(relativeVelocity(a, b, p.rA, p.rB), t) * p.tangentMass, -maxFriction, maxFriction) * t);
            met = true;
            if (++impacts == maxImpacts) break;
        }
    }
}

}  // namespace perpdot
