// Union-find over indices 0..n-1 with path halving: the islands of sleeping (sleep.cpp), revolute
// trees (joint_tree.cpp) and directly solved contact groups (contact_groups.cpp).
#pragma once

#include <algorithm>
#include <vector>

namespace perpdot {

inline int findRoot(std::vector<int>& parent, int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
}

// Joins the sets of a and b; the smaller root stays the root, so the result is order-independent.
inline void unite(std::vector<int>& parent, int a, int b) {
    a = findRoot(parent, a);
    b = findRoot(parent, b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
}

}  // namespace perpdot
