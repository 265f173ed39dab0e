// Box2D 2.4.1 behind collide::CollisionSystem: b2Shape geometry, b2DynamicTree, b2Collide*.
#include "collide/collision.hpp"
#include "collide/time_of_impact.hpp"

#include "collide/b2_convert.hpp"
#include "collide/capsule_b2.hpp"
#include "collide/chain_b2.hpp"
#include "collide/polygon_b2.hpp"
#include "collide/tree_rebuild.hpp"
#include "simd/simd.hpp"

#include <box2d/b2_circle_shape.h>
#include <box2d/b2_collision.h>
#include <box2d/b2_distance.h>
#include <box2d/b2_dynamic_tree.h>
#include <box2d/b2_edge_shape.h>
#include <box2d/b2_polygon_shape.h>

#include <algorithm>
#include <bit>
#include <cmath>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

namespace perpdot::collide {

namespace {

using collide::toB2;  // b2_convert.hpp's, beside the shape conversions below

Vec2 fromB2(const b2Vec2& v) { return {v.x, v.y}; }
AABB fromB2(const b2AABB& box) { return {fromB2(box.lowerBound), fromB2(box.upperBound)}; }

// A chain is kept as its one-sided child edges, each knowing its neighbours (ghost vertices),
// which is what keeps sliding shapes from catching on inner corners.
using ChainEdges = std::vector<b2EdgeShape>;
using Geometry = std::variant<std::monostate, b2CircleShape, b2PolygonShape, b2EdgeShape, ChainEdges>;

const b2Shape& childShape(const Geometry& g, int child) {
    if (auto* chain = std::get_if<ChainEdges>(&g)) return (*chain)[child];
    if (auto* c = std::get_if<b2CircleShape>(&g)) return *c;
    if (auto* p = std::get_if<b2PolygonShape>(&g)) return *p;
    return std::get<b2EdgeShape>(g);
}

b2EdgeShape toB2(const Segment& segment) {
    b2EdgeShape e;
    e.SetTwoSided(toB2(segment.v1), toB2(segment.v2));
    return e;
}

// The margin a moving child's fat AABB keeps around its box (Box2D v3.2's rule): an eighth of
// its size (circle: radius; polygon, capsule: farthest vertex from the centroid plus rounding;
// segment: half its length), at most maxMargin. Box2D 2.4's tree adds 0.1 m to every box (its
// b2_aabbExtension), which for the 0.4 m boxes of the benchmarks keeps three to five times as many
// contacts whose shapes never touch; the adapter narrows the tree's box (CollisionSystem::Impl::fit).
constexpr float maxMargin = 0.05f;
// Static children move only when the game moves them: a margin of Box2D v3's speculative distance.
constexpr float staticMargin = 4.0f * linearSlop;

// The tree's node array, reached from a node's box (GetFatAABB's reference): b2TreeNode is a
// public standard-layout struct whose first member is that box.
static_assert(std::is_standard_layout_v<b2TreeNode> && offsetof(b2TreeNode, aabb) == 0);
const b2TreeNode* treeNodes(const b2DynamicTree& tree, int node) {
    return reinterpret_cast<const b2TreeNode*>(&tree.GetFatAABB(node)) - node;
}

AABB grownBy(const AABB& box, float margin) { return {box.lower - Vec2{margin, margin}, box.upper + Vec2{margin, margin}}; }

float movingMargin(const b2Shape& shape) {
    float size = 0.0f;
    if (shape.m_type == b2Shape::e_circle) size = shape.m_radius;
    if (shape.m_type == b2Shape::e_polygon) {
        const auto& polygon = static_cast<const b2PolygonShape&>(shape);
        for (int i = 0; i < polygon.m_count; ++i)
            size = std::max(size, (polygon.m_vertices[i] - polygon.m_centroid).Length() + polygon.m_radius);
    }
    if (shape.m_type == b2Shape::e_edge) {
        const auto& edge = static_cast<const b2EdgeShape&>(shape);
        size = 0.5f * (edge.m_vertex2 - edge.m_vertex1).Length();
    }
    return std::min(maxMargin, 0.125f * size);
}

// Box2D's dispatch order: circle < polygon < edge.
int rank(ShapeType t) {
    switch (t) {
        case ShapeType::Circle: return 0;
        case ShapeType::Polygon:
        case ShapeType::Capsule: return 1;  // a 2-vertex b2PolygonShape
        case ShapeType::Segment:
        case ShapeType::Chain: return 2;
    }
    return 0;
}

}  // namespace

struct CollisionSystem::Impl {
    std::vector<Geometry> geometry;  // by shape index
    b2DynamicTree tree;
    b2DynamicTree staticTree;         // static proxies again; a leaf's user data is its proxy id in `tree`
    std::vector<int> staticLeaf;      // by proxy id: its leaf in staticTree, or -1
    std::vector<ChildKey> key;        // by proxy id: the shape and child it bounds (not in the tree's
                                      // user data: a 32-bit pointer holds only one of the two ints)
    // By proxy id, its fat AABB as the tree holds it: 16 bytes a proxy side by side, where the
    // narrowphase's overlap test would otherwise miss the cache on a 40-byte tree node per proxy.
    std::vector<AABB> fat;
    std::vector<float> margin;  // by proxy id: movingMargin or staticMargin

