// The state of four solver bodies as simd::Float4 lanes, for the rows that solve four
// constraints of one graph colour at once (contacts: contact_solver_wide.hpp, revolute joints:
// joint_solver_wide.hpp). No two lanes hold the same dynamic body, so the lanes can be written
// back in any order.
#pragma once

#include <vector>

#include "core/step_context.hpp"

namespace perpdot {

// v, ω, Δp and Δq of the bodies in four solver slots.
inline BodyLanes<simd::Float4> gatherBodies(const std::vector<BodyState>& states, const int (&slots)[4]) {
    float vx[4], vy[4], w[4], dpx[4], dpy[4], dqc[4], dqs[4];
    for (int i = 0; i < 4; ++i) {
        const BodyState& s = states[slots[i]];
        vx[i] = s.v.x;
        vy[i] = s.v.y;
        w[i] = s.w;
        dpx[i] = s.dp.x;
        dpy[i] = s.dp.y;
        dqc[i] = s.dq.c;
        dqs[i] = s.dq.s;
    }
    return {{simd::Float4::load(vx), simd::Float4::load(vy)},
            simd::Float4::load(w),
            {simd::Float4::load(dpx), simd::Float4::load(dpy)},
            {simd::Float4::load(dqc), simd::Float4::load(dqs)}};
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

}  // namespace perpdot
