// The Box2D collision adapter: shape geometry, the b2DynamicTree broadphase and the b2Collide*
// narrowphase, behind an interface with no Box2D types in it.
#pragma once

#include <cstdint>
#include <memory>

#include "perpdot/math.hpp"
#include "perpdot/shapes.hpp"

namespace perpdot::collide {

// Box2D's tolerances, kept so perpdot and Box2D rest bodies at the same separations.
inline constexpr float linearSlop = 0.005f;
inline constexpr float polygonRadius = 2.0f * linearSlop;  // collision skin of polygons

struct ManifoldPoint {
    Vec2 point;               // world, midway between the two surfaces
    float separation = 0.0f;  // negative when overlapping
    uint32_t id = 0;          // feature id (Box2D's b2ContactID key)
};

struct Manifold {
    Vec2 normal;  // world, from A to B
    int pointCount = 0;
    ManifoldPoint points[2];
};

// A shape child: a whole circle or polygon, or one segment of a chain.
struct ChildKey {
    int shape = -1;
    int child = 0;
};

class CollisionSystem {
public:
    CollisionSystem();
    ~CollisionSystem();
    CollisionSystem(const CollisionSystem&) = delete;
    CollisionSystem& operator=(const CollisionSystem&) = delete;

    // Geometry, stored per shape index.
    void setGeometry(int shape, const Circle& circle);
    void setGeometry(int shape, const Polygon& polygon);
    void setGeometry(int shape, const Segment& segment);
    void setGeometry(int shape, const Chain& chain);
    void clearGeometry(int shape);
    int childCount(int shape) const;
    AABB computeAABB(int shape, int child, const Transform& xf) const;
    // Whether narrowphase has a routine for this pair of shape types (segments and chains never meet).
    static bool canCollide(ShapeType a, ShapeType b);

    // Broadphase: proxies carry their child key; the tree keeps a fattened AABB per proxy.
    int createProxy(const AABB& aabb, ChildKey key);
    void destroyProxy(int proxy);
    // Re-fits the proxy if `aabb` left its fat AABB; returns whether it moved.
    bool moveProxy(int proxy, const AABB& aabb, Vec2 displacement);
    AABB fatAABB(int proxy) const;
    bool wasMoved(int proxy) const;
    void clearMoved(int proxy);
    ChildKey proxyKey(int proxy) const;
    // Calls visit(proxy) for every proxy whose fat AABB overlaps `aabb`; visit returns false to stop.
    template <class Visit>
    void query(const AABB& aabb, Visit&& visit) const {
        queryImpl(aabb, &visit, [](void* v, int proxy) { return (*static_cast<Visit*>(v))(proxy); });
    }
    void shiftOrigin(Vec2 newOrigin);

    // Narrowphase: the contact manifold of child A at xfA against child B at xfB (A's shape type must
    // be the "larger" one as ordered by orderPair).
    Manifold collide(ChildKey a, const Transform& xfA, ChildKey b, const Transform& xfB) const;
    // True when the pair must be swapped so that collide() receives (A, B) in Box2D's order
    // (polygon before circle, segment/chain before either).
    static bool mustSwap(ShapeType a, ShapeType b);

private:
    void queryImpl(const AABB& aabb, void* context, bool (*visit)(void*, int)) const;
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace perpdot::collide
