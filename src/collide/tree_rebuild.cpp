#include "collide/tree_rebuild.hpp"

#include <algorithm>

namespace perpdot::collide {
namespace {

constexpr int bins = 8;
// Below this depth a split may be as uneven as the heuristic likes; deeper, leaves split at their
// median, so the tree's height stays within this depth plus log₂ of the leaf count.
constexpr int unevenDepth = 40;
// So few leaves split at their median too: the bins would cost more than they find.
constexpr int fewLeaves = 16;

b2AABB combined(const b2AABB& a, const b2AABB& b) {
    b2AABB c;
    c.Combine(a, b);
    return c;
}

struct Builder {
    b2TreeNode* nodes;
    TreeRebuild& s;
    int nextInternal = 0;

    // Where leaves [begin, end) split: the cost of a plane is perimeter · count on each side (a
    // query enters a node about as often as its perimeter is long), planes at eight bins of the
    // centres along `axis`.
    int splitAt(int begin, int end, int axis, float lo, float hi) {
        TreeRebuild::Leaf* leaves = s.leaves.data();
        const float scale = static_cast<float>(bins) / (hi - lo);
        // A bin for any float: centres spread wider than the float range (an infinite spread, a
        // zero scale) or narrower than its resolution (an infinite scale, NaN for the lowest)
        // fall in the end bins, never outside them.
        auto binOf = [&](const TreeRebuild::Leaf& leaf) {
            const float t = ((axis == 0 ? leaf.x : leaf.y) - lo) * scale;
            return t < static_cast<float>(bins) ? (t > 0.0f ? static_cast<int>(t) : 0) : bins - 1;
        };
        int count[bins] = {};
        b2AABB box[bins];
        for (int i = begin; i < end; ++i) {
            const int b = binOf(leaves[i]);
            box[b] = count[b]++ == 0 ? leaves[i].box : combined(box[b], leaves[i].box);
        }
        float rightCost[bins] = {};  // of bins [b, bins)
        b2AABB side = leaves[begin].box;  // (set from the first bin with leaves)
        int n = 0;
        for (int b = bins - 1; b > 0; --b) {
            if (count[b] > 0) side = n == 0 ? box[b] : combined(side, box[b]);
            n += count[b];
            rightCost[b] = n > 0 ? side.GetPerimeter() * static_cast<float>(n) : 0.0f;
        }
        float best = 0.0f;
        int split = -1;
        n = 0;
        for (int b = 0; b + 1 < bins; ++b) {
            if (count[b] > 0) side = n == 0 ? box[b] : combined(side, box[b]);
            n += count[b];
            if (n == 0 || n == end - begin) continue;
            const float cost = side.GetPerimeter() * static_cast<float>(n) + rightCost[b + 1];
            if (split < 0 || cost < best) {
                best = cost;
                split = b;
            }
        }
        if (split < 0) return begin + (end - begin) / 2;  // all in one bin (binOf's end bins)
        return static_cast<int>(std::partition(leaves + begin, leaves + end, [&](const TreeRebuild::Leaf& leaf) { return binOf(leaf) <= split; }) - leaves);
    }

    int build(int begin, int end, int parent, int depth) {
        TreeRebuild::Leaf* leaves = s.leaves.data();
        if (end - begin == 1) {
            nodes[leaves[begin].node].parent = parent;
            return leaves[begin].node;
        }
        const int node = s.internals[static_cast<size_t>(nextInternal++)];
        float lo[2] = {leaves[begin].x, leaves[begin].y}, hi[2] = {lo[0], lo[1]};
        for (int i = begin + 1; i < end; ++i) {
            lo[0] = std::min(lo[0], leaves[i].x), hi[0] = std::max(hi[0], leaves[i].x);
            lo[1] = std::min(lo[1], leaves[i].y), hi[1] = std::max(hi[1], leaves[i].y);
        }
        const int axis = hi[0] - lo[0] >= hi[1] - lo[1] ? 0 : 1;
        int mid = begin + (end - begin) / 2;  // all centres alike: any split
        if (hi[axis] > lo[axis]) {
            if (depth < unevenDepth && end - begin > fewLeaves) {
                mid = splitAt(begin, end, axis, lo[axis], hi[axis]);
            } else {
                std::nth_element(leaves + begin, leaves + mid, leaves + end, [&](const TreeRebuild::Leaf& a, const TreeRebuild::Leaf& b) {
                    return axis == 0 ? a.x < b.x : a.y < b.y;
                });
            }
        }
        const int left = build(begin, mid, node, depth + 1);
        const int right = build(mid, end, node, depth + 1);
        b2TreeNode& n = nodes[node];
        n.parent = parent;
        n.child1 = left;
        n.child2 = right;
        n.aabb = combined(nodes[left].aabb, nodes[right].aabb);
        n.height = 1 + std::max(nodes[left].height, nodes[right].height);
        return node;
    }
};

}  // namespace

void rebuildTree(b2TreeNode* nodes, int root, TreeRebuild& s) {
    s.leaves.clear();
    s.internals.clear();
    s.stack.assign(1, root);
    while (!s.stack.empty()) {  // the root first among the internal nodes: it stays the root
        const int node = s.stack.back();
        s.stack.pop_back();
        const b2TreeNode& n = nodes[node];
        if (n.IsLeaf()) {
            const b2Vec2 center = 0.5f * n.aabb.lowerBound + 0.5f * n.aabb.upperBound;  // (halves: no overflow)
            s.leaves.push_back({center.x, center.y, n.aabb, node});
            continue;
        }
        s.internals.push_back(node);
        s.stack.push_back(n.child2);
        s.stack.push_back(n.child1);
    }
    if (s.leaves.size() < 2) return;
    // The other internal nodes in the order of their indices: the new tree takes them depth first,
    // so a subtree's nodes lie together in memory, and a query's or a re-fit's next node is
    // often in a line just loaded.
    std::sort(s.internals.begin() + 1, s.internals.end());
    Builder{nodes, s}.build(0, static_cast<int>(s.leaves.size()), b2_nullNode, 0);
}

}  // namespace perpdot::collide
