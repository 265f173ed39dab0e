// Continuous collision against static geometry (Box2D v3's scheme): after the solve, a body that
// moved more than half its smallest extent this step is swept from its step-start pose to its end
// pose with the time of impact (CollisionSystem::timeOfImpact: conservative advancement on
// b2Distance) against the static shapes around the sweep, and moved back to the
// earliest time of impact t < 1. Its velocity is kept: the next step's contact stops it.
// A fast body is swept the same way against the jointed bodies it strikes (hitRatio times lighter,
// at their end poses), once every body is final: without it a heavy ball at 10 m/s (16.7 cm a
// step at 60 Hz) ends its first step 6.7 cm inside a light hinged arm it had no contact with yet,
// which its joint holds in place. A free light body is not swept against: the next step's contact
// pushes it out, where a heavy body moved back at every hit would fall behind its own velocity (a
// motor-driven bar stirring light debris would turn less than its ω·t).
// Bullets against moving bodies: continuous_impacts.cpp.
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/contacts/continuous.hpp"

namespace perpdot {

namespace {

Vec2 middle(const AABB& box) { return 0.5f * (box.lower + box.upper); }

// The world endpoints of a segment or of one chain child.
bool segmentOf(const ShapeData& s, int child, const Transform& xf, Vec2& p1, Vec2& p2) {
    if (auto* segment = std::get_if<Segment>(&s.geometry)) {
        p1 = transformPoint(xf, segment->v1);
        p2 = transformPoint(xf, segment->v2);
        return true;
    }
    if (auto* chain = std::get_if<Chain>(&s.geometry)) {
        const std::vector<Vec2>& v = chain->vertices;
        p1 = transformPoint(xf, v[child]);
        p2 = transformPoint(xf, v[(child + 1) % v.size()]);
        return true;
    }
    return false;
}

// How the centre's path meets a segment. A sweep is needed only when the centre starts in front of
// it and ends within `reach` of it (Nears: some point of the shape, turned any way, may touch) or
// behind it (Crosses). Chains are one-sided: their front is the right of v1→v2.
enum class SegmentPass { Misses, Nears, Crosses };

SegmentPass passOfCentre(Vec2 p1, Vec2 p2, bool oneSided, Vec2 start, Vec2 end, float reach) {
    const Vec2 e = p2 - p1;
    const float len = length(e);
    if (len == 0.0f) return SegmentPass::Misses;
    float d1 = -perpDot(e, start - p1) / len;  // distance in front (right side)
    float d2 = -perpDot(e, end - p1) / len;
    if (!oneSided && d1 < 0.0f) {
        d1 = -d1;
        d2 = -d2;
    }
    if (d1 <= 0.0f || d2 >= reach) return SegmentPass::Misses;
    return d2 < 0.0f ? SegmentPass::Crosses : SegmentPass::Nears;
}

// The earliest time of impact in [0, 1] of the body's shapes along `sweep` with the shapes around
// it that `meets` (a shape's body) accepts, each still at its pose: static shapes (a query of the
// static proxies) or those of bodies it strikes (a query of all).
template <class Meets>
float earliestImpact(const ContinuousWorld& w, int index, const collide::Sweep& sweep, bool staticOnly, Meets&& meets) {
    const Body& b = w.bodies[index];
    const Rot q0 = Rot::fromAngle(sweep.a1), q1 = Rot::fromAngle(sweep.a2);
    const Transform xf0{sweep.c1 - rotate(q0, b.localCenter), q0}, xf1{sweep.c2 - rotate(q1, b.localCenter), q1};
    const collide::CollisionSystem& collision = w.broadphase.collision;
    float t = 1.0f;
    for (int s : b.shapes) {
        const ShapeData& shape = w.shapes[s];
        if (!sweeps(shape)) continue;
        const AABB start = collision.computeAABB(s, 0, xf0), end = collision.computeAABB(s, 0, xf1);
        auto visit = [&](int proxy) {
            const collide::ChildKey key = collision.proxyKey(proxy);
            const ShapeData& other = w.shapes[key.shape];
            if (other.body == index || !meets(other.body)) return true;
            const Body& ob = w.bodies[other.body];
            if (other.sensor || !collide::CollisionSystem::canCollide(shape.type, other.type) ||
                !shouldCollide(shape.filter, other.filter) || !jointAllowsCollision(w.bodies, w.joints, index, other.body))
                return true;
            Vec2 p1, p2;
            SegmentPass pass = SegmentPass::Nears;  // what a non-segment shape is treated as
            if (segmentOf(other, key.child, ob.xf, p1, p2)) {
                pass = passOfCentre(p1, p2, other.type == ShapeType::Chain, middle(start), middle(end), shape.maxExtent);
                if (pass == SegmentPass::Misses) return true;
            }
            const collide::Sweep still{ob.localCenter, ob.center, ob.center, ob.angle, ob.angle};
            float toi = collision.timeOfImpact({s, 0}, sweep, key, still);
            // The shape's core (a circle of a quarter of its extent, which turning does not change)
            // must still not pass when the shape was already touching at the start, or when the
            // centre crossed the segment but the time of impact saw none: a shape turning by
            // radians in one step can defeat its separating-axis advance.
            if (toi == 0.0f || (toi >= 1.0f && pass == SegmentPass::Crosses))
                toi = collision.coreTimeOfImpact(s, 0.25f * shape.minExtent, sweep, key, still);
            if (toi > 0.0f && toi < t) t = toi;
            return true;
        };
        if (staticOnly)
            collision.queryStatic(combine(start, end), visit);
        else
            collision.query(combine(start, end), visit);
    }
    return t;
}

// Back to the pose at the time of impact t < 1 along `sweep`: c = c0 + t (c1 - c0), θ = θ0 + t (θ1 - θ0).
void moveBack(Body& b, const collide::Sweep& sweep, float t) {
    b.center = sweep.c1 + t * (sweep.c2 - sweep.c1);
    b.angle = sweep.a1 + t * (sweep.a2 - sweep.a1);
    b.xf = b.derivedTransform();
}

}  // namespace

float staticImpact(const ContinuousWorld& w, int index, const collide::Sweep& sweep) {
    return earliestImpact(w, index, sweep, true, [](int) { return true; });
}

void solveContinuous(const ContinuousWorld& w, int index, Vec2 c0, float a0) {
    Body& b = w.bodies[index];
    const collide::Sweep sweep{b.localCenter, c0, b.center, a0, b.angle};
    const float t = staticImpact(w, index, sweep);
    if (t < 1.0f) moveBack(b, sweep, t);
}

float lightestJointed(const ContinuousWorld& w) {
    struct Visit {
        const Pool<Body>& bodies;
        float lightest = 0.0f;
    } visit{w.bodies};
    forEachJointPair(
        w.joints,
        [](void* context, int bodyA, int bodyB) {
            Visit& v = *static_cast<Visit*>(context);
            v.lightest = std::max({v.lightest, v.bodies[bodyA].invMass, v.bodies[bodyB].invMass});  // 0 if not dynamic
        },
        &visit);
    return visit.lightest;
}

bool solveStrikes(const ContinuousWorld& w, int index, Vec2 c0, float a0, float lightest) {
    Body& b = w.bodies[index];
    if (lightest < hitRatio * b.invMass) return false;  // no jointed body it could strike: no query
    const SolverBodies& solverBodies = w.scratch.bodies;
    const BoxRoom& known = knownShapes(w.broadphase, w.bodies, w.shapes, index);
    const Vec2 travel = b.center - c0;
    const float turn = std::fabs(b.angle - a0) * known.sweepRadius;
    // A jointed body hitRatio times lighter (dynamic: 1/m of a static or kinematic one is 0),
    // passed by more than fastTravel relative to its own move (a body carried or pushed along is
    // not struck; an asleep one stays where it is).
    const auto struck = [&](int other) {
        const int slot = solverBodies.bodySlots[static_cast<size_t>(other)];
        const float invMass = slot != 0 ? solverBodies.states[static_cast<size_t>(slot)].invMass : w.bodies[other].invMass;
        if (invMass < hitRatio * b.invMass || w.bodies[other].jointCount == 0) return false;
        const Vec2 otherTravel = slot != 0 ? solverBodies.states[static_cast<size_t>(slot)].dp : Vec2{};
        return length(travel - otherTravel) + turn > known.fastTravel;
    };
    const collide::Sweep sweep{b.localCenter, c0, b.center, a0, b.angle};
    const float t = earliestImpact(w, index, sweep, false, struck);
    if (t >= 1.0f) return false;
    moveBack(b, sweep, t);
    return true;
}

}  // namespace perpdot
