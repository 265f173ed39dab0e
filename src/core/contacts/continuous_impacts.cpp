// Continuous collision between moving bodies: a bullet against another bullet or any moving body.
//
// Sweeping a bullet against the others' final poses (as against static shapes) misses two bodies
// that cross: each ends where the other started. Instead every fast body of the step is a Mover
// whose centre and angle go linearly from its step-start pose to its end pose; the bodies a fast
// mover's swept box meets become movers too, and each pair with a bullet in it gets a time of
// impact on both moving sweeps (CollisionSystem::timeOfImpact). Impacts are then taken in time order (Box2D 2.4's
// b2World::SolveTOI takes the same order, but solves a small island at each one):
//   1. both bodies go to their poses at the time of impact t, and the manifold there gives the
//      normal n (A to B) and the contact points;
//   2. Hecker's collision impulse at each point, j = -(1+e) v_rel·n / (1/mA + 1/mB +
//      perpDot(rA,n)²/IA + perpDot(rB,n)²/IB), accumulated and clamped (λn ≥ 0) over a few
//      sweeps of the points, with Coulomb friction |λt| ≤ μ λn; equal and opposite, so momentum
//      is kept;
//   3. the time of impact leaves the shapes 3 linear slops inside each other's radius (Box2D's target); the pair goes
//      back along its paths by depth / approach speed, to where the surfaces first touched;
//   4. both move on with their new velocities for the rest of the step, and their new paths are
//      swept again (against static shapes and their other pairs).
// A bullet whose first impact is with a static shape stops there for the rest of the step and
// keeps its velocity, as in continuous.cpp.
#include <algorithm>
#include <cmath>
#include <tuple>

#include "core/contacts/contact_cache.hpp"
#include "core/contacts/continuous.hpp"
#include "core/joints/joint.hpp"
#include "core/bodies/speed_limits.hpp"

