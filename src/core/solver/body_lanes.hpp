// The state of four solver bodies as simd::Float4 lanes, for the rows that solve four
// constraints of one graph colour at once (contacts: contact_solver_wide.hpp, joints:
// joint_solver_wide.hpp). No two lanes hold the same dynamic body, so the lanes can be written
// back in any order.
#pragma once

#include <cstddef>
#include <vector>

#include "core/world/step_context.hpp"

namespace perpdot {

static_assert(sizeof(BodyState) == 8 * sizeof(float) && offsetof(BodyState, dp) == 3 * sizeof(float),
              "a body's state is the floats v.x, v.y, ω, Δp.x, Δp.y, Δq.c, Δq.s, 1/m");

// The states of the bodies in four solver slots: each body's (v.x, v.y, ω, Δp.x) and
// (Δp.y, Δq.c, Δq.s, 1/m) as a row, then rows turned into lanes.
inline BodyLanes<simd::Float4> gatherBodies(const std::vector<BodyState>& states, const int (&slots)[4]) {
    using simd::Float4;
    Float4 head[4], tail[4];
    for (int i = 0; i < 4; ++i) {
        const BodyState& s = states[slots[i]];
        head[i] = Float4::loadBytes(&s);
        tail[i] = Float4::loadBytes(&s.dp.y);
    }
    simd::transpose(head);
    simd::transpose(tail);
    return {{head[0], head[1]}, head[2], {head[3], tail[0]}, {tail[1], tail[2]}, tail[3]};
}

// Starts loading, for writing, the states of a block's bodies (solver slots `bodyA`, `bodyB`): a
// pass over blocks asks for those of the block `bodiesAhead` after the one it solves, so that
// their scattered misses overlap the rows in between instead of stalling the gather.
constexpr int bodiesAhead = 2;
template <std::size_t lanes>
inline void prefetchBodies(const BodyState* states, const int (&bodyA)[lanes], const int (&bodyB)[lanes]) {
    for (std::size_t i = 0; i < lanes; ++i) {
        __builtin_prefetch(&states[bodyA[i]], 1);
        __builtin_prefetch(&states[bodyB[i]], 1);
    }
}

// Write back the velocities the rows changed (Δp and Δq are the integrator's). The static slot 0
// is skipped: lanes share it and it never moves.
inline void scatterVelocities(std::vector<BodyState>& states, const int (&slots)[4], const BodyLanes<simd::Float4>& lanes) {
    float vx[4], vy[4], w[4];
    lanes.v.x.store(vx);
    lanes.v.y.store(vy);
    lanes.w.store(w);
    for (int i = 0; i < 4; ++i) {
        if (slots[i] == 0) continue;
        BodyState& s = states[slots[i]];
        s.v = {vx[i], vy[i]};
        s.w = w[i];
    }
}

// A body's velocity change per substep from its forces (restitution's deceleration), for one
// solver slot or for four as lanes.
inline Vec2 substepVelocityChange(const std::vector<SubstepForces>& forces, int slot) { return forces[slot].dv; }
inline Vec2Lanes<simd::Float4> substepVelocityChange(const std::vector<SubstepForces>& forces, const int (&slots)[4]) {
    float x[4], y[4];
    for (int lane = 0; lane < 4; ++lane) {
        x[lane] = forces[slots[lane]].dv.x;
        y[lane] = forces[slots[lane]].dv.y;
    }
    return {simd::Float4::load(x), simd::Float4::load(y)};
}

}  // namespace perpdot
