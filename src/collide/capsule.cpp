// Capsules on Box2D 2.4's polygon routines (see capsule_b2.hpp for what needs help and why).
#include "collide/capsule_b2.hpp"

#include <box2d/b2_circle_shape.h>
#include <box2d/b2_distance.h>
#include <box2d/b2_edge_shape.h>

#include <algorithm>

namespace perpdot::collide {

namespace {

// Closest features must be within this angle of Box2D's face normal to keep its clipped manifold.
constexpr float sameNormalCos = 0.995f;  // ~5.7°
// Cores closer than this overlap: b2Distance gives no direction, Box2D's separating axis is kept.
constexpr float coreContact = 0.1f * b2_linearSlop;

// The manifold normal in world terms, from A to B (b2WorldManifold's rule for face manifolds).
b2Vec2 worldNormal(const b2Manifold& m, const b2Transform& xfA, const b2Transform& xfB) {
    if (m.type == b2Manifold::e_faceA) return b2Mul(xfA.q, m.localNormal);
    return -b2Mul(xfB.q, m.localNormal);
}

}  // namespace

b2PolygonShape capsuleToB2(const Capsule& capsule) {
    b2PolygonShape p;
    p.m_count = 2;
    p.m_vertices[0] = {capsule.center1.x, capsule.center1.y};
    p.m_vertices[1] = {capsule.center2.x, capsule.center2.y};
    b2Vec2 axis = p.m_vertices[1] - p.m_vertices[0];
    axis.Normalize();
    p.m_normals[0] = b2Cross(axis, 1.0f);   // right of center1 → center2, as for a polygon edge
    p.m_normals[1] = -p.m_normals[0];
    p.m_centroid = 0.5f * (p.m_vertices[0] + p.m_vertices[1]);
    p.m_radius = capsule.radius;  // the whole rounding: no polygon skin, like a circle
    return p;
}

bool isCapsule(const b2Shape& shape) {
    return shape.m_type == b2Shape::e_polygon && static_cast<const b2PolygonShape&>(shape).m_count == 2;
}

void capsuleManifold(b2Manifold& manifold, const b2Shape& a, const b2Transform& xfA, const b2Shape& b, const b2Transform& xfB) {
    b2DistanceInput input;
    input.proxyA.Set(&a, 0);
    input.proxyB.Set(&b, 0);
    input.transformA = xfA;
    input.transformB = xfB;
    input.useRadii = false;
    b2SimplexCache cache;
    cache.count = 0;
    b2DistanceOutput output;
    b2Distance(&output, &cache, &input);
    const float d = output.distance;
    if (d < coreContact) return;
    if (d > a.m_radius + b.m_radius) {
        manifold.pointCount = 0;
        return;
    }
    const b2Vec2 n = (1.0f / d) * (output.pointB - output.pointA);
    if (manifold.pointCount > 0 && b2Dot(worldNormal(manifold, xfA, xfB), n) >= sameNormalCos) return;
    // One point between the closest features, as a circles manifold: b2WorldManifold pushes the
    // two core points out by the radii along their direction.
    manifold.type = b2Manifold::e_circles;
    manifold.pointCount = 1;
    manifold.localNormal.SetZero();
    manifold.localPoint = b2MulT(xfA, output.pointA);
    manifold.points[0].localPoint = b2MulT(xfB, output.pointB);
    manifold.points[0].normalImpulse = manifold.points[0].tangentImpulse = 0.0f;
    b2ContactFeature feature;
    feature.indexA = cache.indexA[0];
    feature.indexB = cache.indexB[0];
    feature.typeA = feature.typeB = b2ContactFeature::e_vertex;
    manifold.points[0].id.cf = feature;
}

bool rayCastCapsule(const b2PolygonShape& capsule, const b2Transform& xf, const b2RayCastInput& input, b2RayCastOutput& output) {
    const b2Vec2 v1 = capsule.m_vertices[0], v2 = capsule.m_vertices[1];
    const b2Vec2 side = capsule.m_radius * capsule.m_normals[0];
    b2CircleShape cap1, cap2;
    cap1.m_p = v1;
    cap2.m_p = v2;
    cap1.m_radius = cap2.m_radius = capsule.m_radius;
    b2EdgeShape side1, side2;
    side1.SetTwoSided(v1 + side, v2 + side);
    side2.SetTwoSided(v1 - side, v2 - side);
    const b2Shape* parts[4] = {&cap1, &cap2, &side1, &side2};
    b2RayCastInput nearest = input;
    bool hit = false;
    for (const b2Shape* part : parts) {
        b2RayCastOutput candidate;
        if (part->RayCast(&candidate, nearest, xf, 0) && candidate.fraction <= nearest.maxFraction) {
            output = candidate;
            nearest.maxFraction = candidate.fraction;
            hit = true;
        }
    }
    return hit;
}

bool capsuleContains(const b2PolygonShape& capsule, const b2Transform& xf, const b2Vec2& point) {
    const b2Vec2 p = b2MulT(xf, point);
    const b2Vec2 v1 = capsule.m_vertices[0], e = capsule.m_vertices[1] - capsule.m_vertices[0];
    const float t = std::clamp(b2Dot(p - v1, e) / b2Dot(e, e), 0.0f, 1.0f);
    const b2Vec2 closest = v1 + t * e;
    return b2DistanceSquared(p, closest) <= capsule.m_radius * capsule.m_radius;
}

}  // namespace perpdot::collide
