// The Box2D collision adapter: shape geometry, the b2DynamicTree broadphase and the b2Collide*
// narrowphase, behind an interface with no Box2D types in it.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <type_traits>
#include <vector>

#include "perpdot/math.hpp"
#include "perpdot/shapes.hpp"

namespace perpdot::collide {

// Box2D's tolerances, kept so perpdot and Box2D rest bodies at the same separations.
inline constexpr float linearSlop = 0.005f;
inline constexpr float polygonRadius = 2.0f * linearSlop;  // Box2D 2.4's collision skin of polygons and segments
// The part of Box2D's skin a polygon or segment keeps as a rest gap against a static or kinematic
// body: a box resting on a row of separate tiles then slides over their seams without catching a
// tile's side face (docs/stress.md). Two dynamic bodies keep none: they rest on their true surfaces.
inline constexpr float keptSkin = 0.1f * linearSlop;

// Where collide() measures a pair's separations: on Box2D 2.4's skins (WorldDef::box2dSkin, and
// the time of impact), between the true surfaces less keptSkin of each skin (a pair with a static
// or kinematic body), or between the true surfaces (two dynamic bodies).
enum class Skin : uint8_t { Box2D, Kept, None };

// Box2D 2.4's skin around a shape: polygons, segments and chains have one, circles and capsules not.
constexpr float box2dSkin(ShapeType type) {
    return type == ShapeType::Polygon || type == ShapeType::Segment || type == ShapeType::Chain ? polygonRadius : 0.0f;
}
// The skin collide() gives a shape against `other`, within which it reports points before the
// true surfaces touch: Box2D's, where a polygon's gives every pair with a polygon a margin of at
// least one skin. Two circles have none, so off Box2D's skin each is collided grown by half a
// polygon skin: a pair of circles about to meet has its contact (and its impact) from the step
// before, as a circle about to meet a polygon does.
inline constexpr float circleSkin = 0.5f * polygonRadius;
constexpr float collisionSkin(ShapeType type, ShapeType other, Skin skin) {
    const bool circles = type == ShapeType::Circle && other == ShapeType::Circle;
    return circles && skin != Skin::Box2D ? circleSkin : box2dSkin(type);
}
// What perpdot adds to Box2D's separations for a shape against `other`: nothing on Box2D's skin,
// else its collision skin, less keptSkin of a polygon's where the pair keeps it (a circle's is all
// taken off: it only reports points early).
constexpr float skinOffset(ShapeType type, ShapeType other, Skin skin) {
    if (skin == Skin::Box2D) return 0.0f;
    if (box2dSkin(type) == 0.0f) return collisionSkin(type, other, skin);
    return skin == Skin::Kept ? box2dSkin(type) - keptSkin : box2dSkin(type);
}

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

// The motion of a body over a step, for time of impact: centre of mass from c1 to c2, angle from
// a1 to a2, about the body-frame centre localCenter.
struct Sweep {
    Vec2 localCenter;
    Vec2 c1, c2;
    float a1 = 0, a2 = 0;
};

struct ShapeCastResult {
    Vec2 point, normal;
    float fraction = 1.0f;
};

struct RayCastResult {
    Vec2 normal;
    float fraction = 1.0f;
};

// Closest points of two children's cores (rounding radii left out) and the radii to add back:
// the surfaces are `distance - radiusA - radiusB` apart.
struct CoreDistance {
    Vec2 pointA, pointB;  // world
    float distance = 0.0f;
    float radiusA = 0.0f, radiusB = 0.0f;  // circle/capsule radius; polygon skin + rounding; edge skin
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
    CollisionSystem& operator=(CollisionSystem&&) noexcept;  // a restored world takes a world's trees

    // Geometry, stored per shape index.
    void setGeometry(int shape, const Circle& circle);
    void setGeometry(int shape, const Polygon& polygon);
    void setGeometry(int shape, const Segment& segment);
    void setGeometry(int shape, const Chain& chain);
    void setGeometry(int shape, const Capsule& capsule);
    void clearGeometry(int shape);
    int childCount(int shape) const;
    AABB computeAABB(int shape, int child, const Transform& xf) const;
    // Whether narrowphase has a routine for this pair of shape types (segments and chains never meet).
    static bool canCollide(ShapeType a, ShapeType b);

