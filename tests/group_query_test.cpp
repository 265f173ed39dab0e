// Moved proxies share a tree query in groups (CollisionSystem::queryNewPairs, updatePairs): a group
// must visit exactly the new pairs its members' own queries would find, boxes that only touch
// included: not a member itself, not a lower proxy that moved too, not a pair whose boxes
// overlapped at the last pair update.
#include <gtest/gtest.h>

#include <random>
#include <set>
#include <utility>
#include <vector>

#include "collide/collision.hpp"

namespace perpdot::collide {
namespace {

using Pairs = std::set<std::pair<int, int>>;

// What each member's own query finds, less itself and the pairs a lower moved proxy reports.
Pairs pairsOfOwnQueries(const CollisionSystem& collision, const std::vector<int>& group) {
    Pairs found;
    for (int proxy : group)
        collision.query(collision.fatAABB(proxy), [&](int other) {
            if (other != proxy && !(other < proxy && collision.wasMoved(other))) found.emplace(proxy, other);
            return true;
        });
    return found;
}

Pairs pairsOfGroupQuery(const CollisionSystem& collision, const std::vector<int>& group) {
    Pairs found;
    collision.queryNewPairs(group.data(), static_cast<int>(group.size()), [&](int proxy, int other) {
        EXPECT_TRUE(found.emplace(proxy, other).second) << "pair visited twice";
    });
    return found;
}

TEST(GroupQuery, VisitsWhatEachMembersOwnQueryWould) {
    CollisionSystem collision;
    std::mt19937 random(7);
    std::uniform_real_distribution<float> place(-20.0f, 20.0f), size(0.1f, 3.0f);
    std::vector<int> proxies;
    // Fat boxes on a 0.5 m lattice (restoreProxy keeps them exactly), so that many only touch.
    auto onLattice = [](float v) { return 0.5f * static_cast<float>(static_cast<int>(2.0f * v)); };
    for (int i = 0; i < 400; ++i) {
        const Vec2 lower{onLattice(place(random)), onLattice(place(random))};
        const Vec2 extent{onLattice(size(random)) + 0.5f, onLattice(size(random)) + 0.5f};
        proxies.push_back(collision.restoreProxy({lower, lower + extent}, {i, 0}, i % 10 == 0));
    }
    std::uniform_int_distribution<int> pick(0, static_cast<int>(proxies.size()) - 1);
    std::uniform_int_distribution<int> members(1, CollisionSystem::groupSize);
    // Half the proxies' moves are done (pairs updated since): their boxes overlapped before.
    for (size_t i = 0; i < proxies.size(); i += 2) collision.clearMoved(proxies[i]);
    size_t visited = 0;
    for (int trial = 0; trial < 200; ++trial) {
        std::vector<int> group;
        for (int m = members(random); m > 0; --m) group.push_back(proxies[static_cast<size_t>(pick(random))]);
        std::sort(group.begin(), group.end());
        group.erase(std::unique(group.begin(), group.end()), group.end());
        Pairs own = pairsOfOwnQueries(collision, group);
        std::erase_if(own, [&](const std::pair<int, int>& p) {  // both settled: overlapped at the last update
            return !collision.wasMoved(p.first) && !collision.wasMoved(p.second);
        });
        EXPECT_EQ(pairsOfGroupQuery(collision, group), own) << "trial " << trial;
        visited += own.size();
    }
    EXPECT_GT(visited, 1000u);  // the groups do find pairs, not just themselves
}

TEST(GroupQuery, BoxesThatOnlyTouchArePairs) {
    CollisionSystem collision;
    const int left = collision.restoreProxy({{0.0f, 0.0f}, {1.0f, 1.0f}}, {0, 0}, false);
    const int right = collision.restoreProxy({{1.0f, 0.0f}, {2.0f, 1.0f}}, {1, 0}, false);      // shares an edge
    const int corner = collision.restoreProxy({{2.0f, 1.0f}, {3.0f, 2.0f}}, {2, 0}, false);     // right's corner
    const int apart = collision.restoreProxy({{3.0f, -1.0f}, {4.0f, 0.99f}}, {3, 0}, false);   // just below corner
    const std::vector<int> group{left, apart};
    const Pairs expected{{left, right}};
    EXPECT_EQ(pairsOfGroupQuery(collision, group), expected);
    EXPECT_EQ(pairsOfOwnQueries(collision, group), expected);
    EXPECT_EQ(pairsOfGroupQuery(collision, {right}), (Pairs{{right, corner}}));  // left is lower and moved too
}

}  // namespace
}  // namespace perpdot::collide
