// The radix sort of (key, value) pairs (src/core/base/radix_sort.hpp) against std::stable_sort: keys
// spread over all four bytes, keys that differ in one byte only (the other passes skipped),
// many equal keys (their values keep their order), and the empty list.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

#include "core/base/radix_sort.hpp"

namespace perpdot {
namespace {

using Items = std::vector<std::pair<uint32_t, int>>;

Items sortedStably(Items items) {
    std::stable_sort(items.begin(), items.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    return items;
}

Items keyed(int count, uint32_t mask, uint32_t seed) {
    std::mt19937 random(seed);
    Items items;
    for (int i = 0; i < count; ++i) items.emplace_back(static_cast<uint32_t>(random()) & mask, i);
    return items;
}

TEST(RadixSort, OrdersLikeAStableSortByKey) {
    const uint32_t masks[] = {0xffffffffu, 0x0000ff00u, 0xff000000u, 0x00000003u, 0x00000000u};
    for (const uint32_t mask : masks) {
        for (const int count : {0, 1, 2, 255, 5000}) {
            Items items = keyed(count, mask, 7u + static_cast<uint32_t>(count));
            const Items expected = sortedStably(items);
            Items scratch;
            radixSort(items, scratch);
            EXPECT_EQ(items, expected) << "mask " << mask << ", " << count << " items";
        }
    }
}

TEST(RadixSort, SortsAgainWithTheSameBuffers) {
    Items items = keyed(3000, 0xffffffffu, 1), scratch;
    radixSort(items, scratch);
    Items again = keyed(2000, 0x00ff00ffu, 2);
    const Items expected = sortedStably(again);
    items = again;
    radixSort(items, scratch);
    EXPECT_EQ(items, expected);
}

}  // namespace
}  // namespace perpdot
