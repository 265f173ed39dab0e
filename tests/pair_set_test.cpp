// collide::PairSet against std::set under churn: pairs inserted and erased at random, as the
// broadphase does, must leave exactly the same members (deletion closes probe runs correctly).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <set>

#include "collide/pair_set.hpp"

namespace perpdot::collide {
namespace {

uint64_t pairKey(uint32_t a, uint32_t b) { return (static_cast<uint64_t>(std::min(a, b)) << 32) | std::max(a, b); }

TEST(PairSet, MatchesAReferenceSetUnderChurn) {
    PairSet set;
    std::set<uint64_t> reference;
    std::mt19937 rng(7);
    std::uniform_int_distribution<uint32_t> proxy(0, 300);  // few proxies: many collisions and repeats
    for (int i = 0; i < 200000; ++i) {
        uint32_t a = proxy(rng), b = proxy(rng);
        if (a == b) continue;
        const uint64_t key = pairKey(a, b);
        // Grow to a few thousand pairs, then churn around that size.
        if (rng() % 100 < (reference.size() < 3000 ? 70u : 50u)) {
            EXPECT_EQ(set.insert(key), reference.insert(key).second);
        } else {
            set.erase(key);
            reference.erase(key);
        }
        ASSERT_EQ(set.size(), reference.size());
    }
    for (uint32_t a = 0; a <= 300; ++a)
        for (uint32_t b = a + 1; b <= 300; ++b) ASSERT_EQ(set.contains(pairKey(a, b)), reference.contains(pairKey(a, b)));
}

TEST(PairSet, ReserveKeepsTheKeys) {
    // A restore reserves for its contacts; reserving on a filled set rehashes what it holds.
    PairSet set;
    for (uint32_t a = 1; a <= 40; ++a) set.insert(pairKey(0, a));
    set.reserve(5000);
    set.reserve(10);  // never shrinks
    for (uint32_t a = 1; a <= 60; ++a) EXPECT_EQ(set.contains(pairKey(0, a)), a <= 40) << a;
    for (uint32_t a = 1; a <= 5000; ++a) set.insert(pairKey(1, a + 1));
    EXPECT_EQ(set.size(), 5040u);
    EXPECT_TRUE(set.contains(pairKey(1, 5001)));
    EXPECT_FALSE(set.insert(pairKey(0, 40)));
}

}  // namespace
}  // namespace perpdot::collide
