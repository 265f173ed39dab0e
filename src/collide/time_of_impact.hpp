// Time of impact by conservative advancement on b2Distance — perpdot's replacement for
// b2TimeOfImpact, whose b2SeparationFunction asserts (and aborts the process) when b2Distance
// returns a non-finite distance, which degenerate or extreme sweeps can cause.
#pragma once

#include <box2d/b2_distance.h>

#include "collide/collision.hpp"

namespace perpdot::collide {

// One probe of conservative advancement (Mirtich 1996) at time t: how far the shapes are from the
// target separation, and a bound on how fast that can shrink per unit of t along the current axis.
struct Advance {
    bool stop = false;         // give up: no impact to report
    float gap = 0.0f;          // distance minus the target
    float closingSpeed = 0.0f; // ≤ 0: the separation along the axis never shrinks
};

// Where conservative advancement ended: at a contact (t), with none before tMax, or out of
// iterations at t (still apart: stopping there is safe).
struct Advanced {
    enum Outcome { Contact, None, OutOfIterations } outcome = None;
    float t = 0.0f;
};

// Conservative advancement: from t = 0, t += gap / closingSpeed until the gap is within
// `tolerance`, or the probe stops, the shapes never close, t reaches `tMax` or `maxIterations`
// pass. Each step leaves the shapes apart, so it never passes the contact. probe(t, iteration)
// -> Advance.
template <class Probe>
Advanced conservativeAdvance(Probe&& probe, float tolerance, float tMax, int maxIterations) {
    float t = 0.0f;
    for (int iteration = 0; iteration < maxIterations; ++iteration) {
        const Advance a = probe(t, iteration);
        if (a.stop) return {};
        if (a.gap < tolerance) return {Advanced::Contact, t};
        if (!(a.closingSpeed > 0.0f)) return {};
        t += a.gap / a.closingSpeed;
        if (!(t < tMax)) return {};
    }
    return {Advanced::OutOfIterations, t};
}

// Fraction t in [0, 1] of the first time the cores of a and b (proxies in their body frames) come
// within Box2D's TOI target separation; 0 if they already are at the start, 1 if they never do or
// if the distance is not finite (a state the world freezes anyway).
float advanceToImpact(const b2DistanceProxy& a, const Sweep& sweepA, const b2DistanceProxy& b, const Sweep& sweepB);

}  // namespace perpdot::collide
