// Support loads and rest sinks (support_sinks.hpp): the load path seeded from the top down, and each
// support row's rest sink, low-passed in its contact.
#include "core/solver/support_sinks.hpp"

#include <algorithm>
#include <cmath>

#include "core/solver/contact_prepare.hpp"
#include "core/solver/solver_world.hpp"

namespace perpdot {

namespace {

// The solver slot of the body a contact supports (supportedSide), 0 (the static slot) for none.
int supportedSlot(const SolverBodies& bodies, const ContactConstraint& c, const Contact& contact, Vec2 up) {
    const int side = supportedSide(contact.normal, up, bodies.states[c.indexA].invMass, bodies.states[c.indexB].invMass);
    return side > 0 ? c.indexB : side < 0 ? c.indexA : 0;
}

// Whether every point of the contact touches, has no impulse and closes no faster than gravity adds
// in a step, |v_rel·n| ≤ g h: new and at rest, with nothing to warm-start.
bool isNewAtRest(const SolverBodies& bodies, const ContactConstraint& c, const Contact& contact, float restSpeed) {
    const BodyState &a = bodies.states[c.indexA], &b = bodies.states[c.indexB];
    for (int i = 0; i < c.pointCount; ++i) {
        const ContactPointState& p = contact.points[i];
        if (p.normalImpulse != 0.0f || p.separation > SupportSinks::touching) return false;
        if (std::fabs(dot(relativeVelocity(a, b, p.anchorA, p.anchorB), contact.normal)) > restSpeed) return false;
    }
    return true;
}

// A point's offset along the ground (t = perp(up)) from the centre of its body on `side` (0: A).
float along(const ContactPointState& p, int side, Vec2 up) { return dot(side == 0 ? p.anchorA : p.anchorB, perp(up)); }

}  // namespace

RestSinkTerms restSinkTerms(Vec2 gravity, const StepContext& ctx) {
    RestSinkTerms t;
    const float g = length(gravity);
    t.any = g > 0.0f;
    if (!t.any) return t;
    t.up = (-1.0f / g) * gravity;
    auto perImpulseK = [](const Softness& soft) { return soft.impulseScale > 0.0f ? soft.impulseScale / (soft.massScale * soft.biasRate) : 0.0f; };
    t.sinkPerImpulseKStatic = perImpulseK(ctx.staticSoftness);
    t.sinkPerImpulseK = perImpulseK(ctx.contactSoftness);
    t.alpha = std::min(1.0f, ctx.h / SupportSinks::settleTime);
    return t;
}

namespace {

// Each awake body's supports (SupportScratch::supports): None, AllNew (every support row new and at
// rest, and the body without joints, which carry loads too) or Carrying; and each constraint's
// supported slot. Returns whether some body is AllNew.
bool classifySupports(const SolverWorld& w, const StepContext& ctx, Vec2 up) {
    SupportScratch& s = w.scratch.contacts.support;
    const SolverBodies& bodies = w.scratch.bodies;
    const int count = static_cast<int>(w.scratch.contacts.constraints.size());
    s.supported.assign(static_cast<size_t>(count), 0);
    s.supports.assign(bodies.states.size(), SupportScratch::None);
    const float restSpeed = length(w.gravity) * ctx.h;
    bool anyNew = false;
    for (int k = 0; k < count; ++k) {
        const ContactConstraint& c = w.scratch.contacts.constraints[k];
        const Contact& contact = w.contactCache.contacts[c.contact];
        const int above = supportedSlot(bodies, c, contact, up);
        s.supported[k] = above;
        if (above == 0) continue;
        const bool fresh = isNewAtRest(bodies, c, contact, restSpeed) && w.bodies[bodies.awakeBodies[static_cast<size_t>(above) - 1]].jointCount == 0;
        uint8_t& kind = s.supports[above];
        kind = fresh && kind != SupportScratch::Carrying ? SupportScratch::AllNew : SupportScratch::Carrying;
        anyNew = anyNew || fresh;
    }
    return anyNew;
}

// The AllNew bodies: their support constraints slot by slot (counting sort; `seeded` set), their
// loads — their weight at the centre and what carrying rows hand down to them, with its moment
// about the centre — and their order from the top down.
void gatherSeededBodies(const SolverWorld& w, const StepContext& ctx, Vec2 up) {
    SupportScratch& s = w.scratch.contacts.support;
    const SolverBodies& bodies = w.scratch.bodies;
    const int count = static_cast<int>(w.scratch.contacts.constraints.size());
    const size_t slots = bodies.states.size();
    s.start.assign(slots + 1, 0);
    s.load.assign(slots, 0.0f);
    s.moment.assign(slots, 0.0f);
    s.order.clear();
    const float g = length(w.gravity);
    for (size_t slot = 1; slot < slots; ++slot) {
        if (s.supports[slot] != SupportScratch::AllNew) continue;
        const Body& body = w.bodies[bodies.awakeBodies[slot - 1]];
        s.load[slot] = body.mass * body.gravityScale * g * ctx.hs;
        s.order.push_back(static_cast<int>(slot));
    }
    for (int k = 0; k < count; ++k) {
        const int above = s.supported[k];
        if (above == 0) continue;
        const ContactConstraint& c = w.scratch.contacts.constraints[k];
        if (s.supports[above] == SupportScratch::AllNew) {
            ++s.start[static_cast<size_t>(above) + 1];
            continue;
        }
        const int below = above == c.indexB ? c.indexA : c.indexB;
        if (s.supports[below] != SupportScratch::AllNew) continue;
        const Contact& contact = w.contactCache.contacts[c.contact];
        const float rise = std::fabs(dot(contact.normal, up));
        for (int i = 0; i < c.pointCount; ++i) {
            const float f = contact.points[i].normalImpulse * rise;
            s.load[below] += f;
            s.moment[below] += f * along(contact.points[i], below == c.indexA ? 0 : 1, up);
        }
    }
    for (size_t slot = 1; slot < slots; ++slot) s.start[slot + 1] += s.start[slot];
    s.rows.resize(static_cast<size_t>(s.start[slots]));
    s.fill.assign(s.start.begin(), s.start.end() - 1);
    for (int k = 0; k < count; ++k)
        if (const int above = s.supported[k]; above != 0 && s.supports[above] == SupportScratch::AllNew) {
            s.rows[s.fill[above]++] = k;
            s.seeded[k] = 1;
        }
    auto height = [&](int slot) { return dot(w.bodies[bodies.awakeBodies[static_cast<size_t>(slot) - 1]].center, up); };
    std::sort(s.order.begin(), s.order.end(), [&](int a, int b) {
        const float ha = height(a), hb = height(b);
        return ha != hb ? ha > hb : a < b;
    });
}

// Body `slot`'s load over its support points by the lever rule, λ_j = L(a + b x_j) with Σλ = L and
// Σλx = L x̄ (an equal split where the points do not span a length), none negative: each point's
// warm start λ_j / |n·up|, and λ_j handed on to the body below where that is seeded too.
void splitLoad(const SolverWorld& w, int slot, Vec2 up) {
    SupportScratch& s = w.scratch.contacts.support;
    const float load = s.load[slot];
    if (!(load > 0.0f)) return;
    float n = 0, sx = 0, sxx = 0;
    for (int r = s.start[slot]; r < s.start[slot + 1]; ++r) {
        const ContactConstraint& c = w.scratch.contacts.constraints[s.rows[r]];
        const Contact& contact = w.contactCache.contacts[c.contact];
        for (int i = 0; i < c.pointCount; ++i) {
            const float x = along(contact.points[i], slot == c.indexA ? 0 : 1, up);
            n += 1.0f, sx += x, sxx += x * x;
        }
    }
    const float xBar = s.moment[slot] / load;
    const float det = n * sxx - sx * sx;
    const bool spans = det > 1e-6f * n * n;
    const float a = spans ? (sxx - sx * xBar) / det : 1.0f / n, b = spans ? (n * xBar - sx) / det : 0.0f;
    for (int r = s.start[slot]; r < s.start[slot + 1]; ++r) {
        const ContactConstraint& c = w.scratch.contacts.constraints[s.rows[r]];
        Contact& contact = w.contactCache.contacts[c.contact];
        const float rise = std::fabs(dot(contact.normal, up));
        const int below = slot == c.indexA ? c.indexB : c.indexA;
        for (int i = 0; i < c.pointCount; ++i) {
            ContactPointState& p = contact.points[i];
            const float share = std::max(0.0f, load * (a + b * along(p, slot == c.indexA ? 0 : 1, up)));
            p.normalImpulse = share / rise;
            if (s.supports[below] != SupportScratch::AllNew) continue;
            s.load[below] += share;
            s.moment[below] += share * along(p, below == c.indexA ? 0 : 1, up);
        }
    }
}

}  // namespace

void seedSupportLoads(const SolverWorld& w, const StepContext& ctx) {
    SupportScratch& s = w.scratch.contacts.support;
    s.seeded.assign(w.scratch.contacts.constraints.size(), 0);
    s.reserve(w.scratch.contacts.constraints.size(), w.scratch.bodies.states.size());
    const RestSinkTerms terms = restSinkTerms(w.gravity, ctx);
    if (!ctx.enableWarmStarting || w.contactCache.beganTouching == 0 || !terms.any) return;
    if (!classifySupports(w, ctx, terms.up)) return;
    gatherSeededBodies(w, ctx, terms.up);
    for (const int slot : s.order) splitLoad(w, slot, terms.up);  // from the top down
}

}  // namespace perpdot