    // The leaf's box (and its static mirror's) becomes `box`, which the box the tree just inserted
    // it with holds: the tree's ancestors still hold the leaf, and are narrowed at their next
    // re-fit. GetFatAABB returns a const reference into the tree's non-const node storage.
    void fit(int proxy, const AABB& box) {
        const b2AABB b{toB2(box.lower), toB2(box.upper)};
        const_cast<b2AABB&>(tree.GetFatAABB(proxy)) = b;
        if (const int leaf = staticLeaf[proxy]; leaf >= 0) const_cast<b2AABB&>(staticTree.GetFatAABB(leaf)) = b;
        fat[proxy] = box;
    }
    // Moves a dynamic proxy's leaf to `box` where it is, without re-inserting it, as Box2D v3
    // enlarges escaped leaves in place: the ancestors below the nearest one that holds `box` (up to
    // the root if none does) become the union of their children again. A move that none of its
    // nearLevels nearest ancestors holds leaves the leaf far from its neighbours, its subtree's box
    // spread over both places: it wears the tree as a re-insertion does, and counts toward the next
    // rebuild (rebuildIfWorn). A re-insertion (b2DynamicTree::MoveProxy) would remove the leaf,
    // descend from the root to insert it again and rebalance on the way back up: several times the
    // cost, and a rebuild spends less per leaf. Either way the leaf's box is `box`: the pairs found
    // do not depend on the tree's shape.
    static constexpr int nearLevels = 5;
    void moveInPlace(int proxy, const AABB& box) {
        const b2AABB b{toB2(box.lower), toB2(box.upper)};
        auto* nodes = const_cast<b2TreeNode*>(treeNodes(tree, proxy));  // the tree's own, non-const storage
        int holder = nodes[proxy].parent, levels = 0;
        for (; holder != b2_nullNode && !nodes[holder].aabb.Contains(b); ++levels) holder = nodes[holder].parent;
        if (levels >= nearLevels || !overlaps(fat[proxy], box)) ++insertions;
        fit(proxy, box);
        nodes[proxy].moved = true;
        for (int n = nodes[proxy].parent; n != holder; n = nodes[n].parent)
            nodes[n].aabb.Combine(nodes[nodes[n].child1].aabb, nodes[nodes[n].child2].aabb);
    }
    // The fat AABB for a proxy's box `aabb` moved along d (predicted).
    AABB fatFor(int proxy, const AABB& aabb, b2Vec2 d) const;
    // The proxy moved from fat AABB `before`: what the next pair update compares with, if not yet known.
    void noteMove(int proxy, const AABB& before);
    // By proxy id, what is known of its fat AABB when pairs were last updated (overlappedBefore):
    // unchanged since, moved from the box in priorFat, or unknown (created, restored, requeried).
    enum class Since : uint8_t { Kept, Moved, New };
    std::vector<Since> since;
    std::vector<AABB> priorFat;  // that box, where since is Moved

    // The proxy's fat AABB at the last pair update, or nullopt where it is not known.
    std::optional<AABB> priorOf(int proxy) const {
        switch (since[proxy]) {
            case Since::Kept: return fat[proxy];
            case Since::Moved: return priorFat[proxy];
            case Since::New: break;
        }
        return std::nullopt;
    }
    // Calls hit.QueryCallback(leaf) for every leaf of `tree` whose box overlaps `box`, as
    // tree.Query would (b2TestOverlap: touching counts), given a leaf `inside` that lies within
    // `box`. The descent tests a node's two children together and asks for the nodes below an
    // overlapping child as it finds it, so that the loads of the nodes it visits overlap (Query
    // tests each node as it takes it from its stack: one load waits on the next). The root is
    // found by climbing from `inside`: the nodes on the way hold its box, so the descent visits
    // them again.
    template <class Hit>
    void descend(int inside, const AABB& box, Hit& hit) const {
        const b2TreeNode* nodes = treeNodes(tree, inside);
        int root = inside;
        while (nodes[root].parent != b2_nullNode) root = nodes[root].parent;
        const b2AABB query{toB2(box.lower), toB2(box.upper)};
        // The nodes left to visit: a pending sibling per level at most.
        constexpr int stackSize = 128;
        if (nodes[root].height >= stackSize) {
            tree.Query(&hit, query);
            return;
        }
        if (!b2TestOverlap(nodes[root].aabb, query)) return;
        if (nodes[root].IsLeaf()) {
            hit.QueryCallback(root);
            return;
        }
        int stack[stackSize];
        int count = 0;
        stack[count++] = root;
        while (count > 0) {
            const b2TreeNode& node = nodes[stack[--count]];
            for (const int child : {node.child1, node.child2}) {
                const b2TreeNode& c = nodes[child];
                if (!b2TestOverlap(c.aabb, query)) continue;
                if (c.IsLeaf()) {
                    hit.QueryCallback(child);
                    continue;
                }
                __builtin_prefetch(&nodes[c.child1]);
                __builtin_prefetch(&nodes[c.child2]);
                stack[count++] = child;
            }
        }
    }
    // Leaves inserted into the tree (created, re-inserted by MoveProxy) or removed since it was
    // last built anew, and the proxies it holds.
    int insertions = 0, proxyCount = 0;
    TreeRebuild rebuildScratch;
    // The tree is built anew (tree_rebuild.hpp) once it has inserted, removed or moved far in place
    // as many leaves as it holds, 64 at least: in bench_tumbler's tumbling pile of 2,000 boxes every twenty
    // steps or so, in a resting world never. A proxy in the tree climbs to the root.
    bool rebuildIfWorn() {
        if (insertions < std::max(64, proxyCount)) return false;
        insertions = 0;
        auto* nodes = const_cast<b2TreeNode*>(treeNodes(tree, 0));  // the tree's own, non-const storage
        for (int proxy = 0; proxy < static_cast<int>(fat.size()); ++proxy) {
            if (nodes[proxy].height != 0) continue;  // a free node, or one reused as an internal node
            int root = proxy;
            while (nodes[root].parent != b2_nullNode) root = nodes[root].parent;
            rebuildTree(nodes, root, rebuildScratch);
            return true;
        }
        return false;
    }
    // Whether both proxies' fat AABBs were known to overlap when pairs were last updated.
    bool overlappedBefore(int proxyA, int proxyB) const {
        const std::optional<AABB> a = priorOf(proxyA), b = priorOf(proxyB);
        return a && b && overlaps(*a, *b);
    }