    // Broadphase: proxies carry their child key; the tree keeps a fattened AABB per proxy. A
    // static shape's proxy is mirrored in a second tree of static proxies only (Box2D v3 keeps
    // static shapes in a tree of their own), so continuous collision searches only those.
    int createProxy(const AABB& aabb, ChildKey key, bool isStatic);
    void destroyProxy(int proxy);
    // Re-fits the proxy if `aabb` left its fat AABB (b2DynamicTree::MoveProxy: the new fat AABB is
    // `aabb` grown by the 0.1 m margin and along the step's displacement, by at most two margins
    // more); returns whether it moved.
    bool moveProxy(int proxy, const AABB& aabb, Vec2 displacement);
    // The fat AABB moveProxy would give a dynamic proxy whose `aabb` left its fat AABB, when its leaf
    // moves in place (the tree's ancestors are re-fitted, nothing re-inserted); nullopt when it
    // would not (the box is inside, overflowed, or the proxy is static). Reads only, so workers may
    // ask side by side between tree updates; moveInPlace(proxy, fat) then makes the move.
    std::optional<AABB> inPlaceFat(int proxy, const AABB& aabb, Vec2 displacement) const;
    void moveInPlace(int proxy, const AABB& fat);
    AABB fatAABB(int proxy) const;
    // Builds the tree anew once it has inserted and removed as many leaves as it holds
    // (tree_rebuild.hpp), and says whether it did: the same proxies and boxes, so every query
    // finds what it found before, through fewer nodes.
    bool rebuildTreeIfWorn();
    // The least distance from aabb to a side of the proxy's fat AABB: >= 0 when the fat AABB holds
    // it, negative when it sticks out (and moveProxy would re-fit). Reads only, so workers may ask
    // side by side between tree updates.
    float room(int proxy, const AABB& aabb) const;
    // A new proxy whose fat AABB is exactly `fat` (a snapshot's), marked as moved like createProxy's.
    int restoreProxy(const AABB& fat, ChildKey key, bool isStatic);
    // Whether `proxy` is already what restoreProxy(fat, key, isStatic) would make: its key, the same
    // fat AABB bit for bit (in the static tree too) and the same tree membership.
    bool proxyIs(int proxy, const AABB& fat, ChildKey key, bool isStatic) const;
    bool wasMoved(int proxy) const;
    // Ends the proxy's move: its fat AABB now is what the next pair update compares with.
    void clearMoved(int proxy);
    // The proxy's box at the last pair update is forgotten (it is looked for as a new one).
    void requery(int proxy);
    ChildKey proxyKey(int proxy) const;
    // Calls visit(proxy) for every proxy whose fat AABB overlaps `aabb`; visit returns false to stop.
    template <class Visit>
    void query(const AABB& aabb, Visit&& visit) const {
        using V = std::remove_reference_t<Visit>;
        queryImpl(aabb, &visit, [](void* v, int proxy) { return (*static_cast<V*>(v))(proxy); });
    }
    // Proxies a moved proxy is grouped with for one tree query (queryNewPairs), at most.
    static constexpr int groupSize = 8;
    // Calls visit(proxy, other) for each proxy of group[0, count) (count <= groupSize) and every
    // proxy `other` whose fat AABB overlaps proxy's fat AABB and that may be a new partner: not
    // proxy itself, not a lower proxy that moved too (that one reports the pair), and not one
    // whose box overlapped proxy's when pairs were last updated (such a pair has its contact
    // already, or was not wanted; a moved proxy's box from before its move is kept). One tree query
    // with the group's union box finds them, its hits sorted out against the members' boxes:
    // worth it for proxies whose union box is compact.
    template <class Visit>
    void queryNewPairs(const int* group, int count, Visit&& visit) const {
        using V = std::remove_reference_t<Visit>;
        queryNewPairsImpl(group, count, &visit, [](void* v, int proxy, int other) { (*static_cast<V*>(v))(proxy, other); });
    }
    // The same over the static proxies only (visit gets the proxy id, as from query).
    template <class Visit>
    void queryStatic(const AABB& aabb, Visit&& visit) const {
        using V = std::remove_reference_t<Visit>;
        queryStaticImpl(aabb, &visit, [](void* v, int proxy) { return (*static_cast<V*>(v))(proxy); });
    }
    void shiftOrigin(Vec2 newOrigin);

    // Narrowphase: the contact manifold of child A at xfA against child B at xfB (A's shape type must
    // be the "larger" one as ordered by orderPair).
    // Box2D 2.4 finds manifold points where the skins (polygonRadius around every polygon and
    // segment) overlap and measures separations between the skins. perpdot measures them between
    // the true surfaces (less keptSkin of each skin with Skin::Kept), so the skin is only a
    // speculative margin; Skin::Box2D keeps Box2D's separations (WorldDef::box2dSkin: bodies rest
    // where b2World rests them).
    Manifold collide(ChildKey a, const Transform& xfA, ChildKey b, const Transform& xfB, Skin skin) const;
    // True when the pair must be swapped so that collide() receives (A, B) in Box2D's order
    // (polygon before circle, segment/chain before either).
    static bool mustSwap(ShapeType a, ShapeType b);

