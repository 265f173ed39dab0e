#include "core/contacts/manifold_reuse.hpp"

#include <algorithm>
#include <cmath>

namespace perpdot {

namespace {

// B's centre of mass in A's rotation frame: unchanged while the two move as one.
Vec2 relativeOffset(const Body& a, const Body& b) { return invRotate(a.xf.q, b.center - a.center); }

// Beyond this turn of either body the stored normal is no longer trusted (0.1 rad, under 6°).
constexpr float maxTurn = 0.1f;

}  // namespace

bool reuseManifold(Contact& c, const Body& a, const Body& b, const ReuseLimits& limits) {
    if (!c.reuseValid || !(limits.distance > 0.0f)) return false;
    const float turnA = a.angle - c.reuseAngleA, turnB = b.angle - c.reuseAngleB;
    if (!(std::fabs(turnA) < maxTurn && std::fabs(turnB) < maxTurn)) return false;
    // Travel of the farthest surface point relative to A: the drift of B's centre plus |r| |Δθ_rel|,
    // r the anchors of a kept manifold, or the shapes' reach when there are no points.
    // (One square root: it is monotonic, so the root of the largest |r|² is the largest |r|.)
    float reach = c.pointCount == 0 ? limits.reach : 0.0f;
    if (c.pointCount > 0) {
        float reachSquared = 0.0f;
        for (int i = 0; i < c.pointCount; ++i)
            reachSquared = std::max({reachSquared, lengthSquared(c.points[i].anchorA), lengthSquared(c.points[i].anchorB)});
        reach = std::sqrt(reachSquared);
    }
    const float drift = length(relativeOffset(a, b) - c.reuseOffset) + reach * std::fabs(turnB - turnA);
    // Apart, the shapes were more than the margin apart: travelling less than half of it they
    // stay apart (and reach the speculative margin with half of it to spare).
    const float tolerance = c.pointCount == 0 ? std::min(limits.distance, 0.5f * limits.margin) : limits.distance;
    if (!(drift < tolerance)) return false;
    if (c.pointCount == 0) return true;

    // The material points that met, each anchor turned with its body: R(θ − θ₀) r = R(θ) R(θ₀)ᵀ r.
    Vec2 points[2];
    float separations[2];
    for (int i = 0; i < c.pointCount; ++i) {
        const ContactPointState& p = c.points[i];
        const Vec2 pointA = a.center + rotate(a.xf.q, invRotate(c.reuseRotA, p.anchorA));
        const Vec2 pointB = b.center + rotate(b.xf.q, invRotate(c.reuseRotB, p.anchorB));
        separations[i] = p.baseSeparation + dot(pointB - pointA, c.normal);
        // A new narrowphase would drop a point whose skins no longer overlap (and end the touch).
        if (!(separations[i] <= limits.skinOffset)) return false;
        points[i] = 0.5f * (pointA + pointB);
    }
    for (int i = 0; i < c.pointCount; ++i) {
        c.points[i].separation = separations[i];
        c.points[i].point = points[i];
    }
    return true;
}

void rememberManifoldPose(Contact& c, const Body& a, const Body& b, bool keepable) {
    // Two-point manifolds, or none: a kept manifold never gains a point, so one with a single point
    // would miss the second corner coming down until the pose moved past the tolerance.
    c.reuseValid = c.pointCount == 0 || (keepable && c.pointCount == 2);
    c.reuseOffset = relativeOffset(a, b);
    c.reuseAngleA = a.angle;
    c.reuseAngleB = b.angle;
    // R(θ₀) without a sine and cosine per body: a body's rotation is R(θ) of its angle
    // (body_store.hpp), which is how rememberReuseRotations derives them again after a restore.
    c.reuseRotA = a.xf.q;
    c.reuseRotB = b.xf.q;
    for (int i = 0; i < c.pointCount; ++i) c.points[i].baseSeparation = c.points[i].separation;
}

}  // namespace perpdot