    // By shape index, a circle about the body origin holding the whole shape, skin and rounding
    // included (extent 0: segments and chains, which have none), and the shape's Box2D radius.
    struct Bound {
        float extent = 0.0f, radius = 0.0f;
    };
    std::vector<Bound> bounds;

    Geometry& slot(int shape) {
        if (static_cast<size_t>(shape) >= geometry.size()) {
            geometry.resize(shape + 1);
            bounds.resize(shape + 1);
        }
        return geometry[shape];
    }

    void setGeometry(int shape, Geometry g) {
        slot(shape) = std::move(g);
        Bound& bound = bounds[shape];
        bound = {};
        if (auto* c = std::get_if<b2CircleShape>(&geometry[shape])) bound = {c->m_p.Length() + c->m_radius, c->m_radius};
        if (auto* p = std::get_if<b2PolygonShape>(&geometry[shape])) {
            float farthest = 0.0f;
            for (int i = 0; i < p->m_count; ++i) farthest = std::max(farthest, p->m_vertices[i].Length());
            bound = {farthest + p->m_radius, p->m_radius};
        }
    }

    // Whether two shapes are too far apart for b2Collide* to report a point. Their cores are
    // D ≥ |pB − pA| − (extentA − rA) − (extentB − rB) apart, r = rA + rB the radii. b2CollidePolygons
    // keeps clipped points up to r past a face's ends, where their separation along the face
    // normal is only √(D² − r²): a point comes while D ≤ √2 r, never once |pB − pA| > extentA +
    // extentB + (√2 − 1) r. Half of r and a slop more absorb the float error, and the collision
    // skins circles may be grown by.
    bool apart(int shapeA, Vec2 originA, int shapeB, Vec2 originB) const {
        const Bound& a = bounds[shapeA];
        const Bound& b = bounds[shapeB];
        if (!(a.extent > 0.0f && b.extent > 0.0f)) return false;
        const float reach = a.extent + b.extent + 0.5f * (a.radius + b.radius) + linearSlop + 2.0f * circleSkin;
        return lengthSquared(originB - originA) > reach * reach;
    }
};

CollisionSystem::CollisionSystem() : impl_(std::make_unique<Impl>()) {}
CollisionSystem::~CollisionSystem() = default;
CollisionSystem& CollisionSystem::operator=(CollisionSystem&&) noexcept = default;

void CollisionSystem::setGeometry(int shape, const Circle& circle) { impl_->setGeometry(shape, toB2(circle)); }
void CollisionSystem::setGeometry(int shape, const Polygon& polygon) { impl_->setGeometry(shape, polygonToB2(polygon)); }

void CollisionSystem::setGeometry(int shape, const Segment& segment) { impl_->setGeometry(shape, toB2(segment)); }
void CollisionSystem::setGeometry(int shape, const Capsule& capsule) { impl_->setGeometry(shape, capsuleToB2(capsule)); }


void CollisionSystem::setGeometry(int shape, const Chain& chain) {
    const ChainPath path = box2dChainPath(chain);
    const std::vector<Vec2>& v = path.vertices;
    const int n = static_cast<int>(v.size());
    const int edgeCount = chain.loop ? n : n - 1;
    // Ghost vertices: the neighbours on a loop, the path's ghosts at the ends of an open chain.
    auto vertex = [&](int i) -> Vec2 {
        if (chain.loop) return v[(i % n + n) % n];
        if (i < 0) return path.prev;
        if (i >= n) return path.next;
        return v[i];
    };
    ChainEdges edges(edgeCount);
    for (int i = 0; i < edgeCount; ++i)
        edges[i].SetOneSided(toB2(vertex(i - 1)), toB2(vertex(i)), toB2(vertex(i + 1)), toB2(vertex(i + 2)));
    impl_->setGeometry(shape, std::move(edges));
}

void CollisionSystem::clearGeometry(int shape) { impl_->setGeometry(shape, std::monostate{}); }

int CollisionSystem::childCount(int shape) const {
    const Geometry& g = impl_->geometry[shape];
    if (auto* chain = std::get_if<ChainEdges>(&g)) return static_cast<int>(chain->size());
    return 1;
}

AABB CollisionSystem::computeAABB(int shape, int child, const Transform& xf) const {
    b2AABB box;
    childShape(impl_->geometry[shape], child).ComputeAABB(&box, toB2(xf), 0);
    return fromB2(box);
}

bool CollisionSystem::canCollide(ShapeType a, ShapeType b) { return rank(a) < 2 || rank(b) < 2; }
bool CollisionSystem::mustSwap(ShapeType a, ShapeType b) { return rank(a) < rank(b); }

int CollisionSystem::createProxy(const AABB& aabb, ChildKey key, bool isStatic) {
    const b2AABB box{toB2(aabb.lower), toB2(aabb.upper)};
    const int proxy = impl_->tree.CreateProxy(box, nullptr);
    ++impl_->insertions;
    ++impl_->proxyCount;
    if (static_cast<size_t>(proxy) >= impl_->staticLeaf.size()) {
        impl_->staticLeaf.resize(proxy + 1, -1);
        impl_->key.resize(proxy + 1);
        impl_->since.resize(proxy + 1);
        impl_->priorFat.resize(proxy + 1);
        impl_->fat.resize(proxy + 1);
        impl_->margin.resize(proxy + 1);
    }
    impl_->since[proxy] = Impl::Since::New;
    impl_->key[proxy] = key;
    impl_->staticLeaf[proxy] = isStatic ? impl_->staticTree.CreateProxy(box, reinterpret_cast<void*>(static_cast<uintptr_t>(proxy))) : -1;
    const bool hasGeometry = static_cast<size_t>(key.shape) < impl_->geometry.size() &&
                             !std::holds_alternative<std::monostate>(impl_->geometry[key.shape]);
    const float margin = isStatic       ? staticMargin
                         : hasGeometry ? movingMargin(childShape(impl_->geometry[key.shape], key.child))
                                       : maxMargin;
    impl_->margin[proxy] = margin;
    impl_->fit(proxy, grownBy(aabb, margin));
    return proxy;
}

void CollisionSystem::destroyProxy(int proxy) {
    if (const int leaf = impl_->staticLeaf[proxy]; leaf >= 0) impl_->staticTree.DestroyProxy(leaf);
    impl_->staticLeaf[proxy] = -1;
    impl_->tree.DestroyProxy(proxy);
    ++impl_->insertions;
    --impl_->proxyCount;
}

namespace {

// The displacement a moved proxy's fat AABB grows along (the tree adds b2_aabbMultiplier times it
// on its side), shortened so that it grows by at most two of Box2D 2.4's margins (0.2 m) more.
// Box2D 2.4's unbounded 4d makes a fast body's box span several steps, and the pairs it finds
// that way never touch (smash: +30 % per step); growing by the margin alone, as Box2D v3 does,
// re-fits a steadily moving body every few steps instead (joint_grid: +24 % instructions). Two
// margins cost joint_grid 1 % and smash nothing (callgrind; one margin: +7 % and −2 %).
b2Vec2 predicted(Vec2 displacement) {
    const float growth = b2_aabbMultiplier * length(displacement);
    const float most = 2.0f * b2_aabbExtension;
    const b2Vec2 d = toB2(displacement);
    return growth > most ? (most / growth) * d : d;
}

}  // namespace

AABB CollisionSystem::Impl::fatFor(int proxy, const AABB& aabb, b2Vec2 d) const {
    // `aabb` with the proxy's own margin around and the growth along d (the tree's would be `aabb`
    // grown by its 0.1 m and by b2_aabbMultiplier d along d).
    AABB box = grownBy(aabb, margin[proxy]);
    const Vec2 growth = b2_aabbMultiplier * Vec2{d.x, d.y};
    (growth.x < 0.0f ? box.lower.x : box.upper.x) += growth.x;
    (growth.y < 0.0f ? box.lower.y : box.upper.y) += growth.y;
    return box;
}

void CollisionSystem::Impl::noteMove(int proxy, const AABB& before) {
    if (since[proxy] != Since::Kept) return;
    since[proxy] = Since::Moved;
    priorFat[proxy] = before;
}

std::optional<AABB> CollisionSystem::inPlaceFat(int proxy, const AABB& aabb, Vec2 displacement) const {
    // A box that overflowed (a body at the edge of the float range) never enters the tree; a static
    // proxy's mirror in the static tree is re-inserted there, and its leaf here too.
    if (!isFinite(aabb.lower) || !isFinite(aabb.upper) || impl_->staticLeaf[proxy] >= 0 || !(room(proxy, aabb) < 0.0f))
        return std::nullopt;
    return impl_->fatFor(proxy, aabb, predicted(displacement));
}

void CollisionSystem::moveInPlace(int proxy, const AABB& fat) {
    const AABB before = fatAABB(proxy);
    impl_->moveInPlace(proxy, fat);
    impl_->noteMove(proxy, before);
}

bool CollisionSystem::moveProxy(int proxy, const AABB& aabb, Vec2 displacement) {
    if (const std::optional<AABB> fat = inPlaceFat(proxy, aabb, displacement)) {
        moveInPlace(proxy, *fat);
        return true;
    }
    if (!isFinite(aabb.lower) || !isFinite(aabb.upper)) return false;  // the proxy keeps its fat AABB
    const b2AABB box{toB2(aabb.lower), toB2(aabb.upper)};
    const b2Vec2 d = predicted(displacement);
    if (const int leaf = impl_->staticLeaf[proxy]; leaf >= 0) impl_->staticTree.MoveProxy(leaf, box, d);
    const AABB before = fatAABB(proxy);
    if (!impl_->tree.MoveProxy(proxy, box, d)) return false;
    ++impl_->insertions;
    impl_->fit(proxy, impl_->fatFor(proxy, aabb, d));
    impl_->noteMove(proxy, before);
    return true;
}

AABB CollisionSystem::fatAABB(int proxy) const { return impl_->fat[proxy]; }

bool CollisionSystem::rebuildTreeIfWorn() { return impl_->rebuildIfWorn(); }

float CollisionSystem::room(int proxy, const AABB& aabb) const {
    const AABB& fat = impl_->fat[proxy];
    return std::min(std::min(aabb.lower.x - fat.lower.x, aabb.lower.y - fat.lower.y),
                    std::min(fat.upper.x - aabb.upper.x, fat.upper.y - aabb.upper.y));
}

// The tree fattens what it is given, so insert `fat` itself (every ancestor then contains the
// fattened box, hence `fat`) and set the leaf's own box to `fat`. GetFatAABB returns a const
// reference to that box in the tree's (non-const) node storage, so writing through it is defined.
int CollisionSystem::restoreProxy(const AABB& fat, ChildKey key, bool isStatic) {
    const int proxy = createProxy(fat, key, isStatic);
    const b2AABB box{toB2(fat.lower), toB2(fat.upper)};
    const_cast<b2AABB&>(impl_->tree.GetFatAABB(proxy)) = box;
    impl_->fat[proxy] = fat;
    if (const int leaf = impl_->staticLeaf[proxy]; leaf >= 0) const_cast<b2AABB&>(impl_->staticTree.GetFatAABB(leaf)) = box;
    return proxy;
}

bool CollisionSystem::proxyIs(int proxy, const AABB& fat, ChildKey key, bool isStatic) const {
    auto same = [](float a, float b) { return std::bit_cast<uint32_t>(a) == std::bit_cast<uint32_t>(b); };
    auto sameBox = [&](const b2AABB& box) {
        return same(box.lowerBound.x, fat.lower.x) && same(box.lowerBound.y, fat.lower.y) &&
               same(box.upperBound.x, fat.upper.x) && same(box.upperBound.y, fat.upper.y);
    };
    const ChildKey k = proxyKey(proxy);
    const int leaf = impl_->staticLeaf[proxy];
    return k.shape == key.shape && k.child == key.child && (leaf >= 0) == isStatic && sameBox(impl_->tree.GetFatAABB(proxy)) &&
           (leaf < 0 || sameBox(impl_->staticTree.GetFatAABB(leaf)));
}

bool CollisionSystem::wasMoved(int proxy) const { return impl_->tree.WasMoved(proxy); }
void CollisionSystem::clearMoved(int proxy) {
    impl_->tree.ClearMoved(proxy);
    impl_->since[proxy] = Impl::Since::Kept;
}
void CollisionSystem::requery(int proxy) { impl_->since[proxy] = Impl::Since::New; }

ChildKey CollisionSystem::proxyKey(int proxy) const { return impl_->key[proxy]; }

void CollisionSystem::queryImpl(const AABB& aabb, void* context, bool (*visit)(void*, int)) const {
    struct Callback {
        void* context;
        bool (*visit)(void*, int);
        bool QueryCallback(int32 proxy) { return visit(context, proxy); }
    } callback{context, visit};
    impl_->tree.Query(&callback, b2AABB{toB2(aabb.lower), toB2(aabb.upper)});
}

void CollisionSystem::queryNewPairsImpl(const int* group, int count, void* context, void (*visit)(void*, int, int)) const {
    static_assert(groupSize == 8, "the members' boxes are tested four at a time, in two halves");
    using simd::Float4;
    struct Callback {
        const Impl& impl;
        const int* group;
        int count;
        // The members' boxes by coordinate; a lane past the members holds a box no box overlaps.
        alignas(16) float lowerX[groupSize], lowerY[groupSize], upperX[groupSize], upperY[groupSize];
        void* context;
        void (*visit)(void*, int, int);
        // The tree tested the hit's box against the union box; b2TestOverlap(leaf, member) is
        // `overlaps` (touching counts), so each member sees exactly what its own query would. The
        // members whose box the hit overlaps are found four at a time: no lane is apart on an axis.
        bool QueryCallback(int32 other) {
            const AABB& box = impl.fat[other];
            unsigned overlapping = 0;
            for (int half = 0; half < count; half += 4) {
                const simd::Mask4 apart = (Float4::load(lowerX + half) > Float4(box.upper.x)) | (Float4::load(lowerY + half) > Float4(box.upper.y)) |
                                          (Float4(box.lower.x) > Float4::load(upperX + half)) | (Float4(box.lower.y) > Float4::load(upperY + half));
                overlapping |= (~simd::laneBits(apart) & 0xFu) << half;
            }
            overlapping &= (1u << count) - 1u;  // (a NaN box is apart from none, the empty lanes included)
            for (; overlapping != 0; overlapping &= overlapping - 1) {
                const int proxy = group[std::countr_zero(overlapping)];
                if (other == proxy || (other < proxy && impl.tree.WasMoved(other))) continue;
                if (!impl.overlappedBefore(proxy, other)) visit(context, proxy, other);
            }
            return true;
        }
    } callback{*impl_, group, count, {}, {}, {}, {}, context, visit};
    AABB all = impl_->fat[group[0]];
    for (int m = 0; m < groupSize; ++m) {
        const AABB box = m < count ? impl_->fat[group[m]] : AABB{{b2_maxFloat, b2_maxFloat}, {-b2_maxFloat, -b2_maxFloat}};
        callback.lowerX[m] = box.lower.x;
        callback.lowerY[m] = box.lower.y;
        callback.upperX[m] = box.upper.x;
        callback.upperY[m] = box.upper.y;
        if (m < count) all = combine(all, box);
    }
    impl_->descend(group[0], all, callback);
}

void CollisionSystem::queryStaticImpl(const AABB& aabb, void* context, bool (*visit)(void*, int)) const {
    struct Callback {
        const b2DynamicTree& staticTree;
        void* context;
        bool (*visit)(void*, int);
        bool QueryCallback(int32 leaf) {
            return visit(context, static_cast<int>(reinterpret_cast<uintptr_t>(staticTree.GetUserData(leaf))));
        }
    } callback{impl_->staticTree, context, visit};
    impl_->staticTree.Query(&callback, b2AABB{toB2(aabb.lower), toB2(aabb.upper)});
}

void CollisionSystem::shiftOrigin(Vec2 newOrigin) {
    impl_->tree.ShiftOrigin(toB2(newOrigin));
    impl_->staticTree.ShiftOrigin(toB2(newOrigin));
    for (AABB& box : impl_->fat) box = {box.lower - newOrigin, box.upper - newOrigin};  // as the tree shifts its nodes
    for (Impl::Since& s : impl_->since)
        if (s == Impl::Since::Moved) s = Impl::Since::New;  // the boxes before are in the old frame
}

namespace {

// What perpdot adds to a b2 shape's separations: collision.hpp's skinOffset, where polygons and
// edges have Box2D's polygon skin, a circle against a circle its collision skin and capsules (b2
// polygons with a radius) none.
float skinOffset(const b2Shape& shape, const b2Shape& other, Skin skin) {
    if (isCapsule(shape)) return 0.0f;
    auto type = [](const b2Shape& s) { return s.m_type == b2Shape::e_circle ? ShapeType::Circle : ShapeType::Polygon; };
    return collide::skinOffset(type(shape), type(other), skin);
}

// `circle` grown by its collision skin against another circle (collision.hpp), which skinOffset
// takes off again.
b2CircleShape withCircleSkin(const b2CircleShape& circle, Skin skin) {
    b2CircleShape grown = circle;
    grown.m_radius += collide::collisionSkin(ShapeType::Circle, ShapeType::Circle, skin);
    return grown;
}

}  // namespace

Manifold CollisionSystem::collide(ChildKey a, const Transform& xfA, ChildKey b, const Transform& xfB, Skin skin) const {
    if (impl_->apart(a.shape, xfA.p, b.shape, xfB.p)) return {};
    const Geometry& ga = impl_->geometry[a.shape];
    const Geometry& gb = impl_->geometry[b.shape];
    const b2Shape& shapeA = childShape(ga, a.child);
    const b2Shape& shapeB = childShape(gb, b.child);
    const b2Transform ta = toB2(xfA), tb = toB2(xfB);

    b2Manifold m;
    m.pointCount = 0;
    const auto* circleB = shapeB.m_type == b2Shape::e_circle ? static_cast<const b2CircleShape*>(&shapeB) : nullptr;
    // The radii wm below measures from: two circles' grown by their skins.
    float radiusA = shapeA.m_radius, radiusB = shapeB.m_radius;
    switch (shapeA.m_type) {
        case b2Shape::e_circle: {
            const b2CircleShape grownA = withCircleSkin(static_cast<const b2CircleShape&>(shapeA), skin);
            const b2CircleShape grownB = withCircleSkin(*circleB, skin);
            b2CollideCircles(&m, &grownA, ta, &grownB, tb);
            radiusA = grownA.m_radius, radiusB = grownB.m_radius;
            break;
        }
        case b2Shape::e_polygon:
            if (circleB)
                b2CollidePolygonAndCircle(&m, static_cast<const b2PolygonShape*>(&shapeA), ta, circleB, tb);
            else
                b2CollidePolygons(&m, static_cast<const b2PolygonShape*>(&shapeA), ta, static_cast<const b2PolygonShape*>(&shapeB), tb);
            break;
        case b2Shape::e_edge:
            if (circleB) {
                // b2CollideEdgeAndCircle asserts e·e > 0; a loop chain's closing edge is not length-
                // checked (compatibility), and e·e underflows to 0 below ~1e-23 m.
                const auto* edge = static_cast<const b2EdgeShape*>(&shapeA);
                const b2Vec2 e = edge->m_vertex2 - edge->m_vertex1;
                if (b2Dot(e, e) > 0.0f) b2CollideEdgeAndCircle(&m, edge, ta, circleB, tb);
            } else
                b2CollideEdgeAndPolygon(&m, static_cast<const b2EdgeShape*>(&shapeA), ta, static_cast<const b2PolygonShape*>(&shapeB), tb);
            break;
        default:
            break;
    }
    // Capsules against a polygon, capsule or segment (not chains: their one-sided rules decide).
    const bool chainChild = std::holds_alternative<ChainEdges>(ga);
    if (!circleB && !chainChild && (isCapsule(shapeA) || isCapsule(shapeB))) capsuleManifold(m, shapeA, ta, shapeB, tb);

    Manifold out;
    out.pointCount = m.pointCount;
    if (m.pointCount == 0) return out;
    b2WorldManifold wm;
    wm.Initialize(&m, ta, radiusA, tb, radiusB);
    out.normal = fromB2(wm.normal);
    // Between the true surfaces the gap is skinA + skinB wider, and its midpoint moves by half the
    // difference along n.
    const float skinA = skinOffset(shapeA, shapeB, skin), skinB = skinOffset(shapeB, shapeA, skin);
    for (int i = 0; i < m.pointCount; ++i) {
        out.points[i].point = fromB2(wm.points[i]) + (0.5f * (skinB - skinA)) * out.normal;
        out.points[i].separation = wm.separations[i] + skinA + skinB;
        out.points[i].id = m.points[i].id.key;
    }
    return out;
}

namespace {

bool overlap(const b2Shape& a, const b2Transform& xfA, const b2Shape& b, const b2Transform& xfB) {
    return b2TestOverlap(&a, 0, &b, 0, xfA, xfB);
}

}  // namespace

bool CollisionSystem::testOverlap(ChildKey a, const Transform& xfA, ChildKey b, const Transform& xfB) const {
    return overlap(childShape(impl_->geometry[a.shape], a.child), toB2(xfA), childShape(impl_->geometry[b.shape], b.child), toB2(xfB));
}

bool CollisionSystem::testOverlap(ChildKey a, const Transform& xfA, const Circle& query, const Transform& xf) const {
    return overlap(childShape(impl_->geometry[a.shape], a.child), toB2(xfA), toB2(query), toB2(xf));
}

bool CollisionSystem::testOverlap(ChildKey a, const Transform& xfA, const Polygon& query, const Transform& xf) const {
    return overlap(childShape(impl_->geometry[a.shape], a.child), toB2(xfA), polygonToB2(query), toB2(xf));
}

bool CollisionSystem::testPoint(int shape, const Transform& xf, Vec2 point) const {
    const Geometry& g = impl_->geometry[shape];
    if (std::holds_alternative<ChainEdges>(g) || std::holds_alternative<b2EdgeShape>(g)) return false;
    if (isCapsule(childShape(g, 0))) return capsuleContains(std::get<b2PolygonShape>(g), toB2(xf), toB2(point));
    return childShape(g, 0).TestPoint(toB2(xf), toB2(point));
}

CoreDistance CollisionSystem::coreDistance(ChildKey a, const Transform& xfA, ChildKey b, const Transform& xfB) const {
    const b2Shape& shapeA = childShape(impl_->geometry[a.shape], a.child);
    const b2Shape& shapeB = childShape(impl_->geometry[b.shape], b.child);
    b2DistanceInput input;
    input.proxyA.Set(&shapeA, 0);
    input.proxyB.Set(&shapeB, 0);
    input.transformA = toB2(xfA);
    input.transformB = toB2(xfB);
    input.useRadii = false;
    b2SimplexCache cache;
    cache.count = 0;
    b2DistanceOutput output;
    b2Distance(&output, &cache, &input);
    return {fromB2(output.pointA), fromB2(output.pointB), output.distance, shapeA.m_radius, shapeB.m_radius};
}

CollisionSystem::SurfacePoint CollisionSystem::closestSurfacePoint(ChildKey key, const Transform& xf, Vec2 point) const {
    const b2Shape& shape = childShape(impl_->geometry[key.shape], key.child);
    b2DistanceInput input;
    input.proxyA.Set(&shape, 0);  // a chain child is already its own edge
    const b2Vec2 p = toB2(point);
    input.proxyB.m_vertices = &p;
    input.proxyB.m_count = 1;
    input.proxyB.m_radius = 0.0f;
    input.transformA = toB2(xf);
    input.transformB = b2Transform(b2Vec2(0.0f, 0.0f), b2Rot(0.0f));
    input.useRadii = false;
    b2SimplexCache cache;
    cache.count = 0;
    b2DistanceOutput output;
    b2Distance(&output, &cache, &input);
    const float rounding = shape.m_radius - (shape.m_type == b2Shape::e_circle || isCapsule(shape) ? 0.0f : polygonRadius);
    if (!(output.distance > rounding)) return {point, 0.0f};
    const Vec2 core = fromB2(output.pointA);
    const Vec2 toPoint = (1.0f / output.distance) * (point - core);
    return {core + rounding * toPoint, output.distance - rounding};
}

bool CollisionSystem::rayCast(ChildKey key, const Transform& xf, Vec2 p1, Vec2 p2, float maxFraction, RayCastResult& result) const {
    b2RayCastInput input{toB2(p1), toB2(p2), maxFraction};
    b2RayCastOutput output;
    const b2Shape& shape = childShape(impl_->geometry[key.shape], key.child);
    const bool hit = isCapsule(shape) ? rayCastCapsule(static_cast<const b2PolygonShape&>(shape), toB2(xf), input, output)
                                      : shape.RayCast(&output, input, toB2(xf), 0);
    if (!hit) return false;
    result = {fromB2(output.normal), output.fraction};
    return true;
}

namespace {

bool shapeCastOf(const b2Shape& target, int child, const b2Transform& xfTarget, const b2Shape& query, const b2Transform& xf,
                 Vec2 translation, ShapeCastResult& result) {
    // Shapes overlapping at the start are a hit at once (b2ShapeCast does not detect every overlap).
    if (b2TestOverlap(&target, child, &query, 0, xfTarget, xf)) {
        result = {fromB2(xf.p), -normalize(translation), 0.0f};
        return true;
    }
    b2ShapeCastInput input;
    input.proxyA.Set(&target, child);
    input.proxyB.Set(&query, 0);
    input.transformA = xfTarget;
    input.transformB = xf;
    input.translationB = toB2(translation);
    b2ShapeCastOutput output;
    if (!b2ShapeCast(&output, &input)) return false;
    result = {fromB2(output.point), fromB2(output.normal), output.lambda};
    return true;
}

}  // namespace

bool CollisionSystem::shapeCast(ChildKey key, const Transform& xfKey, const Circle& query, const Transform& xf,
                                Vec2 translation, ShapeCastResult& result) const {
    const b2CircleShape shape = toB2(query);
    return shapeCastOf(childShape(impl_->geometry[key.shape], key.child), 0, toB2(xfKey), shape, toB2(xf), translation, result);
}

bool CollisionSystem::shapeCast(ChildKey key, const Transform& xfKey, const Polygon& query, const Transform& xf,
                                Vec2 translation, ShapeCastResult& result) const {
    const b2PolygonShape shape = polygonToB2(query);
    return shapeCastOf(childShape(impl_->geometry[key.shape], key.child), 0, toB2(xfKey), shape, toB2(xf), translation, result);
}

bool CollisionSystem::shapeCast(ChildKey key, const Transform& xfKey, const Segment& query, const Transform& xf,
                                Vec2 translation, ShapeCastResult& result) const {
    const b2EdgeShape shape = toB2(query);
    return shapeCastOf(childShape(impl_->geometry[key.shape], key.child), 0, toB2(xfKey), shape, toB2(xf), translation, result);
}

void CollisionSystem::rayCastImpl(Vec2 p1, Vec2 p2, void* context, float (*visit)(void*, int, float)) const {
    struct Callback {
        void* context;
        float (*visit)(void*, int, float);
        float RayCastCallback(const b2RayCastInput& input, int32 proxy) { return visit(context, proxy, input.maxFraction); }
    } callback{context, visit};
    // b2DynamicTree::RayCast asserts a ray of non-zero length (also after squaring underflows).
    if (!(lengthSquared(p2 - p1) > 0.0f)) return;
    impl_->tree.RayCast(&callback, b2RayCastInput{toB2(p1), toB2(p2), 1.0f});
}

float CollisionSystem::timeOfImpact(ChildKey a, const Sweep& sweepA, ChildKey b, const Sweep& sweepB) const {
    b2DistanceProxy proxyA, proxyB;
    proxyA.Set(&childShape(impl_->geometry[a.shape], a.child), 0);
    proxyB.Set(&childShape(impl_->geometry[b.shape], b.child), 0);
    return advanceToImpact(proxyA, sweepA, proxyB, sweepB);
}

float CollisionSystem::coreTimeOfImpact(int shapeA, float coreRadius, const Sweep& sweepA, ChildKey b, const Sweep& sweepB) const {
    const Geometry& g = impl_->geometry[shapeA];
    b2CircleShape core;
    core.m_radius = coreRadius;
    if (auto* c = std::get_if<b2CircleShape>(&g)) core.m_p = c->m_p;
    if (auto* p = std::get_if<b2PolygonShape>(&g)) core.m_p = p->m_centroid;
    b2DistanceProxy proxyA, proxyB;
    proxyA.Set(&core, 0);
    proxyB.Set(&childShape(impl_->geometry[b.shape], b.child), 0);
    return advanceToImpact(proxyA, sweepA, proxyB, sweepB);
}

float CollisionSystem::minExtent(int shape) const {
    const Geometry& g = impl_->geometry[shape];
    if (auto* c = std::get_if<b2CircleShape>(&g)) return c->m_radius;
    const auto* p = std::get_if<b2PolygonShape>(&g);
    if (!p) return 0.0f;
    // Distance from the centroid to the nearest face plane, plus the rounding.
    float extent = b2_maxFloat;
    for (int i = 0; i < p->m_count; ++i)
        extent = std::min(extent, b2Dot(p->m_normals[i], p->m_vertices[i] - p->m_centroid));
    return extent + p->m_radius;
}

float CollisionSystem::maxExtent(int shape) const { return impl_->bounds[shape].extent; }

float CollisionSystem::turningReach(int shape, Vec2 pivot) const {
    const b2Vec2 o = toB2(pivot);
    float reach = 0.0f;
    auto edge = [&](const b2EdgeShape& e) { reach = std::max({reach, (e.m_vertex1 - o).Length(), (e.m_vertex2 - o).Length()}); };
    const Geometry& g = impl_->geometry[shape];
    if (auto* c = std::get_if<b2CircleShape>(&g)) reach = (c->m_p - o).Length();
    if (auto* p = std::get_if<b2PolygonShape>(&g))
        for (int i = 0; i < p->m_count; ++i) reach = std::max(reach, (p->m_vertices[i] - o).Length());
    if (auto* e = std::get_if<b2EdgeShape>(&g)) edge(*e);
    if (auto* chain = std::get_if<ChainEdges>(&g))
        for (const b2EdgeShape& e : *chain) edge(e);
    return reach;
}

}  // namespace perpdot::collide
