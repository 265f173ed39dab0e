// Graph colouring of constraints: no two constraints of one colour share a dynamic body, so the
// constraints of a colour can be solved side by side (SIMD lanes) with the same result as one
// after another. Static bodies never move, so any number of constraints of a colour may touch one.
#pragma once

#include <algorithm>
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

// A colour's constraints in slotBuckets parts by where their bodies are: part b holds those whose
// first moving body (the lower solver slot of the two, or the one that moves) has a slot in
// [b, b + 1) slots / slotBuckets. The workers that share a colour's constraints take them from
// k/n of the way along (solver_stages.hpp), so each meets about the same bodies colour after
// colour, their states in its own cache. In pool order instead, the bodies of a scattered scene
// (smash) went from worker to worker at every colour, and each worker's rows ran half as fast.
// Within a colour the order changes no result: its constraints share no moving body.
constexpr int slotBuckets = 16;
inline int slotBucket(int slotA, int slotB, int slots) {
    const int first = slotA == 0 ? slotB : slotB == 0 ? slotA : std::min(slotA, slotB);  // slot 0: static
    return static_cast<int>(static_cast<int64_t>(first) * slotBuckets / slots);
}

// Counting sort: `order` becomes the positions 0..n-1 of `keys` (colour · slotBuckets + part) by
// key, each key's in their original order (stable, so the solve order stays deterministic); the
// colours' starts in `order`.
ColorStarts sortByColor(const std::vector<int>& keys, std::vector<int>& order);

}  // namespace perpdot
