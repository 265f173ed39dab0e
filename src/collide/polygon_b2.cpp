#include "collide/polygon_b2.hpp"

#include "collide/collision.hpp"

namespace perpdot::collide {

// perpdot polygons are already validated convex and counter-clockwise (makePolygon), so they go to
// Box2D as they are: b2PolygonShape::Set would re-run its own hull with other tolerances, and it
// asserts on thin polygons that pass perpdot's checks (a fuzz finding).
b2PolygonShape polygonToB2(const Polygon& polygon) {
    const int n = polygon.count;
    b2PolygonShape p;
    p.m_count = n;
    for (int i = 0; i < n; ++i) {
        const Vec2 edge = polygon.vertices[(i + 1) % n] - polygon.vertices[i];
        p.m_vertices[i] = {polygon.vertices[i].x, polygon.vertices[i].y};
        const Vec2 normal = normalize(Vec2{edge.y, -edge.x});  // outward for counter-clockwise
        p.m_normals[i] = {normal.x, normal.y};
    }
    Polygon core = polygon;
    core.radius = 0.0f;
    const Vec2 centroid = computeMass(core, 1.0f).center;
    p.m_centroid = {centroid.x, centroid.y};
    p.m_radius = polygonRadius + polygon.radius;
    return p;
}

}  // namespace perpdot::collide
