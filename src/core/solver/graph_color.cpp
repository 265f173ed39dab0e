#include "core/solver/graph_color.hpp"

#include <cstddef>

namespace perpdot {

static_assert(GraphColoring::colorCount <= 16, "one bit per colour in a uint16_t");

void GraphColoring::reset(int bodyCount) { used_.assign(static_cast<size_t>(bodyCount), 0); }

ColorStarts sortByColor(const std::vector<int>& keys, std::vector<int>& order) {
    std::array<int, (GraphColoring::colorCount + 1) * slotBuckets + 1> keyStart{};
    for (int key : keys) ++keyStart[static_cast<size_t>(key) + 1];
    for (size_t k = 1; k < keyStart.size(); ++k) keyStart[k] += keyStart[k - 1];
    ColorStarts start{};
    for (size_t c = 0; c < start.size(); ++c) start[c] = keyStart[c * slotBuckets];  // the last: every key
    order.resize(keys.size());
    for (size_t k = 0; k < keys.size(); ++k) order[static_cast<size_t>(keyStart[static_cast<size_t>(keys[k])]++)] = static_cast<int>(k);
    return start;
}

}  // namespace perpdot
