// A fresh shape for Box2D 2.4.1's dynamic tree over the leaves it holds (tree_rebuild.cpp).
// b2DynamicTree inserts a leaf where it costs least at that moment and keeps heights balanced by
// rotations; after many re-insertions (a tumbling pile re-inserts a twentieth of its proxies a
// step) its nodes overlap far more than a tree built over all leaves at once, and every query
// descends through them. The tree stays Box2D's: its root and leaves keep their indices, the
// other internal nodes are the same set of indices (handed out in index order, depth first), and
// only links, boxes and heights are rewritten, so its own insertion, removal and balancing go on
// from the new shape. Only collision.cpp (and its test) includes this header (Box2D types).
#pragma once

#include <box2d/b2_dynamic_tree.h>

#include <vector>

namespace perpdot::collide {

// Scratch kept from one rebuild to the next.
struct TreeRebuild {
    struct Leaf {
        float x, y;  // the centre of its box
        b2AABB box;
        int node;
    };
    std::vector<Leaf> leaves;
    std::vector<int> internals, stack;
};

// Builds the tree under `root` (an internal node, which stays the root) again, top down: each
// node's leaves split where the surface area heuristic (perimeters in 2D) costs least, among
// eight planes across the longer axis of their centres.
void rebuildTree(b2TreeNode* nodes, int root, TreeRebuild& scratch);

}  // namespace perpdot::collide
