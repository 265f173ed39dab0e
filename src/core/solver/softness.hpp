// Soft constraints (Catto, "Solver2D" soft step): a row with stiffness `hertz` and damping ratio ζ,
// solved over substep h, becomes  Δλ = -effectiveMass⁻¹·massScale·(v + biasRate·C) - impulseScale·λ.
#pragma once

#include <type_traits>

#include "perpdot/math.hpp"

namespace perpdot {

struct Softness {
    float biasRate = 0.0f;
    float massScale = 1.0f;
    float impulseScale = 0.0f;
};

// ω = 2π·hertz, a1 = 2ζ + hω, a2 = hω·a1, a3 = 1/(1 + a2):
// biasRate = ω/a1, massScale = a2·a3, impulseScale = a3.  hertz = 0 is a rigid row.
inline Softness makeSoftness(float hertz, float zeta, float h) {
    if (hertz == 0.0f) return {0.0f, 1.0f, 0.0f};
    const float omega = 2.0f * pi * hertz;
    const float a1 = 2.0f * zeta + h * omega;
    const float a2 = h * omega * a1;
    const float a3 = 1.0f / (1.0f + a2);
    return {omega / a1, a2 * a3, a3};
}

// A Softness per lane of a block of rows (for F = float, Softness itself): a joint's spring's where
// a lane's joint has one, the rigid row's where not; a contact's against the static body or not.
template <class F>
struct SoftnessLanes {
    F biasRate{}, massScale{}, impulseScale{};
};
template <class F>
using SoftnessT = std::conditional_t<std::is_same_v<F, float>, Softness, SoftnessLanes<F>>;

}  // namespace perpdot
