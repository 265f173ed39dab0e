// The dynamic tree is built anew once it has re-inserted as many leaves as it holds
// (CollisionSystem::rebuildTreeIfWorn, tree_rebuild.cpp), rewriting its nodes' links, boxes and
// heights. Afterwards the tree must still find exactly the fat boxes that overlap a probe (every
// node holds its leaves), group queries must still visit what each member's own query would, and
// Box2D's own re-insertions and the in-place moves must go on from the new shape.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "collide/collision.hpp"
#include "collide/tree_rebuild.hpp"
#include "tree_probe.hpp"

namespace perpdot::collide {
namespace {

using Pairs = std::set<std::pair<int, int>>;

TEST(TreeRebuild, AWornTreeIsBuiltAnewAndFindsWhatItFoundBefore) {
    CollisionSystem collision;
    std::mt19937 random(11);
    collision.setGeometry(0, makeBox(0.2f, 0.2f));
    collision.setGeometry(1, makeBox(6.0f, 0.5f));  // walls: boxes that hold many others
    std::vector<int> proxies;
    std::vector<AABB> boxes;
    std::vector<Vec2> velocity;
    std::uniform_real_distribution<float> speed(-0.3f, 0.3f), place(-2.0f, 14.0f);
    for (int i = 0; i < 30; ++i)
        for (int j = 0; j < 30; ++j) {
            const AABB box = collision.computeAABB(0, 0, {{0.45f * i, 0.45f * j}, Rot::fromAngle(0.0f)});
            proxies.push_back(collision.createProxy(box, {0, i * 30 + j}, false));
            boxes.push_back(box);
            velocity.push_back({speed(random), speed(random)});
        }
    for (int k = 0; k < 4; ++k) {
        const AABB box = collision.computeAABB(1, 0, {{6.0f, k < 2 ? 0.0f : 13.0f}, Rot::fromAngle(1.5708f * (k % 2))});
        proxies.push_back(collision.createProxy(box, {1, k}, false));
        boxes.push_back(box);
        velocity.push_back({0.02f * (k % 2 == 0 ? 1.0f : -1.0f), 0.0f});
    }
    std::vector<AABB> prior(proxies.size());
    std::vector<size_t> indexOf(static_cast<size_t>(*std::max_element(proxies.begin(), proxies.end())) + 1);
    for (size_t k = 0; k < proxies.size(); ++k) indexOf[static_cast<size_t>(proxies[k])] = k;
    int rebuilds = 0;
    size_t groupPairs = 0;
    for (int round = 0; round < 80; ++round) {
        // Pair updates rebuild a worn tree before they query it.
        if (collision.rebuildTreeIfWorn()) {
            ++rebuilds;
            for (int probe = 0; probe < 40; ++probe) {
                const Vec2 c{place(random), place(random)};
                const AABB box{c - Vec2{0.8f, 0.5f}, c + Vec2{0.8f, 0.5f}};
                const auto [found, expected] = test::foundAndExpected(collision, proxies, box);
                ASSERT_EQ(found, expected) << "after rebuild " << rebuilds << ", probe " << probe;
            }
            // Groups of neighbours (in creation order: on the grid) visit what their members' own
            // queries find, less a lower moved proxy's pairs and pairs whose boxes overlapped at
            // the last pair update.
            for (size_t first = 0; first + CollisionSystem::groupSize <= proxies.size(); first += 97) {
                const std::vector<int> group(proxies.begin() + static_cast<std::ptrdiff_t>(first),
                                             proxies.begin() + static_cast<std::ptrdiff_t>(first) + CollisionSystem::groupSize);
                Pairs own, grouped;
                for (int proxy : group)
                    collision.query(collision.fatAABB(proxy), [&](int other) {
                        const bool reportedByOther = other < proxy && collision.wasMoved(other);
                        const bool overlappedBefore = round > 0 && overlaps(prior[indexOf[proxy]], prior[indexOf[other]]);
                        if (other != proxy && !reportedByOther && !overlappedBefore) own.emplace(proxy, other);
                        return true;
                    });
                collision.queryNewPairs(group.data(), static_cast<int>(group.size()), [&](int proxy, int other) { grouped.emplace(proxy, other); });
                EXPECT_EQ(grouped, own) << "after rebuild " << rebuilds << ", group at " << first;
                groupPairs += own.size();
            }
        }
        for (size_t k = 0; k < proxies.size(); ++k) {
            collision.clearMoved(proxies[k]);
            prior[k] = collision.fatAABB(proxies[k]);  // the box the next pair update compares with
        }
        // Everything drifts (the walls too): many re-fits, most of them re-insertions.
        for (size_t k = 0; k < proxies.size(); ++k) {
            if (boxes[k].lower.x < -2.0f || boxes[k].upper.x > 16.0f) velocity[k].x = -velocity[k].x;
            if (boxes[k].lower.y < -2.0f || boxes[k].upper.y > 16.0f) velocity[k].y = -velocity[k].y;
            boxes[k] = {boxes[k].lower + velocity[k], boxes[k].upper + velocity[k]};
            if (collision.room(proxies[k], boxes[k]) >= 0.0f) continue;
            ASSERT_TRUE(collision.moveProxy(proxies[k], boxes[k], velocity[k]));
            EXPECT_GE(collision.room(proxies[k], boxes[k]), 0.0f);
        }
        // Between rebuilds the tree still finds exactly the overlapping boxes.
        const Vec2 c{place(random), place(random)};
        const AABB box{c - Vec2{1.0f, 1.0f}, c + Vec2{1.0f, 1.0f}};
        const auto [found, expected] = test::foundAndExpected(collision, proxies, box);
        ASSERT_EQ(found, expected) << "round " << round;
    }
    EXPECT_GE(rebuilds, 3);
    EXPECT_GT(groupPairs, 50u);  // the groups do find new pairs
}

TEST(TreeRebuild, CentresSpreadBeyondTheFloatRangeOrBelowItsResolution) {
    // Boxes at ±2e38 (their centres' spread overflows) and two dozen whose centres differ by
    // subnormals (the bins' scale overflows): the split must still bin every leaf, and the tree
    // must still find exactly the overlapping boxes.
    CollisionSystem collision;
    std::vector<int> proxies;
    for (int i = 0; i < 40; ++i) {
        const float c = (i % 2 == 0 ? 2e38f : -2e38f) * (1.0f + 0.01f * static_cast<float>(i));
        proxies.push_back(collision.restoreProxy({{c, c}, {c, c}}, {i, 0}, false));
    }
    for (int i = 0; i < 24; ++i) {
        const float tiny = 1.4e-45f * static_cast<float>(i);
        proxies.push_back(collision.restoreProxy({{0.0f, 0.0f}, {tiny, tiny}}, {40 + i, 0}, false));
    }
    for (int i = 0; i < 40; ++i)
        proxies.push_back(collision.restoreProxy({{static_cast<float>(i), 1.0f}, {static_cast<float>(i) + 0.5f, 1.5f}}, {64 + i, 0}, false));
    ASSERT_TRUE(collision.rebuildTreeIfWorn());
    for (const AABB& probe : {AABB{{-1.0f, -1.0f}, {1.0f, 1.0f}}, AABB{{0.0f, 0.0f}, {0.0f, 0.0f}}, AABB{{1e38f, 1e38f}, {3e38f, 3e38f}},
                              AABB{{-3e38f, -3e38f}, {0.0f, 0.0f}}, AABB{{5.0f, 0.0f}, {20.0f, 2.0f}}}) {
        const auto [found, expected] = test::foundAndExpected(collision, proxies, probe);
        EXPECT_EQ(found, expected);
        EXPECT_FALSE(expected.empty());
    }
}

TEST(TreeRebuild, InternalNodesAreHandedOutDepthFirstInIndexOrder) {
    // Box2D's own tree over scattered boxes, inserted in random order: its internal nodes lie
    // anywhere. Rebuilt, the same internal indices must follow the new tree depth first (the
    // root aside, which stays where Box2D keeps it), and every node must still hold its children.
    b2DynamicTree tree;
    std::mt19937 random(5);
    std::uniform_real_distribution<float> at(-50.0f, 50.0f);
    std::vector<int> leaves;
    for (int i = 0; i < 300; ++i) {
        const b2Vec2 c{at(random), at(random)};
        leaves.push_back(tree.CreateProxy({c - b2Vec2{0.3f, 0.3f}, c + b2Vec2{0.3f, 0.3f}}, nullptr));
    }
    for (int i = 0; i < 300; i += 3) tree.MoveProxy(leaves[i], {{at(random), 60.0f}, {60.5f, 61.0f}}, {0.0f, 0.0f});
    auto* nodes = const_cast<b2TreeNode*>(&reinterpret_cast<const b2TreeNode&>(tree.GetFatAABB(0)));
    int root = leaves[0];
    while (nodes[root].parent != b2_nullNode) root = nodes[root].parent;
    auto internals = [&] {  // depth first, child1 before child2
        std::vector<int> order, stack{root};
        while (!stack.empty()) {
            const int n = stack.back();
            stack.pop_back();
            if (nodes[n].IsLeaf()) continue;
            order.push_back(n);
            stack.push_back(nodes[n].child2);
            stack.push_back(nodes[n].child1);
        }
        return order;
    };
    std::vector<int> before = internals();
    ASSERT_FALSE(std::is_sorted(before.begin() + 1, before.end()));
    TreeRebuild scratch;
    rebuildTree(nodes, root, scratch);
    const std::vector<int> after = internals();
    EXPECT_EQ(after.front(), root);
    EXPECT_TRUE(std::is_sorted(after.begin() + 1, after.end()));
    std::sort(before.begin(), before.end());
    std::vector<int> kept = after;
    std::sort(kept.begin(), kept.end());
    EXPECT_EQ(kept, before);  // the same indices
    for (int n : after) {
        EXPECT_TRUE(nodes[n].aabb.Contains(nodes[nodes[n].child1].aabb) && nodes[n].aabb.Contains(nodes[nodes[n].child2].aabb));
        EXPECT_EQ(nodes[nodes[n].child1].parent, n);
        EXPECT_EQ(nodes[nodes[n].child2].parent, n);
    }
    tree.Validate();
    EXPECT_EQ(tree.GetHeight(), nodes[root].height);
}

TEST(TreeRebuild, ARestingTreeIsNotRebuilt) {
    CollisionSystem collision;
    collision.setGeometry(0, makeBox(0.2f, 0.2f));
    for (int i = 0; i < 25; ++i)
        for (int j = 0; j < 20; ++j)
            collision.createProxy(collision.computeAABB(0, 0, {{0.5f * static_cast<float>(i), 0.5f * static_cast<float>(j)}, Rot::fromAngle(0.0f)}), {0, 20 * i + j}, false);
    // Creating the proxies inserted each once: the tree is worn out once, never again.
    EXPECT_TRUE(collision.rebuildTreeIfWorn());
    for (int round = 0; round < 10; ++round) EXPECT_FALSE(collision.rebuildTreeIfWorn());
}

}  // namespace
}  // namespace perpdot::collide
