// What the solver stages of one World::step share: the substep, the softness of each kind of row,
// and the velocity/position-delta state of every awake body in one contiguous array.
#pragma once

#include <cstdint>
#include <vector>

#include "core/solver/lanes.hpp"
#include "core/solver/softness.hpp"
#include "perpdot/math.hpp"

namespace perpdot {

// Per-substep state of a solver body: v, ω, Δp, Δq and 1/m (lanes.hpp). Slot 0 is the shared static
// body: it never moves, so rows against static bodies need no branches.
using BodyState = BodyLanes<float>;

// Velocity change a constrained body receives at the start of every substep:
// v = dv + linearDamping·v, ω = dw + angularDamping·ω (a free body gets dv = 0, damping = 1).
struct SubstepForces {
    Vec2 dv;
    float dw = 0;
    float linearDamping = 1;
    float angularDamping = 1;
};

// Rotation after turning by ω·h: q + h ω perp(q), renormalised (exact to first order).
inline Rot integrateRotation(Rot q, float angle) {
    const Rot r{q.c - angle * q.s, q.s + angle * q.c};
    const float invLength = 1.0f / std::sqrt(r.c * r.c + r.s * r.s);
    return {invLength * r.c, invLength * r.s};
}

// The three passes of the rows in a substep: warm start, solve with soft bias, relax without it.
enum class RowPass : uint8_t { WarmStart, Solve, Relax, Restitution };  // Restitution: contacts only, after the substeps

struct StepContext {
    float h = 0;       // the whole step
    float invH = 0;
    float hs = 0;      // one substep
    float invHs = 0;
    int substeps = 1;
    Softness contactSoftness;  // dynamic against dynamic
    Softness staticSoftness;   // dynamic against static or kinematic: twice as stiff
    Softness jointSoftness;
    float restitutionThreshold = 1.0f;
    float maxBiasVelocity = 3.0f;
    float maxLinearSpeed = 0;  // WorldDef::maxLinearSpeed: the step clamps every speed it writes to it
    // Overlap left unpushed: Box2D 2.4's linear slop on its skin (WorldDef::box2dSkin), else none.
    float pushSlop = 0.0f;
    bool enableWarmStarting = true;
    bool hitEvents = false;  // some shape reports hits: every contact point records its largest push
};

}  // namespace perpdot
