// World::explode: a radial impulse with linear falloff (ExplosionDef, perpdot/queries.hpp).
// Each reached shape takes J = impulse·(1 − d/radius)·u at its surface point p nearest the centre,
// u the unit vector from the centre to p, d = |p − centre|; applied as a linear impulse at p, so
// the body also turns by perpDot(p − c, J)/I.
#include <algorithm>
#include <cmath>
#include <vector>

#include "core/queries/query_world.hpp"
#include "perpdot/error.hpp"

namespace perpdot {

namespace {

struct Reached {
    int shape = -1;
    collide::CollisionSystem::SurfacePoint nearest;
};

// Whether a static shape lies on the segment from the centre to `point` (before reaching it).
bool hiddenByStatic(const QueryWorld& w, Vec2 centre, Vec2 point) {
    if (!(lengthSquared(point - centre) > 0.0f)) return false;
    bool hidden = false;
    w.collision.rayCastTree(centre, point, [&](int proxy, float maxFraction) {
        const collide::ChildKey key = w.collision.proxyKey(proxy);
        const ShapeData& s = w.shapes[key.shape];
        if (s.sensor || w.bodies[s.body].type != BodyType::Static) return -1.0f;
        collide::RayCastResult result;
        if (w.collision.rayCast(key, w.bodies[s.body].xf, centre, point, maxFraction, result) && result.fraction < 1.0f) {
            hidden = true;
            return 0.0f;  // one is enough
        }
        return -1.0f;
    });
    return hidden;
}

}  // namespace

int World::explode(const ExplosionDef& def) {
    const QueryWorld w = queryWorld(*impl_);
    checkUnlocked(w.locked, "explode");
    if (!isFinite(def.position)) throw Error("ExplosionDef.position must be finite");
    if (!(def.radius > 0.0f) || !std::isfinite(def.radius)) throw Error("ExplosionDef.radius must be > 0 and finite");
    if (!(def.impulse >= 0.0f) || !std::isfinite(def.impulse)) throw Error("ExplosionDef.impulse must be >= 0 and finite");

    // Nearest surface point of every dynamic shape within the radius (of its nearest child).
    std::vector<Reached> reached;
    const Vec2 extent{def.radius, def.radius};
    w.collision.query({def.position - extent, def.position + extent}, [&](int proxy) {
        const collide::ChildKey key = w.collision.proxyKey(proxy);
        const ShapeData& s = w.shapes[key.shape];
        const Body& b = w.bodies[s.body];
        if (b.type != BodyType::Dynamic || s.sensor || !shouldCollide(def.filter, s.filter)) return true;
        const auto nearest = w.collision.closestSurfacePoint(key, b.xf, def.position);
        if (!(nearest.distance < def.radius)) return true;
        const auto same = std::find_if(reached.begin(), reached.end(), [&](const Reached& r) { return r.shape == key.shape; });
        if (same == reached.end()) reached.push_back({key.shape, nearest});
        else if (nearest.distance < same->nearest.distance) same->nearest = nearest;
        return true;
    });
    std::sort(reached.begin(), reached.end(), [](const Reached& a, const Reached& b) { return a.shape < b.shape; });

    int pushed = 0;
    for (const Reached& r : reached) {
        const int body = w.shapes[r.shape].body;
        if (def.blockedByStatic && hiddenByStatic(w, def.position, r.nearest.point)) continue;
        // From the centre to the nearest point; from the centre to the centre of mass when the
        // centre is inside the shape; no direction at all: nothing to push along.
        Vec2 away = r.nearest.point - def.position;
        if (!(lengthSquared(away) > 0.0f)) away = w.bodies[body].center - def.position;
        if (!(lengthSquared(away) > 0.0f)) continue;
        const float magnitude = def.impulse * (1.0f - r.nearest.distance / def.radius);
        applyLinearImpulse(w.bodyId(body), magnitude * normalize(away), r.nearest.point);
        ++pushed;
    }
    return pushed;
}

}  // namespace perpdot
