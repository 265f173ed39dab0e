// Continuous collision against static geometry (Box2D v3's scheme): after the solve, a body that
// moved more than half its smallest extent this step is swept from its step-start pose to its end
// pose with the time of impact (CollisionSystem::timeOfImpact: conservative advancement on
// b2Distance) against the static shapes around the sweep, and moved back to the
// earliest time of impact t < 1. Its velocity is kept: the next step's contact stops it.
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

}  // namespace

float staticImpact(const ContinuousWorld& w, int index, const collide::Sweep& sweep) {
    const Body& b = w.bodies[index];
    const Rot q0 = Rot::fromAngle(sweep.a1), q1 = Rot::fromAngle(sweep.a2);
    const Transform xf0{sweep.c1 - rotate(q0, b.localCenter), q0}, xf1{sweep.c2 - rotate(q1, b.localCenter), q1};
    float t = 1.0f;
    for (int s : b.shapes) {
        const ShapeData& shape = w.shapes[s];
        if (!sweeps(shape)) continue;
        const AABB start = w.broadphase.collision.computeAABB(s, 0, xf0), end = w.broadphase.collision.computeAABB(s, 0, xf1);
        w.broadphase.collision.queryStatic(combine(start, end), [&](int proxy) {
            const collide::ChildKey key = w.broadphase.collision.proxyKey(proxy);
            const ShapeData& other = w.shapes[key.shape];
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
            float toi = w.broadphase.collision.timeOfImpact({s, 0}, sweep, key, still);
            // The shape's core (a circle of a quarter of its extent, which turning does not change)
            // must still not pass when the shape was already touching at the start, or when the
            // centre crossed the segment but the time of impact saw none: a shape turning by
            // radians in one step can defeat its separating-axis advance.
            if (toi == 0.0f || (toi >= 1.0f && pass == SegmentPass::Crosses))
                toi = w.broadphase.collision.coreTimeOfImpact(s, 0.25f * shape.minExtent, sweep, key, still);
            if (toi > 0.0f && toi < t) t = toi;
            return true;
        });
    }
    return t;
}

void solveContinuous(const ContinuousWorld& w, int index, Vec2 c0, float a0) {
    Body& b = w.bodies[index];
    const float t = staticImpact(w, index, {b.localCenter, c0, b.center, a0, b.angle});
    if (t >= 1.0f) return;
    // Back to the pose at the time of impact: c = c0 + t (c1 - c0), θ = θ0 + t (θ1 - θ0).
    b.center = c0 + t * (b.center - c0);
    b.angle = a0 + t * (b.angle - a0);
    b.xf = b.derivedTransform();
}

}  // namespace perpdot
