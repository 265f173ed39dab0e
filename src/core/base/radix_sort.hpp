// (key, value) pairs sorted by a 32-bit key, least significant byte first: each of four passes is
// a stable counting sort into the other buffer (a pass is skipped where every key has the same
// byte). Linear in the count; stable, so equal keys keep their order.
#pragma once

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace perpdot {

template <class Value>
void radixSort(std::vector<std::pair<uint32_t, Value>>& items, std::vector<std::pair<uint32_t, Value>>& scratch) {
    constexpr int passes = 4;
    auto digit = [](uint32_t key, int pass) { return (key >> (8 * pass)) & 0xffu; };
    std::array<std::array<int, 256>, passes> counts{};
    for (const auto& item : items)
        for (int pass = 0; pass < passes; ++pass) ++counts[pass][digit(item.first, pass)];
    scratch.resize(items.size());
    for (int pass = 0; pass < passes && !items.empty(); ++pass) {
        std::array<int, 256>& next = counts[pass];
        if (next[digit(items[0].first, pass)] == static_cast<int>(items.size())) continue;  // one digit for all
        int first = 0;  // where each digit's items begin
        for (int& count : next) first += std::exchange(count, first);
        for (const auto& item : items) scratch[next[digit(item.first, pass)]++] = item;
        items.swap(scratch);
    }
}

}  // namespace perpdot
