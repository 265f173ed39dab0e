// Graph colouring of contact constraints (src/core/solver/graph_color.hpp): no two constraints of one
// colour share a dynamic body, static bodies are shared freely, the overflow colour takes what
// the 16 colours cannot, and the result depends only on the order of the constraints.
#include <gtest/gtest.h>

#include <cstdint>
#include <set>
#include <utility>
#include <vector>

#include "core/solver/graph_color.hpp"

namespace perpdot {
namespace {

using Pair = std::pair<int, int>;

std::vector<int> colorAll(int bodyCount, const std::vector<Pair>& pairs) {
    GraphColoring coloring;
    coloring.reset(bodyCount);
    std::vector<int> colors;
    for (const auto& [a, b] : pairs) colors.push_back(coloring.assign(a, b));
    return colors;
}

// Pairs of solver slots 0..bodyCount-1 from a fixed linear congruential sequence; slot 0 is static.
std::vector<Pair> scrambledPairs(int bodyCount, int count) {
    std::vector<Pair> pairs;
    uint32_t x = 12345u;
    const auto next = [&] {
        x = x * 1664525u + 1013904223u;
        return static_cast<int>((x >> 8) % static_cast<uint32_t>(bodyCount));
    };
    while (static_cast<int>(pairs.size()) < count) {
        const int a = next(), b = next();
        if (a != b) pairs.emplace_back(a, b);
    }
    return pairs;
}

TEST(GraphColor, NoDynamicBodyTwiceInOneColor) {
    const std::vector<Pair> pairs = scrambledPairs(200, 1000);
    const std::vector<int> colors = colorAll(200, pairs);
    std::vector<std::set<int>> bodiesOfColor(GraphColoring::colorCount);
    int colored = 0;
    for (size_t i = 0; i < pairs.size(); ++i) {
        const int color = colors[i];
        ASSERT_GE(color, 0);
        ASSERT_LE(color, GraphColoring::overflow);
        if (color == GraphColoring::overflow) continue;
        ++colored;
        for (const int body : {pairs[i].first, pairs[i].second}) {
            if (body == 0) continue;
            EXPECT_TRUE(bodiesOfColor[color].insert(body).second) << "body " << body << " twice in colour " << color;
        }
    }
    EXPECT_GT(colored, 900);  // about 10 constraints per body: nearly all fit in 16 colours
}

TEST(GraphColor, StaticBodyIsSharedFreely) {
    // Twenty bodies resting on the ground (slot 0): one colour holds them all.
    std::vector<Pair> pairs;
    for (int body = 1; body <= 20; ++body) pairs.emplace_back(body % 2 == 0 ? 0 : body, body % 2 == 0 ? body : 0);
    for (const int color : colorAll(21, pairs)) EXPECT_EQ(color, 0);
}

TEST(GraphColor, OverflowWhenABodyTouchesMoreThanTheColors) {
    // A dynamic body touching 20 others: 16 colours, then the overflow set.
    std::vector<Pair> pairs;
    for (int other = 2; other <= 21; ++other) pairs.emplace_back(1, other);
    const std::vector<int> colors = colorAll(22, pairs);
    for (int i = 0; i < 20; ++i) EXPECT_EQ(colors[i], i < GraphColoring::colorCount ? i : GraphColoring::overflow) << i;
    // The same holds for many contacts of one dynamic body against the static one.
    const std::vector<int> againstStatic = colorAll(2, std::vector<Pair>(20, Pair{1, 0}));
    EXPECT_EQ(againstStatic[15], 15);
    EXPECT_EQ(againstStatic[16], GraphColoring::overflow);
}

TEST(GraphColor, DeterministicAndResetForgets) {
    const std::vector<Pair> pairs = scrambledPairs(50, 400);
    EXPECT_EQ(colorAll(50, pairs), colorAll(50, pairs));
    GraphColoring coloring;
    coloring.reset(3);
    EXPECT_EQ(coloring.assign(1, 2), 0);
    EXPECT_EQ(coloring.assign(1, 2), 1);
    coloring.reset(3);
    EXPECT_EQ(coloring.assign(1, 2), 0);
}

}  // namespace
}  // namespace perpdot
