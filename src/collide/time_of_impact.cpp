// Conservative advancement (Mirtich 1996) on b2Distance. At time t, b2Distance gives the distance
// d between the cores and the unit normal n from A's closest point to B's. The separation along
// the fixed axis n shrinks no faster than
//     n·(v_A − v_B) + |ω_A| r_A + |ω_B| r_B
// (v = c2 − c1 and ω = a2 − a1 per unit of t, r the largest distance from the centre of mass to a
// core vertex), and the distance is never less than the separation along any axis, so advancing by
//     Δt = (d − target) / (n·(v_A − v_B) + |ω_A| r_A + |ω_B| r_B)
// cannot step past the target. Every Box2D call here is b2Distance, which has no reachable
// assertion; a non-finite distance ends the search as "no impact".
#include "collide/time_of_impact.hpp"

#include <algorithm>
#include <cmath>

namespace perpdot::collide {

namespace {

constexpr float tolerance = 0.25f * linearSlop;  // Box2D's TOI tolerance
// Each advance leaves the shapes apart, so stopping early is safe (the body stops short of the
// impact for this step); grazing or spinning sweeps converge slowest.
constexpr int maxIterations = 64;

b2Transform poseAt(const Sweep& s, float t) {
    const float angle = s.a1 + t * (s.a2 - s.a1);
    const Rot q = Rot::fromAngle(angle);
    const Vec2 p = s.c1 + t * (s.c2 - s.c1) - rotate(q, s.localCenter);
    b2Transform xf;
    xf.p.Set(p.x, p.y);
    xf.q.c = q.c;
    xf.q.s = q.s;
    return xf;
}

// Largest distance from the body's centre of mass to a vertex of the proxy (body frame).
float reach(const b2DistanceProxy& proxy, Vec2 localCenter) {
    float r2 = 0.0f;
    for (int i = 0; i < proxy.m_count; ++i)
        r2 = std::max(r2, lengthSquared(Vec2{proxy.m_vertices[i].x, proxy.m_vertices[i].y} - localCenter));
    return std::sqrt(r2);
}

}  // namespace

float advanceToImpact(const b2DistanceProxy& a, const Sweep& sweepA, const b2DistanceProxy& b, const Sweep& sweepB) {
    // Box2D's target: the cores a little (3 slop) inside the rounded surfaces' touching distance.
    const float target = std::max(linearSlop, a.m_radius + b.m_radius - 3.0f * linearSlop);
    const Vec2 velocityAB = (sweepA.c2 - sweepA.c1) - (sweepB.c2 - sweepB.c1);
    const float spinSpeed = std::fabs(sweepA.a2 - sweepA.a1) * reach(a, sweepA.localCenter) +
                            std::fabs(sweepB.a2 - sweepB.a1) * reach(b, sweepB.localCenter);
    b2DistanceInput input;
    input.proxyA = a;
    input.proxyB = b;
    input.useRadii = false;
    b2SimplexCache cache;
    cache.count = 0;
    const Advanced advanced = conservativeAdvance(
        [&](float at, int) {
            input.transformA = poseAt(sweepA, at);
            input.transformB = poseAt(sweepB, at);
            b2DistanceOutput output;
            b2Distance(&output, &cache, &input);
            const float d = output.distance;
            if (!std::isfinite(d)) return Advance{.stop = true};
            if (d < target + tolerance) return Advance{.gap = d - target};  // at the impact: no axis needed
            const Vec2 n = (1.0f / d) * Vec2{output.pointB.x - output.pointA.x, output.pointB.y - output.pointA.y};
            return Advance{.gap = d - target, .closingSpeed = dot(n, velocityAB) + spinSpeed};
        },
        tolerance, 1.0f, maxIterations);
    // Out of iterations mid-way it stops short (safe); no impact is t = 1.
    return advanced.outcome == Advanced::None ? 1.0f : advanced.t;
}

}  // namespace perpdot::collide
