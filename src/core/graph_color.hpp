// Graph colouring of constraints: no two constraints of one colour share a dynamic body, so the
// constraints of a colour can be solved side by side (SIMD lanes) with the same result as one
// after another. Static bodies never move, so any number of constraints of a colour may touch one.
#pragma once

#include <array>
#include <bit>
#include <cstdint>
#include <vector>

namespace perpdot {

class GraphColoring {
public:
    static constexpr int colorCount = 16;
    static constexpr int overflow = colorCount;  // the colour of constraints no colour could take

    // Forget all colours; bodies are solver slots 0..bodyCount-1, slot 0 the shared static body.
    void reset(int bodyCount);
    // The lowest colour used by neither body (0 for a static one), now taken at both; overflow if
    // every colour is taken. Deterministic: depends only on the order of the calls. Inline: it
    // runs once for every constraint of a step.
    int assign(int bodyA, int bodyB) {
        const unsigned usedA = bodyA == 0 ? 0u : used_[bodyA];
        const unsigned usedB = bodyB == 0 ? 0u : used_[bodyB];
        const int color = std::countr_one(usedA | usedB);  // lowest colour free at both
        if (color >= colorCount) return overflow;
        const auto bit = static_cast<uint16_t>(1u << color);
        if (bodyA != 0) used_[bodyA] |= bit;
        if (bodyB != 0) used_[bodyB] |= bit;
        return color;
    }

private:
    std::vector<uint16_t> used_;  // per body: bit k set when a constraint of colour k touches it
};

// Where each colour begins in a list sorted by colour: colour c (overflow last) is [start[c], start[c + 1]).
using ColorStarts = std::array<int, GraphColoring::colorCount + 2>;

// Counting sort: `order` becomes the positions 0..n-1 of `colors` grouped by colour, each colour in
// its original order (stable, so the solve order stays deterministic).
ColorStarts sortByColor(const std::vector<int>& colors, std::vector<int>& order);

}  // namespace perpdot
