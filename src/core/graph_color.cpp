#include "core/graph_color.hpp"

#include <bit>
#include <cstddef>

namespace perpdot {

static_assert(GraphColoring::colorCount <= 16, "one bit per colour in a uint16_t");

void GraphColoring::reset(int bodyCount) { used_.assign(static_cast<size_t>(bodyCount), 0); }

int GraphColoring::assign(int bodyA, int bodyB) {
    const unsigned usedA = bodyA == 0 ? 0u : used_[bodyA];
    const unsigned usedB = bodyB == 0 ? 0u : used_[bodyB];
    const int color = std::countr_one(usedA | usedB);  // lowest colour free at both
    if (color >= colorCount) return overflow;
    const auto bit = static_cast<uint16_t>(1u << color);
    if (bodyA != 0) used_[bodyA] |= bit;
    if (bodyB != 0) used_[bodyB] |= bit;
    return color;
}

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