    // Overlap tests (b2TestOverlap, b2Shape::TestPoint): child against child or a query shape.
    bool testOverlap(ChildKey a, const Transform& xfA, ChildKey b, const Transform& xfB) const;
    bool testOverlap(ChildKey a, const Transform& xfA, const Circle& query, const Transform& xf) const;
    bool testOverlap(ChildKey a, const Transform& xfA, const Polygon& query, const Transform& xf) const;
    bool testPoint(int shape, const Transform& xf, Vec2 point) const;  // false for segments and chains

    // b2Distance between two children's cores.
    CoreDistance coreDistance(ChildKey a, const Transform& xfA, ChildKey b, const Transform& xfB) const;
    // The point of a child's true surface nearest to `point` (b2Distance to a one-vertex proxy, less
    // the shape's rounding), and how far away it is; `point` itself at distance 0 when inside.
    struct SurfacePoint {
        Vec2 point;
        float distance = 0.0f;
    };
    SurfacePoint closestSurfacePoint(ChildKey key, const Transform& xf, Vec2 point) const;

    // The ray p1 -> p2 against one child; a hit below maxFraction fills `result`.
    bool rayCast(ChildKey key, const Transform& xf, Vec2 p1, Vec2 p2, float maxFraction, RayCastResult& result) const;
    // b2ShapeCast of `query` at xf moved by `translation` against one child; false when it misses.
    // An overlap at the start is a hit at fraction 0 (b2TestOverlap), normal −translation/|translation|.
    bool shapeCast(ChildKey key, const Transform& xfKey, const Circle& query, const Transform& xf, Vec2 translation,
                   ShapeCastResult& result) const;
    bool shapeCast(ChildKey key, const Transform& xfKey, const Polygon& query, const Transform& xf, Vec2 translation,
                   ShapeCastResult& result) const;
    bool shapeCast(ChildKey key, const Transform& xfKey, const Segment& query, const Transform& xf, Vec2 translation,
                   ShapeCastResult& result) const;
    // Calls visit(proxy, maxFraction) for proxies whose fat AABB the ray p1 -> p2 crosses; visit returns
    // the new maxFraction (0 stops, a negative value leaves it unchanged).
    template <class Visit>
    void rayCastTree(Vec2 p1, Vec2 p2, Visit&& visit) const {
        rayCastImpl(p1, p2, &visit, [](void* v, int proxy, float maxFraction) {
            return (*static_cast<Visit*>(v))(proxy, maxFraction);
        });
    }

    // Time of impact (advanceToImpact, conservative advancement on b2Distance): fraction t in [0, 1]
    // of the first time the two moving children come within Box2D's target separation; 0 if they
    // already are at the start, 1 if they never do.
    float timeOfImpact(ChildKey a, const Sweep& sweepA, ChildKey b, const Sweep& sweepB) const;
    // The same for a small disc of radius coreRadius at shape A's centroid (Box2D v3's fallback when
    // the shapes already touch at the start: the core still must not pass through).
    float coreTimeOfImpact(int shapeA, float coreRadius, const Sweep& sweepA, ChildKey b, const Sweep& sweepB) const;
    // Smallest distance from the shape's centroid to its surface, and largest distance from the
    // shape frame's origin to its surface (rounding included); 0 for segments and chains.
    float minExtent(int shape) const;
    float maxExtent(int shape) const;
    // How far the points that place the shape's box (a circle's centre, vertices) lie from `pivot`
    // (body frame) at most: turning the body about the pivot moves its box by at most this times
    // |q₁ − q₀| (a circle turning about its own centre keeps its box).
    float turningReach(int shape, Vec2 pivot) const;

private:
    void queryImpl(const AABB& aabb, void* context, bool (*visit)(void*, int)) const;
    void queryStaticImpl(const AABB& aabb, void* context, bool (*visit)(void*, int)) const;
    void queryNewPairsImpl(const int* group, int count, void* context, void (*visit)(void*, int, int)) const;
    void rayCastImpl(Vec2 p1, Vec2 p2, void* context, float (*visit)(void*, int, float)) const;
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace perpdot::collide