namespace perpdot {

namespace {

constexpr int impulseSweeps = 64;     // passes over a manifold's (at most two) points: 8 left a 0.05 m box
                                      // closing on a 1 m box (1 : 400) at 1.2 m/s after the impact
constexpr int impactsPerMover = 4;    // bound on the impacts taken per step, per mover and per pair
constexpr float coreFraction = 0.25f; // of the smallest extent: the disc swept when shapes touch at the start

// Fraction of the mover's path at step time t: the path starts at t0 and ends at 1.
float along(const Mover& m, float t) { return m.t0 < 1.0f ? (t - m.t0) / (1.0f - m.t0) : 0.0f; }
Vec2 centerAt(const Mover& m, float t) { return m.c0 + along(m, t) * (m.c1 - m.c0); }
float angleAt(const Mover& m, float t) { return m.a0 + along(m, t) * (m.a1 - m.a0); }
Transform frameAt(const Mover& m, Vec2 localCenter, float t) {
    const Rot q = Rot::fromAngle(angleAt(m, t));
    return {centerAt(m, t) - rotate(q, localCenter), q};
}
// The path from step time t to the end of the step, for the time of impact (which measures in [0, 1]).
collide::Sweep sweepFrom(const Mover& m, Vec2 localCenter, float t) {
    return {localCenter, centerAt(m, t), m.c1, angleAt(m, t), m.a1};
}
// A time of impact measured on [t, 1], as a step time.
float stepTime(float t, float toi) { return toi < 1.0f ? t + toi * (1.0f - t) : 1.0f; }

// The mover's path restarted at step time t, from its pose there (its end to be set).
void restartAt(Mover& m, float t) {
    m.c0 = centerAt(m, t);
    m.a0 = angleAt(m, t);
    m.t0 = t;
    m.moved = true;
}

// One contact point of an impact: anchors from each centre of mass and the rows' effective masses.
struct ImpactPoint {
    Vec2 rA, rB;
    float normalMass = 0, tangentMass = 0;  // 1 / (1/mA + 1/mB + perpDot(rA,d)²/IA + perpDot(rB,d)²/IB)
    float targetSpeed = 0;                  // -e v_rel·n before the impact (0 below the threshold)
    float normalImpulse = 0, tangentImpulse = 0;
};

float effectiveMass(const Body& a, const Body& b, Vec2 rA, Vec2 rB, Vec2 d) {
    const float rnA = perpDot(rA, d), rnB = perpDot(rB, d);
    const float k = a.invMass + b.invMass + a.invInertia * rnA * rnA + b.invInertia * rnB * rnB;
    return k > 0.0f ? 1.0f / k : 0.0f;
}

Vec2 relativeVelocity(const Mover& a, const Mover& b, const ImpactPoint& p) {
    return pointVelocity(b.v, b.w, p.rB) - pointVelocity(a.v, a.w, p.rA);
}

// j applied as vA -= j/mA, ωA -= perpDot(rA, j)/IA, and + for B.
void applyImpulse(Mover& a, const Body& ba, Mover& b, const Body& bb, const ImpactPoint& p, Vec2 j) {
    a.v -= ba.invMass * j;
    a.w -= ba.invInertia * perpDot(p.rA, j);
    b.v += bb.invMass * j;
    b.w += bb.invInertia * perpDot(p.rB, j);
}

// Movers and pairs: the fast movers are in `movers` already; the bodies their swept boxes meet
// are added, and every pair with a bullet in it is listed once.
void collectMoverPairs(const ContinuousWorld& w) {
    std::vector<Mover>& movers = w.scratch.continuous.movers;
    std::vector<MoverPair>& moverPairs = w.scratch.continuous.pairs;
    std::vector<int>& moverOfBody = w.scratch.continuous.moverOfBody;
    moverPairs.clear();
    moverOfBody.assign(w.bodies.capacity(), -1);
    const int fastCount = static_cast<int>(movers.size());
    for (int i = 0; i < fastCount; ++i) {
        Mover& m = movers[i];
        moverOfBody[m.body] = i;
        const Body& b = w.bodies[m.body];
        const Rot q0 = Rot::fromAngle(m.a0);
        const Transform xf0{m.c0 - rotate(q0, b.localCenter), q0};
        bool first = true;
        for (int s : b.shapes)
            for (int child = 0; child < w.broadphase.collision.childCount(s); ++child) {
                const AABB box = combine(w.broadphase.collision.computeAABB(s, child, xf0), w.broadphase.collision.computeAABB(s, child, b.xf));
                m.swept = first ? box : combine(m.swept, box);
                first = false;
            }
    }
    const auto addPair = [&](int a, int b) { moverPairs.push_back({.a = std::min(a, b), .b = std::max(a, b)}); };
    for (int i = 0; i < fastCount; ++i) {
        if (w.bodies[movers[i].body].shapes.empty()) continue;
        const bool bullet = w.bodies[movers[i].body].bullet;
        // Slower bodies: their fat boxes in the tree hold their whole (short) paths.
        w.broadphase.collision.query(movers[i].swept, [&](int proxy) {
            const int other = w.shapes[w.broadphase.collision.proxyKey(proxy).shape].body;
            const Body& o = w.bodies[other];
            if (other == movers[i].body || o.type == BodyType::Static || !(bullet || o.bullet)) return true;
            int m = moverOfBody[other];
            if (m >= 0 && m < fastCount) return true;  // fast against fast: below
            if (m < 0) {
                const int slot = w.scratch.bodies.bodySlots[other];
                const BodyState& s = w.scratch.bodies.states[slot];  // slot 0 (asleep): no motion
                const Vec2 c0 = o.center - s.dp;
                const float a0 = o.angle - w.scratch.bodies.stepRotation[slot];
                m = static_cast<int>(movers.size());
                movers.push_back({.body = other, .c0 = c0, .c1 = o.center, .a0 = a0, .a1 = o.angle, .v = o.v,
                                  .w = o.w, .stepStart = c0});
                moverOfBody[other] = m;
            }
            addPair(i, m);
            return true;
        });
        // Other fast bodies: their swept boxes.
        for (int j = i + 1; j < fastCount; ++j)
            if ((bullet || w.bodies[movers[j].body].bullet) && overlaps(movers[i].swept, movers[j].swept)) addPair(i, j);
    }
    std::sort(moverPairs.begin(), moverPairs.end(), [](const MoverPair& x, const MoverPair& y) {
        return std::tie(x.a, x.b) < std::tie(y.a, y.b);
    });
    moverPairs.erase(std::unique(moverPairs.begin(), moverPairs.end(),
                                 [](const MoverPair& x, const MoverPair& y) { return x.a == y.a && x.b == y.b; }),
                     moverPairs.end());
}

// The pair's first time of impact after step time t (1: none), and the children that meet.
void pairImpact(const ContinuousWorld& w, MoverPair& pair, float t) {
    const std::vector<Mover>& movers = w.scratch.continuous.movers;
    const Mover& a = movers[pair.a];
    const Mover& b = movers[pair.b];
    const Body& ba = w.bodies[a.body];
    const Body& bb = w.bodies[b.body];
    pair.time = 1.0f;
    if (!jointAllowsCollision(w.bodies, w.joints, a.body, b.body)) return;
    const collide::Sweep sweepA = sweepFrom(a, ba.localCenter, t), sweepB = sweepFrom(b, bb.localCenter, t);
    float first = 1.0f;
    // The swept shape `s` (of the body moving along `sweep`) against every child of `other`.
    const auto sweepShape = [&](int s, const collide::Sweep& sweep, int other, const collide::Sweep& otherSweep, bool isA) {
        for (int child = 0; child < w.broadphase.collision.childCount(other); ++child) {
            const collide::ChildKey key{other, child};
            float toi = w.broadphase.collision.timeOfImpact({s, 0}, sweep, key, otherSweep);
            // Touching at the start: the shape's core must still not pass through.
            if (toi == 0.0f) toi = w.broadphase.collision.coreTimeOfImpact(s, coreFraction * w.shapes[s].minExtent, sweep, key, otherSweep);
            if (toi > 0.0f && toi < first) {
                first = toi;
                pair.keyA = isA ? collide::ChildKey{s, 0} : key;
                pair.keyB = isA ? key : collide::ChildKey{s, 0};
            }
        }
    };
    for (int sa : ba.shapes)
        for (int sb : bb.shapes) {
            const ShapeData& shapeA = w.shapes[sa];
            const ShapeData& shapeB = w.shapes[sb];
            if (shapeA.sensor || shapeB.sensor || !collide::CollisionSystem::canCollide(shapeA.type, shapeB.type) ||
                !shouldCollide(shapeA.filter, shapeB.filter))
                continue;
            if (sweeps(shapeA)) sweepShape(sa, sweepA, sb, sweepB, true);
            if (sweeps(shapeB)) sweepShape(sb, sweepB, sa, sweepA, false);
        }
    pair.time = stepTime(t, first);
}

// The impact of the pair at step time t: Hecker's impulse at the manifold's points, the pair
// moved back to first touch, and new paths for the rest of the step.
void resolveImpact(const ContinuousWorld& w, const MoverPair& pair, float t, const StepContext& ctx) {
    const float h = ctx.h;
    std::vector<Mover>& movers = w.scratch.continuous.movers;
    Mover& a = movers[pair.a];
    Mover& b = movers[pair.b];
    const Body& ba = w.bodies[a.body];
    const Body& bb = w.bodies[b.body];
    const Transform xfA = frameAt(a, ba.localCenter, t), xfB = frameAt(b, bb.localCenter, t);
    const ShapeData& shapeA = w.shapes[pair.keyA.shape];
    const ShapeData& shapeB = w.shapes[pair.keyB.shape];
    const bool swap = collide::CollisionSystem::mustSwap(shapeA.type, shapeB.type);
    // Box2D's separations: the time of impact stops at Box2D's target distance in skin terms, and
    // going back by the skin overlap leaves the pair a skin apart, never inside each other.
    constexpr collide::Skin skin = collide::Skin::Box2D;
    const collide::Manifold manifold =
        swap ? w.broadphase.collision.collide(pair.keyB, xfB, pair.keyA, xfA, skin) : w.broadphase.collision.collide(pair.keyA, xfA, pair.keyB, xfB, skin);
    if (manifold.pointCount == 0) {  // nothing to push on: both wait at the impact (continuous.cpp's answer)
        for (Mover* m : {&a, &b}) {
            restartAt(*m, t);
            m->c1 = m->c0, m->a1 = m->a0;
            m->sweepStatic = true;
        }
        return;
    }
    const Vec2 cA = xfA.p + rotate(xfA.q, ba.localCenter), cB = xfB.p + rotate(xfB.q, bb.localCenter);
    const Vec2 n = swap ? -manifold.normal : manifold.normal;  // from A to B
    const Vec2 tangent = perp(n);
    const float friction = mixFriction(shapeA.friction, shapeB.friction);
    const float restitution = mixRestitution(shapeA.restitution, shapeB.restitution);
    ImpactPoint points[2];
    float backTime = 0.0f;  // seconds back to the first touch
    for (int i = 0; i < manifold.pointCount; ++i) {
        ImpactPoint& p = points[i];
        p.rA = manifold.points[i].point - cA;
        p.rB = manifold.points[i].point - cB;
        p.normalMass = effectiveMass(ba, bb, p.rA, p.rB, n);
        p.tangentMass = effectiveMass(ba, bb, p.rA, p.rB, tangent);
        const float vn = dot(relativeVelocity(a, b, p), n);
        p.targetSpeed = vn < -ctx.restitutionThreshold ? -restitution * vn : 0.0f;
        // Depth over approach speed: how long ago this point's surfaces touched.
        if (manifold.points[i].separation < 0.0f && vn < 0.0f) backTime = std::max(backTime, manifold.points[i].separation / vn);
    }
    for (int sweep = 0; sweep < impulseSweeps; ++sweep)
        for (int i = 0; i < manifold.pointCount; ++i) {
            ImpactPoint& p = points[i];
            // Normal: λn += -(v_rel·n - target) / K, clamped to λn ≥ 0.
            const float vn = dot(relativeVelocity(a, b, p), n);
            const float normal = std::max(p.normalImpulse - p.normalMass * (vn - p.targetSpeed), 0.0f);
            applyImpulse(a, ba, b, bb, p, (normal - p.normalImpulse) * n);
            p.normalImpulse = normal;
            // Friction: λt += -v_rel·t / K, clamped to |λt| ≤ μ λn.
            const float vt = dot(relativeVelocity(a, b, p), tangent);
            const float limit = friction * p.normalImpulse;
            const float tangential = std::clamp(p.tangentImpulse - p.tangentMass * vt, -limit, limit);
            applyImpulse(a, ba, b, bb, p, (tangential - p.tangentImpulse) * tangent);
            p.tangentImpulse = tangential;
        }
    // An impulse that overflowed (a restitution or masses far beyond any game's) leaves NaN: the
    // pair stops where it met and is frozen at the end, as finalizeBodies freezes a body whose
    // motion went non-finite, and no NaN path is ever swept (Box2D's time of impact asserts).
    if (!isFinite(a.v) || !std::isfinite(a.w) || !isFinite(b.v) || !std::isfinite(b.w)) {
        for (Mover* m : {&a, &b}) {
            restartAt(*m, t);
            m->c1 = m->c0, m->a1 = m->a0;
            m->v = {}, m->w = 0.0f;
            m->frozen = true;
        }
        return;
    }
    // The integration's speed limits hold here too (speed_limits.hpp).
    for (Mover* m : {&a, &b}) {
        m->v = clampSpeed(m->v, ctx.maxLinearSpeed);
        m->w = clampAngularSpeed(m->w, maxAngularSpeed(ctx.invHs));
    }
    // Back along the old paths to the first touch (not before either path began), then on with the
    // new velocities: c1 = c(t') + (1 - t') h v, θ1 = θ(t') + (1 - t') h ω.
    const float touch = std::max({t - backTime / h, a.t0, b.t0});
    for (Mover* m : {&a, &b}) {
        restartAt(*m, touch);
        m->c1 = m->c0 + ((1.0f - touch) * h) * m->v;
        m->a1 = m->a0 + (1.0f - touch) * h * m->w;
        m->sweepStatic = true;
    }
}

}  // namespace

void solveMovingImpacts(const ContinuousWorld& w, const StepContext& ctx) {
    collectMoverPairs(w);
    std::vector<Mover>& movers = w.scratch.continuous.movers;
    std::vector<MoverPair>& moverPairs = w.scratch.continuous.pairs;
    for (Mover& m : movers) m.sweepStatic = m.fast && w.bodies[m.body].bullet;  // the others were swept already
    float now = 0.0f;
    const int maxImpacts = impactsPerMover * static_cast<int>(movers.size() + moverPairs.size());
    for (int impact = 0; impact < maxImpacts; ++impact) {
        // The earliest impact after `now`: a pair's, or a mover's with static shapes.
        float first = 1.0f;
        int firstPair = -1, firstStatic = -1;
        for (int i = 0; i < static_cast<int>(moverPairs.size()); ++i) {
            MoverPair& p = moverPairs[i];
            if (p.dirty) pairImpact(w, p, now), p.dirty = false;
            if (p.time < first) first = p.time, firstPair = i, firstStatic = -1;
        }
        for (int i = 0; i < static_cast<int>(movers.size()); ++i) {
            Mover& m = movers[i];
            if (m.sweepStatic) {
                m.staticTime = stepTime(now, staticImpact(w, m.body, sweepFrom(m, w.bodies[m.body].localCenter, now)));
                m.sweepStatic = false;
            }
            if (m.staticTime < first) first = m.staticTime, firstStatic = i, firstPair = -1;
        }
        if (first >= 1.0f) break;
        now = first;
        int changedA = firstStatic, changedB = firstStatic;
        if (firstStatic >= 0) {  // stops at the static shape for the rest of the step, keeping its velocity
            Mover& m = movers[firstStatic];
            restartAt(m, now);
            m.c1 = m.c0, m.a1 = m.a0;
            m.staticTime = 1.0f;
        } else {
            const MoverPair& p = moverPairs[firstPair];
            resolveImpact(w, p, now, ctx);
            changedA = p.a, changedB = p.b;
        }
        for (MoverPair& p : moverPairs)
            if (p.a == changedA || p.b == changedA || p.a == changedB || p.b == changedB) p.dirty = true;
    }
    // The movers' ends into their bodies; the broadphase follows (fast bullets were not synchronised yet).
    for (const Mover& m : movers) {
        Body& b = w.bodies[m.body];
        if (!m.moved && !(m.fast && b.bullet)) continue;
        if (m.moved && !b.awake) wakeIsland(w.bodies, m.body);
        b.center = m.c1;
        b.angle = m.a1;
        b.xf = b.derivedTransform();
        b.v = m.v;
        b.w = m.w;
        if (m.frozen) freeze(b, w.frozenBodies);
        w.broadphase.synchronizeProxies(w.shapes, w.bodies, m.body, b.xf, b.center - m.stepStart);
    }
}

}  // namespace perpdot
