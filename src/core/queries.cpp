// World queries through the broadphase tree: ray casts (b2DynamicTree::RayCast + b2Shape::RayCast),
// AABB, point (b2Shape::TestPoint) and shape overlap (b2TestOverlap). A shape is reported when
// shouldCollide(query filter, shape filter).
#include <algorithm>
#include <cmath>
#include <string>

#include "core/world_impl.hpp"

namespace perpdot {

namespace {

// Calls visit(key) for each shape child whose fat AABB overlaps `box` and whose filter passes.
template <class Visit>
void forEachChild(const World::Impl& w, const AABB& box, const Filter& filter, Visit&& visit) {
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

template <class QueryShape>
std::vector<ShapeId> overlapQuery(const World::Impl& w, const QueryShape& query, const Transform& xf, const Filter& filter) {
    // A hand-filled query shape gets a created shape's checks (a polygon's count indexes a fixed
    // array of 8 in the adapter); the error names the call.
    try {
        validateGeometry(query);
    } catch (const Error& e) {
        throw Error(std::string("overlapShape: ") + e.what());
    }
    if (!isFinite(xf.p) || !std::isfinite(xf.q.c) || !std::isfinite(xf.q.s)) throw Error("overlapShape: transform must be finite");
    std::vector<ShapeId> out;
    // The query shape's bounds: transform its vertices (or centre ± radius).
    AABB box;
    if constexpr (std::is_same_v<QueryShape, Circle>) {
        const Vec2 c = transformPoint(xf, query.center);
        box = {c - Vec2{query.radius, query.radius}, c + Vec2{query.radius, query.radius}};
    } else {
        box.lower = box.upper = transformPoint(xf, query.vertices[0]);
        for (int i = 1; i < query.count; ++i) {
            const Vec2 p = transformPoint(xf, query.vertices[i]);
            box.lower = {std::min(box.lower.x, p.x), std::min(box.lower.y, p.y)};
            box.upper = {std::max(box.upper.x, p.x), std::max(box.upper.y, p.y)};
        }
        const float r = query.radius + collide::polygonRadius;
        box.lower -= Vec2{r, r};
        box.upper += Vec2{r, r};
    }
    forEachChild(w, box, filter, [&](collide::ChildKey key) {
        const Transform& shapeXf = w.bodies[w.shapes[key.shape].body].xf;
        if (w.collision.testOverlap(key, shapeXf, query, xf)) addUnique(out, w.shapeId(key.shape));
    });
    return out;
}

// Ray casts: visit(hit) per child hit, returning the new max fraction (closest: the hit's own).
template <class OnHit>
void rayCast(const World::Impl& w, Vec2 origin, Vec2 translation, const Filter& filter, OnHit&& onHit) {
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
    rayCast(*impl_, origin, translation, filter, [&](const RayHit& hit) {
        closest = hit;
        return hit.fraction;  // later hits must be nearer
    });
    return closest;
}

std::vector<RayHit> World::castRay(Vec2 origin, Vec2 translation, const Filter& filter) const {
    std::vector<RayHit> hits;
    rayCast(*impl_, origin, translation, filter, [&](const RayHit& hit) {
        hits.push_back(hit);
        return -1.0f;  // keep the whole ray
    });
    std::sort(hits.begin(), hits.end(), [](const RayHit& a, const RayHit& b) { return a.fraction < b.fraction; });
    return hits;
}

std::vector<ShapeId> World::overlapAABB(const AABB& box, const Filter& filter) const {
    std::vector<ShapeId> out;
    forEachChild(*impl_, box, filter, [&](collide::ChildKey key) {
        const Transform& xf = impl_->bodies[impl_->shapes[key.shape].body].xf;
        if (overlaps(impl_->collision.computeAABB(key.shape, key.child, xf), box)) addUnique(out, impl_->shapeId(key.shape));
    });
    return out;
}

std::vector<ShapeId> World::overlapPoint(Vec2 point, const Filter& filter) const {
    std::vector<ShapeId> out;
    forEachChild(*impl_, AABB{point, point}, filter, [&](collide::ChildKey key) {
        const Transform& xf = impl_->bodies[impl_->shapes[key.shape].body].xf;
        if (impl_->collision.testPoint(key.shape, xf, point)) addUnique(out, impl_->shapeId(key.shape));
    });
    return out;
}

std::vector<ShapeId> World::overlapShape(const Circle& shape, const Transform& xf, const Filter& filter) const {
    return overlapQuery(*impl_, shape, xf, filter);
}

std::vector<ShapeId> World::overlapShape(const Polygon& shape, const Transform& xf, const Filter& filter) const {
    return overlapQuery(*impl_, shape, xf, filter);
}

}  // namespace perpdot
