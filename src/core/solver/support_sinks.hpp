// Piles that keep their height. A soft contact row solved one at a time rests where its spring
// holds its load: with the soft step's Δλ zero and v = 0, massScale·biasRate·C = −impulseScale·λ K_ii,
//   C = −λ K_ii / (hs ω²)                    (the row's rest sink; K_ii its Hecker denominator)
// so the rows under a pile sink in proportion to the weight above them: a 20-row pyramid's top
// 3 cm, a 100-row one's 0.75 m. Two things keep a pile at the height it was built:
//
// - The rest sink, offset. A support row (its normal within about 45° of up, a dynamic body above
//   it) keeps in its contact restSink: the mean over its points of λ₀ K_ii / (hs ω²), λ₀ last
//   step's impulse, low-passed over settleTime and kept to 2⁻²⁰ m. Its points are solved as if
//   that much deeper (their separations less it), so the row rests at C = 0 on average. One offset
//   for a manifold's points moves the body, not the share of the load each point takes;
//   low-passed, it follows the static load and not the rows' oscillation: taken from last step's
//   impulses unfiltered, it stiffens the rows by 1/(1 − κ) at every frequency, and the pile walks
//   (0.38 m at κ = 1).
// - The load path. A support row that is new (touching, no impulse yet, closing no faster than
//   g h) is warm-started with its share of what its body carries: the bodies whose supports are all
//   new (and that have no joints, which carry loads too) are taken from the top down, each one's
//   weight and the loads handed to it from above split over its support points by the lever rule,
//   Σλ = L and Σλ x = L x̄ (x along the ground from the body's centre, x̄ where its load acts). A
//   pile placed touching then carries its top from the first step (the passes alone reach it only
//   after about four steps, the top falling 1.8 cm first). A seeded row takes its rest sink at once.
// Contact groups solved directly rest at C = K F / ω² already (contact_groups.hpp): their rows take
// no offset. docs/stress.md, "Piles that keep their height".
#pragma once

#include <cstdint>

#include "perpdot/math.hpp"

namespace perpdot {

struct StepContext;
struct SolverWorld;  // solver_world.hpp

struct SupportSinks {
    static constexpr float upCosine = 0.7f;           // a support row's normal within about 45° of up
    static constexpr float touching = 0.005f;         // a new row supports from separation ≤ this (m)
    static constexpr float settleTime = 1.0f / 3.0f;  // the rest sinks' low-pass time constant (s)
};

// What settling a row's rest sink needs, the same for every row of a step.
struct RestSinkTerms {
    bool any = false;  // gravity: some row may be a support
    Vec2 up;           // against gravity
    // 1 / (hs ω²) of a row against a body that cannot move and of one between moving bodies, as
    // their softness gives it (impulseScale / (massScale·biasRate)): λ K_ii times it is the rest sink.
    float sinkPerImpulseKStatic = 0, sinkPerImpulseK = 0;
    float alpha = 1;   // of the way to the new mean each step: h / settleTime
};
RestSinkTerms restSinkTerms(Vec2 gravity, const StepContext& ctx);

// The side of the body a contact of normal n (A to B) supports: 1 for B, −1 for A, 0 for none (a
// normal more than about 45° from up, or a body above that cannot move).
inline int supportedSide(Vec2 normal, Vec2 up, float invMassA, float invMassB) {
    const float rise = dot(normal, up);
    if (rise > SupportSinks::upCosine) return invMassB > 0.0f ? 1 : 0;
    if (rise < -SupportSinks::upCosine) return invMassA > 0.0f ? -1 : 0;
    return 0;
}

// x rounded to a multiple of 2⁻²⁰ m (about a micrometre): a settled pile's rest sinks then stop
// changing with the last bits of its impulses, and its snapshots with them. Beyond ±1 km (a world
// thrown apart, tests/fuzz/findings) or NaN, x as it is: the rounding's int32 holds ±2 km.
inline float toMicrometre(float x) {
    constexpr float steps = 1048576.0f;
    if (!(x > -1024.0f && x < 1024.0f)) return x;
    return static_cast<float>(static_cast<int32_t>(x * steps + (x >= 0.0f ? 0.5f : -0.5f))) / steps;
}

// The next rest sink of a support row whose points' λ₀ K_ii sum to `impulseK` over `points` points:
// their mean rest sink, low-passed from `restSink` (taken at once where `seeded`).
inline float settledRestSink(float restSink, float impulseK, int points, bool fixed, bool seeded, const RestSinkTerms& t) {
    const float mean = impulseK * (fixed ? t.sinkPerImpulseKStatic : t.sinkPerImpulseK) / static_cast<float>(points);
    return toMicrometre(seeded ? mean : restSink + t.alpha * (mean - restSink));
}

// Warm-starts the new support rows of bodies whose supports are all new with their static loads,
// in a step in which some contact began touching (before the contact groups, which read loads).
// Writes the contacts' normal impulses and `seeded`, by constraint: 1 where a row was seeded.
void seedSupportLoads(const SolverWorld& world, const StepContext& ctx);

}  // namespace perpdot
