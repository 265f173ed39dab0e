// Graph colouring of constraints: no two constraints of one colour share a dynamic body, so the
// constraints of a colour can be solved side by side (SIMD lanes) with the same result as one
// after another. Static bodies never move, so any number of constraints of a colour may touch one.
#pragma once

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
    // every colour is taken. Deterministic: depends only on the order of the calls.
    int assign(int bodyA, int bodyB);

private:
    std::vector<uint16_t> used_;  // per body: bit k set when a constraint of colour k touches it
};

}  // namespace perpdot
