#include "core/graph_color.hpp"

#include <cstddef>

namespace perpdot {

static_assert(GraphColoring::colorCount <= 16, "one bit per colour in a uint16_t");

void GraphColoring::reset(int bodyCount) { used_.assign(static_cast<size_t>(bodyCount), 0); }

ColorStarts sortByColor(const std::vector<int>& colors, std::vector<int>& order) {
    ColorStarts start{};
    for (int color : colors) ++start[color + 1];
    for (size_t c = 1; c < start.size(); ++c) start[c] += start[c - 1];
    ColorStarts next = start;
    order.resize(colors.size());
    for (size_t k = 0; k < colors.size(); ++k) order[next[colors[k]]++] = static_cast<int>(k);
    return start;
}

}  // namespace perpdot
