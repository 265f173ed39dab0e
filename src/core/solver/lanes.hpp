// Hecker's 2D algebra over a lane type F: float (one row at a time) or simd::Float4 (four rows).
// For F = float the vector and rotation types are math.hpp's own Vec2 and Rot, so scalar code
// uses exactly math.hpp's functions; Vec2Lanes/RotLanes carry the same formulas across lanes.
#pragma once

#include <type_traits>

#include "simd/simd.hpp"
#include "perpdot/math.hpp"

namespace perpdot {

template <class F>
struct Vec2Lanes {
    F x{}, y{};
};

template <class F>
struct RotLanes {
    F c{}, s{};
};

template <class F>
using Vec2T = std::conditional_t<std::is_same_v<F, float>, Vec2, Vec2Lanes<F>>;
template <class F>
using RotT = std::conditional_t<std::is_same_v<F, float>, Rot, RotLanes<F>>;

template <class F>
Vec2Lanes<F> operator+(Vec2Lanes<F> a, Vec2Lanes<F> b) {
    return {a.x + b.x, a.y + b.y};
}
template <class F>
Vec2Lanes<F> operator-(Vec2Lanes<F> a, Vec2Lanes<F> b) {
    return {a.x - b.x, a.y - b.y};
}
template <class F>
Vec2Lanes<F> operator-(Vec2Lanes<F> a) {
    return {-a.x, -a.y};
}
template <class F>
Vec2Lanes<F> operator*(F s, Vec2Lanes<F> a) {
    return {s * a.x, s * a.y};
}
template <class F>
F dot(Vec2Lanes<F> a, Vec2Lanes<F> b) {
    return a.x * b.x + a.y * b.y;
}
// perp(r) = (-r.y, r.x); perpDot(a, b) = perp(a)·b.
template <class F>
Vec2Lanes<F> perp(Vec2Lanes<F> r) {
    return {-r.y, r.x};
}
template <class F>
F perpDot(Vec2Lanes<F> a, Vec2Lanes<F> b) {
    return a.x * b.y - a.y * b.x;
}
// a/|a|, or zero where |a| ≤ 1e-12: math.hpp's normalize lane by lane (the same operations, and
// +0 where it returns Vec2{}).
template <class F>
Vec2Lanes<F> normalize(Vec2Lanes<F> a) {
    const F len = simd::sqrt(dot(a, a));
    const auto unit = len > F(1.0e-12f);
    const F inverse = F(1.0f) / len;
    return {simd::select(unit, inverse * a.x, F(0.0f)), simd::select(unit, inverse * a.y, F(0.0f))};
}
// v_B = v + ω perp(r).
template <class F>
Vec2Lanes<F> pointVelocity(Vec2Lanes<F> v, F omega, Vec2Lanes<F> r) {
    return {v.x - omega * r.y, v.y + omega * r.x};
}
template <class F>
Vec2Lanes<F> rotate(RotLanes<F> q, Vec2Lanes<F> v) {
    return {q.c * v.x - q.s * v.y, q.s * v.x + q.c * v.y};
}

// Per-substep state of a solver body (see BodyState in step_context.hpp, which is BodyLanes<float>).
// Eight floats aligned on 32 bytes: the rows gather the states of the bodies of every lane from
// anywhere in the array, and a state never spans two cache lines.
template <class F>
struct alignas(32) BodyLanes {
    Vec2T<F> v;   // linear velocity of the centre of mass
    F w{};        // angular velocity ω
    Vec2T<F> dp;  // centre-of-mass displacement since the step began
    RotT<F> dq;   // rotation since the step began
    F invMass{};  // 1/m, fixed for the step (0: the static slot, a kinematic body), for the contact rows
};

}  // namespace perpdot
