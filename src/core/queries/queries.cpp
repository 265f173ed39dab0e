// World queries through the broadphase tree: ray casts (b2DynamicTree::RayCast + b2Shape::RayCast),
// shape casts (b2ShapeCast),
// AABB, point (b2Shape::TestPoint) and shape overlap (b2TestOverlap). A shape is reported when
// shouldCollide(query filter, shape filter).
#include <algorithm>
#include <cmath>
#include <span>
#include <string>
#include <variant>

#include "core/queries/query_world.hpp"

namespace perpdot {

namespace {

// Calls visit(key) for each shape child whose fat AABB overlaps `box` and whose filter passes.
template <class Visit>
void forEachChild(const QueryWorld& w, const AABB& box, const Filter& filter, Visit&& visit) {
    w.collision.query(box, [&](int proxy) {
        const collide::ChildKey key = w.collision.proxyKey(proxy);
        if (shouldCollide(filter, w.shapes[key.shape].filter)) visit(key);
        return true;
    });
}

// Each shape once, in the order first met.
void addUnique(std::vector<ShapeId>& out, ShapeId id) {
    if (std::find(out.begin(), out.end(), id) == out.end()) out.push_back(id);
}

// A query shape's bounds at xf: transformed vertices (or centre ± radius), grown by the rounding.
AABB boundsOf(const Circle& query, const Transform& xf) {
    const Vec2 c = transformPoint(xf, query.center);
    return {c - Vec2{query.radius, query.radius}, c + Vec2{query.radius, query.radius}};
}

AABB boundsOf(std::span<const Vec2> vertices, float radius, const Transform& xf) {
    AABB box{transformPoint(xf, vertices[0]), transformPoint(xf, vertices[0])};
    for (const Vec2 v : vertices.subspan(1)) {
        const Vec2 p = transformPoint(xf, v);
        box.lower = {std::min(box.lower.x, p.x), std::min(box.lower.y, p.y)};
        box.upper = {std::max(box.upper.x, p.x), std::max(box.upper.y, p.y)};
    }
    box.lower -= Vec2{radius, radius};
    box.upper += Vec2{radius, radius};
    return box;
}

AABB boundsOf(const Polygon& query, const Transform& xf) {
    return boundsOf(std::span(query.vertices.data(), query.count), query.radius + collide::polygonRadius, xf);
}

AABB boundsOf(const Segment& query, const Transform& xf) {
    const Vec2 ends[] = {query.v1, query.v2};
    return boundsOf(ends, collide::polygonRadius, xf);
}

template <class QueryShape>
std::vector<ShapeId> overlapQuery(const QueryWorld& w, const QueryShape& query, const Transform& xf, const Filter& filter) {
    // A hand-filled query shape gets a created shape's checks (a polygon's count indexes a fixed
    // array of 8 in the adapter); the error names the call.
    try {
        validateGeometry(query);
    } catch (const Error& e) {
        throw Error(std::string("overlapShape: ") + e.what());
    }
    if (!isFinite(xf.p) || !std::isfinite(xf.q.c) || !std::isfinite(xf.q.s)) throw Error("overlapShape: transform must be finite");
    std::vector<ShapeId> out;
    forEachChild(w, boundsOf(query, xf), filter, [&](collide::ChildKey key) {
        const Transform& shapeXf = w.bodies[w.shapes[key.shape].body].xf;
        if (w.collision.testOverlap(key, shapeXf, query, xf)) addUnique(out, w.shapeId(key.shape));
    });
    return out;
}

// Shape casts: every child the swept shape's path box reaches is cast against (b2ShapeCast);
// onHit(hit) per hit.
template <class OnHit>
void shapeCast(const QueryWorld& w, const CastShape& shape, const Transform& xf, Vec2 translation, const Filter& filter,
               OnHit&& onHit) {
    if (!isFinite(xf.p) || !std::isfinite(xf.q.c) || !std::isfinite(xf.q.s) || !isFinite(translation))
        throw Error("castShape: transform and translation must be finite");
    std::visit(
        [&](const auto& query) {
            validateGeometry(query);
            const AABB start = boundsOf(query, xf);
            const AABB path{{std::min(start.lower.x, start.lower.x + translation.x), std::min(start.lower.y, start.lower.y + translation.y)},
                            {std::max(start.upper.x, start.upper.x + translation.x), std::max(start.upper.y, start.upper.y + translation.y)}};
            forEachChild(w, path, filter, [&](collide::ChildKey key) {
                collide::ShapeCastResult result;
                if (w.collision.shapeCast(key, w.bodies[w.shapes[key.shape].body].xf, query, xf, translation, result))
                    onHit(ShapeCastHit{w.shapeId(key.shape), result.point, result.normal, result.fraction});
            });
        },
        shape);
}

// Ray casts: visit(hit) per child hit, returning the new max fraction (closest: the hit's own).
template <class OnHit>
void rayCast(const QueryWorld& w, Vec2 origin, Vec2 translation, const Filter& filter, OnHit&& onHit) {
    if (!isFinite(origin) || !isFinite(translation)) throw Error("castRay: origin and translation must be finite");
    const Vec2 p2 = origin + translation;
    w.collision.rayCastTree(origin, p2, [&](int proxy, float maxFraction) {
        const collide::ChildKey key = w.collision.proxyKey(proxy);
        const ShapeData& s = w.shapes[key.shape];
        if (!shouldCollide(filter, s.filter)) return -1.0f;
        collide::RayCastResult result;
        if (!w.collision.rayCast(key, w.bodies[s.body].xf, origin, p2, maxFraction, result)) return -1.0f;
        return onHit(RayHit{w.shapeId(key.shape), origin + result.fraction * translation, result.normal, result.fraction});
    });
}

}  // namespace

std::optional<RayHit> World::castRayClosest(Vec2 origin, Vec2 translation, const Filter& filter) const {
    std::optional<RayHit> closest;
    rayCast(queryWorld(*impl_), origin, translation, filter, [&](const RayHit& hit) {
        closest = hit;
        return hit.fraction;  // later hits must be nearer
    });
    return closest;
}

std::vector<RayHit> World::castRay(Vec2 origin, Vec2 translation, const Filter& filter) const {
    std::vector<RayHit> hits;
    rayCast(queryWorld(*impl_), origin, translation, filter, [&](const RayHit& hit) {
        hits.push_back(hit);
        return -1.0f;  // keep the whole ray
    });
    std::sort(hits.begin(), hits.end(), [](const RayHit& a, const RayHit& b) { return a.fraction < b.fraction; });
    return hits;
}

std::optional<ShapeCastHit> World::castShapeClosest(const CastShape& shape, const Transform& xf, Vec2 translation,
                                                    const Filter& filter) const {
    std::optional<ShapeCastHit> closest;
    shapeCast(queryWorld(*impl_), shape, xf, translation, filter, [&](const ShapeCastHit& hit) {
        if (!closest || hit.fraction < closest->fraction) closest = hit;
    });
    return closest;
}

std::vector<ShapeCastHit> World::castShape(const CastShape& shape, const Transform& xf, Vec2 translation,
                                           const Filter& filter) const {
    std::vector<ShapeCastHit> hits;
    shapeCast(queryWorld(*impl_), shape, xf, translation, filter, [&](const ShapeCastHit& hit) { hits.push_back(hit); });
    std::stable_sort(hits.begin(), hits.end(), [](const ShapeCastHit& a, const ShapeCastHit& b) { return a.fraction < b.fraction; });
    return hits;
}

std::vector<ShapeId> World::overlapAABB(const AABB& box, const Filter& filter) const {
    std::vector<ShapeId> out;
    const QueryWorld w = queryWorld(*impl_);
    forEachChild(w, box, filter, [&](collide::ChildKey key) {
        const Transform& xf = w.bodies[w.shapes[key.shape].body].xf;
        if (overlaps(w.collision.computeAABB(key.shape, key.child, xf), box)) addUnique(out, w.shapeId(key.shape));
    });
    return out;
}

std::vector<ShapeId> World::overlapPoint(Vec2 point, const Filter& filter) const {
    std::vector<ShapeId> out;
    const QueryWorld w = queryWorld(*impl_);
    forEachChild(w, AABB{point, point}, filter, [&](collide::ChildKey key) {
        const Transform& xf = w.bodies[w.shapes[key.shape].body].xf;
        if (w.collision.testPoint(key.shape, xf, point)) addUnique(out, w.shapeId(key.shape));
    });
    return out;
}

std::vector<ShapeId> World::overlapShape(const Circle& shape, const Transform& xf, const Filter& filter) const {
    return overlapQuery(queryWorld(*impl_), shape, xf, filter);
}

std::vector<ShapeId> World::overlapShape(const Polygon& shape, const Transform& xf, const Filter& filter) const {
    return overlapQuery(queryWorld(*impl_), shape, xf, filter);
}

}  // namespace perpdot
