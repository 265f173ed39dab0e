// The state of four solver bodies as simd::Float4 lanes (or eight, LaneBodies), for the rows that solve
// several constraints of one graph colour at once (contacts: contact_solver_wide.hpp, joints:
// joint_solver_wide.hpp). No two lanes hold the same dynamic body, so the lanes can be written
// back in any order.
#pragma once

#include <cstddef>
#include <vector>

#include "core/world/step_context.hpp"

namespace perpdot {

static_assert(sizeof(BodyState) == 8 * sizeof(float) && offsetof(BodyState, dp) == 3 * sizeof(float),
              "a body's state is the floats v.x, v.y, ω, Δp.x, Δp.y, Δq.c, Δq.s, 1/m");

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

// The bodies of solver slots as lanes of F, for the rows templated on F: gather, scatter and
// velocityChange at F's width (one slot for float). float's and Float4's are here; Float8's are in
// the AVX2 file (contact_solver_avx2.cpp), the one place its type may be named.
template <class F>
struct LaneBodies;

template <>
struct LaneBodies<float> {
    // A body's velocity change per substep from its forces (restitution's deceleration).
    static Vec2 velocityChange(const SubstepForces* forces, int slot) { return forces[slot].dv; }
};

template <>
struct LaneBodies<simd::Float4> {
    using Float4 = simd::Float4;
    using Slots = int[4];

    // The states of the bodies in four solver slots: each body's (v.x, v.y, ω, Δp.x) and
    // (Δp.y, Δq.c, Δq.s, 1/m) as a row, then rows turned into lanes.
    static BodyLanes<Float4> gather(const BodyState* states, const Slots& slots) {
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

    // Write back the velocities the rows changed (Δp and Δq are the integrator's). The static
    // slot 0 is skipped: lanes share it and it never moves.
    static void scatter(BodyState* states, const Slots& slots, const BodyLanes<Float4>& lanes) {
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

    static Vec2Lanes<Float4> velocityChange(const SubstepForces* forces, const Slots& slots) {
        float x[4], y[4];
        for (int lane = 0; lane < 4; ++lane) {
            x[lane] = forces[slots[lane]].dv.x;
            y[lane] = forces[slots[lane]].dv.y;
        }
        return {Float4::load(x), Float4::load(y)};
    }
};

// The loop over blocks of one graph colour, for contacts at every width and for joints:
// `rows(block, a, b)` on the blocks of [begin, end) that `needs`, each block's bodies (its slots
// bodyA, bodyB) gathered into lanes of F and their velocities scattered back. With `ahead` > 0
// the bodies of the block `ahead` on are asked for meanwhile (prefetchBodies: the contacts, at
// bodiesAhead; the joints' longer rows ask for none).
template <class F, int ahead, class Block, class Rows, class Needs>
void forBlocks(Block* blocks, int begin, int end, BodyState* states, Rows rows, Needs needs) {
    for (int k = begin; k < end; ++k) {
        Block& block = blocks[k];
        if (!needs(block)) continue;
        if (ahead > 0 && k + ahead < end && needs(blocks[k + ahead]))
            prefetchBodies(states, blocks[k + ahead].bodyA, blocks[k + ahead].bodyB);
        BodyLanes<F> a = LaneBodies<F>::gather(states, block.bodyA);
        BodyLanes<F> b = LaneBodies<F>::gather(states, block.bodyB);
        rows(block, a, b);
        LaneBodies<F>::scatter(states, block.bodyA, a);
        LaneBodies<F>::scatter(states, block.bodyB, b);
    }
}

// Every block: no block is skipped.
struct EveryBlock {
    template <class Block>
    constexpr bool operator()(const Block&) const { return true; }
};

}  // namespace perpdot
