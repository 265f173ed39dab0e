// Convex polygon construction and mass properties from area integrals.
#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "perpdot/error.hpp"
#include "perpdot/portable_math.hpp"
#include "perpdot/shapes.hpp"

namespace perpdot {

namespace {

// Box2D's linear slop, and its weld distance (half of it): closer vertices are the same point.
constexpr float linearSlop = 0.005f;
constexpr float weldDistance = 0.5f * linearSlop;

float signedArea(std::span<const Vec2> p) {
    float twiceArea = 0.0f;
    for (size_t i = 0; i < p.size(); ++i) twiceArea += perpDot(p[i], p[(i + 1) % p.size()]);
    return 0.5f * twiceArea;
}

}  // namespace

Polygon makePolygon(std::span<const Vec2> points, float radius) {
    const int n = static_cast<int>(points.size());
    if (n < 3 || n > maxPolygonVertices)
        throw Error("polygon needs 3 to " + std::to_string(maxPolygonVertices) + " vertices, got " + std::to_string(n));
    if (!std::isfinite(radius) || radius < 0.0f) throw Error("polygon radius must be finite and >= 0");
    if (!withinShapeRange(radius)) throw Error("polygon radius is more than 100000 m");
    Polygon poly;
    poly.count = n;
    poly.radius = radius;
    for (int i = 0; i < n; ++i) {
        if (!isFinite(points[i])) throw Error("polygon vertex " + std::to_string(i) + " is not finite");
        if (!withinShapeRange(points[i])) throw Error("polygon vertex " + std::to_string(i) + " is more than 100000 m from the body origin");
        poly.vertices[i] = points[i];
    }
    // Normalise to counter-clockwise winding.
    if (signedArea(std::span(poly.vertices.data(), n)) < 0.0f) std::reverse(poly.vertices.begin(), poly.vertices.begin() + n);

    for (int i = 0; i < n; ++i) {
        const Vec2 a = poly.vertices[i];
        const Vec2 b = poly.vertices[(i + 1) % n];
        const Vec2 c = poly.vertices[(i + 2) % n];
        if (distance(a, b) < weldDistance) throw Error("polygon has coincident vertices " + std::to_string(i) + " and " + std::to_string((i + 1) % n));
        // Strict convexity: every turn is to the left, with some margin for collinear points.
        const Vec2 e1 = b - a, e2 = c - b;
        if (perpDot(e1, e2) <= 1.0e-6f * length(e1) * length(e2)) throw Error("polygon is not convex");
    }
    // No sliver: every vertex stands at least the linear slop off the line through its
    // neighbours (Box2D v3's hull rule); thinner polygons break the time-of-impact solver.
    for (int i = 0; i < n; ++i) {
        const Vec2 prev = poly.vertices[(i + n - 1) % n], v = poly.vertices[i], next = poly.vertices[(i + 1) % n];
        const float offLine = perpDot(next - prev, v - prev) / length(next - prev);
        if (std::fabs(offLine) < linearSlop)
            throw Error("polygon is degenerate: vertex " + std::to_string(i) + " lies within 0.005 m of the line through its neighbours");
    }
    // A star-shaped loop turns left everywhere but winds twice: the turning must add up to one turn.
    float turning = 0.0f;
    for (int i = 0; i < n; ++i) {
        const Vec2 e1 = poly.vertices[(i + 1) % n] - poly.vertices[i];
        const Vec2 e2 = poly.vertices[(i + 2) % n] - poly.vertices[(i + 1) % n];
        turning += atan2(perpDot(e1, e2), dot(e1, e2));
    }
    if (std::fabs(turning - 2.0f * pi) > 1.0e-3f) throw Error("polygon is not convex");
    return poly;
}

Polygon makeBox(float hx, float hy, Vec2 center, float angle) {
    if (!(std::isfinite(hx) && std::isfinite(hy)) || hx <= 0.0f || hy <= 0.0f)
        throw Error("box half extents must be finite and > 0");
    if (!isFinite(center) || !std::isfinite(angle)) throw Error("box center and angle must be finite");
    const Rot q = Rot::fromAngle(angle);
    const Vec2 corners[4] = {{-hx, -hy}, {hx, -hy}, {hx, hy}, {-hx, hy}};
    Polygon poly;
    poly.count = 4;
    for (int i = 0; i < 4; ++i) poly.vertices[i] = rotate(q, corners[i]) + center;
    return poly;
}

bool shouldCollide(const Filter& a, const Filter& b) {
    if (a.group == b.group && a.group != 0) return a.group > 0;
    return (a.mask & b.category) != 0 && (a.category & b.mask) != 0;
}

MassData computeMass(const Circle& circle, float density) {
    // m = ρπr², I = m r²/2 about the centre.
    const float rr = circle.radius * circle.radius;
    const float m = density * pi * rr;
    return {m, circle.center, 0.5f * m * rr};
}

MassData computeMass(const Polygon& polygon, float density) {
    const int n = polygon.count;
    // Triangle fan about the vertex average (better conditioned than the origin).
    Vec2 ref;
    for (int i = 0; i < n; ++i) ref += polygon.vertices[i];
    ref = (1.0f / static_cast<float>(n)) * ref;

    float area = 0.0f;
    Vec2 firstMoment;       // ∫ r dA, r from ref
    float secondMoment = 0; // ∫ |r|² dA about ref
    for (int i = 0; i < n; ++i) {
        const Vec2 e1 = polygon.vertices[i] - ref;
        const Vec2 e2 = polygon.vertices[(i + 1) % n] - ref;
        const float a = 0.5f * perpDot(e1, e2);
        area += a;
        firstMoment += (a / 3.0f) * (e1 + e2);
        secondMoment += (a / 6.0f) * (dot(e1, e1) + dot(e1, e2) + dot(e2, e2));
    }
    const Vec2 c = (1.0f / area) * firstMoment;
    // Parallel axis: I_c = I_ref - A|c|².
    std::array<MassData, 1 + 2 * maxPolygonVertices> parts;
    int count = 0;
    parts[count++] = {density * area, ref + c, density * (secondMoment - area * dot(c, c))};

    const float r = polygon.radius;
    if (r > 0.0f) {
        // Rounding adds a rectangle of width r on every edge and a circular sector at every corner.
        auto outwardNormal = [&](int i) {
            const Vec2 e = polygon.vertices[(i + 1) % n] - polygon.vertices[i];
            return normalize(Vec2{e.y, -e.x});
        };
        for (int i = 0; i < n; ++i) {
            const Vec2 a = polygon.vertices[i], b = polygon.vertices[(i + 1) % n];
            const float len = distance(a, b);
            const float m = density * len * r;
            parts[count++] = {m, 0.5f * (a + b) + (0.5f * r) * outwardNormal(i), m * (len * len + r * r) / 12.0f};

            const Vec2 n0 = outwardNormal((i + n - 1) % n), n1 = outwardNormal(i);
            const float phi = atan2(perpDot(n0, n1), dot(n0, n1));  // exterior angle at vertex a
            const float ms = density * 0.5f * r * r * phi;
            // Sector centroid lies on the bisector at 4 r sin(φ/2) / (3φ) from the vertex.
            const float d = 4.0f * r * sinCos(0.5f * phi).sin / (3.0f * phi);
            parts[count++] = {ms, a + d * normalize(n0 + n1), ms * (0.5f * r * r - d * d)};
        }
    }
    return combineMass(std::span(parts.data(), count));
}

MassData computeMass(const Capsule& capsule, float density) {
    const float r = capsule.radius;
    const Vec2 axis = capsule.center2 - capsule.center1;
    const float len = length(axis);
    const Vec2 u = (1.0f / len) * axis;
    // The 2r × L rectangle: m = ρ·2rL, I = m(L² + (2r)²)/12 about its centre.
    const float mRect = density * 2.0f * r * len;
    // Each half-disc: m = ρπr²/2, centroid 4r/(3π) beyond its cap centre, I = m r²/2 − m d² about it.
    const float mHalf = density * 0.5f * pi * r * r;
    const float d = 4.0f * r / (3.0f * pi);
    const MassData parts[3] = {
        {mRect, 0.5f * (capsule.center1 + capsule.center2), mRect * (len * len + 4.0f * r * r) / 12.0f},
        {mHalf, capsule.center1 - d * u, mHalf * (0.5f * r * r - d * d)},
        {mHalf, capsule.center2 + d * u, mHalf * (0.5f * r * r - d * d)},
    };
    return combineMass(parts);
}

MassData combineMass(std::span<const MassData> parts) {
    MassData total;
    Vec2 moment;
    for (const MassData& p : parts) {
        total.mass += p.mass;
        moment += p.mass * p.center;
    }
    if (total.mass <= 0.0f) return {};
    total.center = (1.0f / total.mass) * moment;
    for (const MassData& p : parts) {
        const Vec2 d = p.center - total.center;
        total.rotationalInertia += p.rotationalInertia + p.mass * dot(d, d);
    }
    return total;
}

}  // namespace perpdot
