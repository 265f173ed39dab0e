// Pool's live bytes against its items' alive flags: through random creates and destroys, a
// snapshot-style restore (slots read one by one, then the free list), and forEachLive.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "core/base/pool.hpp"

namespace perpdot {
namespace {

struct Item {
    bool alive = false;
    uint32_t generation = 0;
    int value = 0;
};

void expectLiveMatchesAlive(const Pool<Item>& pool) {
    std::vector<int> visited;
    pool.forEachLive([&](int index, const Item& item) {
        EXPECT_TRUE(item.alive) << "slot " << index;
        visited.push_back(index);
    });
    std::vector<int> alive;
    for (int i = 0; i < pool.capacity(); ++i) {
        EXPECT_EQ(pool.isLive(i), pool[i].alive) << "slot " << i;
        if (pool[i].alive) alive.push_back(i);
    }
    EXPECT_EQ(visited, alive);
    EXPECT_EQ(static_cast<int>(alive.size()), pool.size());
}

TEST(Pool, LiveBytesFollowCreatesAndDestroys) {
    Pool<Item> pool;
    std::mt19937 rng(11);
    std::vector<int> live;
    for (int i = 0; i < 5000; ++i) {
        if (live.empty() || rng() % 100 < 55) {
            live.push_back(pool.create());
        } else {
            const size_t k = rng() % live.size();
            pool.destroy(live[k]);
            live[k] = live.back();
            live.pop_back();
        }
        if (i % 500 == 0) expectLiveMatchesAlive(pool);
    }
    expectLiveMatchesAlive(pool);
    EXPECT_GT(pool.capacity(), pool.size());  // free slots in the middle: the bytes were tested on them
}

TEST(Pool, RestoredSlotsTakeTheirAliveFlagsAsLiveBytes) {
    Pool<Item> pool;
    for (int i = 0; i < 6; ++i) pool.create();
    Pool<Item> restored;
    restored.adoptStorage(std::move(pool));
    restored.restoreSlots(5);
    const bool alive[5] = {true, false, true, true, false};
    for (int i = 0; i < 5; ++i) restored[i].alive = alive[i];
    restored.restoreFreeList({4, 1});
    expectLiveMatchesAlive(restored);
    EXPECT_EQ(restored.create(), 1);  // the last freed slot first, and it is live now
    EXPECT_TRUE(restored.isLive(1));
    expectLiveMatchesAlive(restored);
}

}  // namespace
}  // namespace perpdot
