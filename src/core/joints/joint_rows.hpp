// The row math every joint shares. A scalar row measures
//   Ċ = n·(vB − vA) + sB ωB − sA ωA,   sA = perpDot(rA, n), sB = perpDot(rB, n),
// the velocity along n of B's anchor relative to A's (Hecker: v_P = v + ω perp(r)); with n = 0
// and sA = sB = 1 it is the angular row ωB − ωA. Its inverse effective mass is Hecker's
// denominator 1/mA + 1/mB + perpDot(rA,n)²/IA + perpDot(rB,n)²/IB (1/IA + 1/IB for an angle),
// and every impulse is solved soft-step style: Δλ = −m_eff·massScale·(Ċ + biasRate·C) − impulseScale·λ.
#pragma once

#include <type_traits>

#include "core/joints/joint_store.hpp"

namespace perpdot {

// The helpers below are written over a lane type F (lanes.hpp): float for one joint, simd::Float4
// for four joints of one graph colour (joint_solver_wide.hpp), with the same operations in the
// same order, so a lane computes bit for bit what the scalar joint computes.
template <class F>
struct RowT {
    Vec2T<F> n;
    F sA{}, sB{};
};
using Row = RowT<float>;

template <class F = float>
inline RowT<F> linearRow(Vec2T<F> rA, Vec2T<F> rB, Vec2T<F> n) {
    return {n, perpDot(rA, n), perpDot(rB, n)};
}
// The angular row ωB − ωA: n = 0, sA = sB = 1.
template <class F>
constexpr RowT<F> angularRowOf() {
    return {{}, F(1.0f), F(1.0f)};
}
inline constexpr Row angularRow = angularRowOf<float>();
template <class F>
inline RowT<F> negated(const RowT<F>& r) {
    return {-r.n, -r.sA, -r.sB};
}

template <class F>
inline F effectiveMass(const JointMassT<F>& m, const RowT<F>& r) {
    const F k = (m.mA + m.mB) * dot(r.n, r.n) + m.iA * r.sA * r.sA + m.iB * r.sB * r.sB;
    return simd::select(k > F(0.0f), F(1.0f) / k, F(0.0f));
}

template <class F>
inline F rowVelocity(const JointPairT<F>& p, const RowT<F>& r) {
    return dot(r.n, p.b.v - p.a.v) + r.sB * p.b.w - r.sA * p.a.w;
}

// λ along the row: B gets +λ, A gets −λ (vA −= λ n/mA, ωA −= λ sA/IA).
template <class F>
inline void applyRow(JointPairT<F>& p, const RowT<F>& r, F impulse) {
    p.a.v = p.a.v - (p.m.mA * impulse) * r.n;
    p.a.w = p.a.w - p.m.iA * impulse * r.sA;
    p.b.v = p.b.v + (p.m.mB * impulse) * r.n;
    p.b.w = p.b.w + p.m.iB * impulse * r.sB;
}

// A rigid row is soft (the world's joint stiffness) in the biased pass and rigid, without bias,
// in the relax pass.
inline Softness rigidSoftness(const StepContext& ctx, bool useBias) { return useBias ? ctx.jointSoftness : Softness{}; }

// The same Softness in every lane.
template <class F>
inline SoftnessT<F> everyLane(const Softness& s) {
    return {F(s.biasRate), F(s.massScale), F(s.impulseScale)};
}

// `spring` where `springy`, else `rigid`.
template <class F>
inline SoftnessT<F> selectSoftness(simd::MaskOf<F> springy, const SoftnessT<F>& spring, const Softness& rigid) {
    using simd::select;
    return {select(springy, spring.biasRate, F(rigid.biasRate)), select(springy, spring.massScale, F(rigid.massScale)),
            select(springy, spring.impulseScale, F(rigid.impulseScale))};
}

// An equality row C = 0 (rigid or spring, by `soft`).
template <class F>
inline void solveRow(JointPairT<F>& p, const RowT<F>& r, F mass, F C, const SoftnessT<F>& soft, F& lambda) {
    const F impulse = -mass * soft.massScale * (rowVelocity(p, r) + soft.biasRate * C) - soft.impulseScale * lambda;
    lambda += impulse;
    applyRow(p, r, impulse);
}

// A one-sided row C ≥ 0 with λ ≥ 0 (limits). While C > 0 it is speculative: it lets the gap
// close this substep and no further (bias = C/hs, rigid).
template <class F>
inline void solveLimitRow(JointPairT<F>& p, const RowT<F>& r, F mass, F C, const StepContext& ctx, bool useBias, F& lambda) {
    using simd::select;
    const Softness rigid = rigidSoftness(ctx, useBias);
    const simd::MaskOf<F> speculative = C > F(0.0f);
    const F biasRate = select(speculative, F(ctx.invHs), F(rigid.biasRate));
    const F massScale = select(speculative, F(1.0f), F(rigid.massScale));
    const F impulseScale = select(speculative, F(0.0f), F(rigid.impulseScale));
    const F impulse = -mass * massScale * (rowVelocity(p, r) + biasRate * C) - impulseScale * lambda;
    const F newLambda = simd::max(F(0.0f), lambda + impulse);  // std::max(λ + Δλ, 0), −0 and NaN as it keeps them
    applyRow(p, r, newLambda - lambda);
    lambda = newLambda;
}

// A motor drives Ċ to `speed` with |λ| ≤ maxImpulse (max torque or force × hs).
template <class F>
inline void solveMotorRow(JointPairT<F>& p, const RowT<F>& r, F mass, F speed, F maxImpulse, F& lambda) {
    const F impulse = -mass * (rowVelocity(p, r) - speed);
    // std::clamp(λ + Δλ, −maxImpulse, maxImpulse) as libstdc++ writes it, min(max(x, lo), hi), with
    // its choice among equal zeros and for NaN: std::max(x, lo) is simd::max(lo, x).
    const F newLambda = simd::min(maxImpulse, simd::max(-maxImpulse, lambda + impulse));
    applyRow(p, r, newLambda - lambda);
    lambda = newLambda;
}

// A row that only some of a joint's instances have (a motor, a limit). One joint: solved if it has
// it. Four joints in lanes: solved on all four, then the lanes without it take back their
// velocities and impulses bit for bit, as if the row had been skipped (even applying a zero
// impulse would turn a velocity of −0 into +0).
template <class Solve, class... Lambda>
inline void solveWhere(bool enabled, JointPair&, Solve solve, Lambda&...) {
    if (enabled) solve();
}

template <class Solve, class... Lambda>
inline void solveWhere(simd::Mask4 enabled, JointPairT<simd::Float4>& p, Solve solve, Lambda&... lambdas) {
    using simd::select;
    if (simd::noLane(enabled)) return;
    if (simd::allLanes(enabled)) {
        solve();
        return;
    }
    const BodyLanes<simd::Float4> a = p.a, b = p.b;
    const simd::Float4 before[] = {lambdas...};
    solve();
    p.a.v = {select(enabled, p.a.v.x, a.v.x), select(enabled, p.a.v.y, a.v.y)};
    p.a.w = select(enabled, p.a.w, a.w);
    p.b.v = {select(enabled, p.b.v.x, b.v.x), select(enabled, p.b.v.y, b.v.y)};
    p.b.w = select(enabled, p.b.w, b.w);
    int i = 0;
    ((lambdas = select(enabled, lambdas, before[i++])), ...);
}

// A motor and two limits on one coordinate of a joint (the revolute joint's angle, the prismatic
// joint's translation), as its rows carry them.
template <class F>
struct MotorLimitsT {
    F motorSpeed{}, maxMotor{};  // maxMotor: torque or force
    F lower{}, upper{};
    F motor{}, limit{};  // 1 where enabled, else 0
};

// One pass of them along `row` (effective mass `mass`), each where a joint has it: the motor drives
// Ċ to motorSpeed (|λ| ≤ maxMotor·hs), the limits keep position − lower ≥ 0 and upper − position ≥ 0.
template <class F>
inline void solveMotorAndLimits(JointPairT<F>& p, const RowT<F>& row, F mass, F position, const MotorLimitsT<F>& c,
                                const StepContext& ctx, bool useBias, F& motorImpulse, F& lowerImpulse, F& upperImpulse) {
    solveWhere(
        c.motor != F(0.0f), p, [&] { solveMotorRow(p, row, mass, c.motorSpeed, c.maxMotor * F(ctx.hs), motorImpulse); }, motorImpulse);
    solveWhere(
        c.limit != F(0.0f), p,
        [&] {
            solveLimitRow(p, row, mass, position - c.lower, ctx, useBias, lowerImpulse);
            solveLimitRow(p, negated(row), mass, c.upper - position, ctx, useBias, upperImpulse);
        },
        lowerImpulse, upperImpulse);
}

// --- Point rows: B's anchor held on A's, both directions at once. ---

template <class F>
struct Mat22T {
    Vec2T<F> cx, cy;  // columns
};

// K = (1/mA + 1/mB)·𝟙 + perp(rA)perp(rA)ᵀ/IA + perp(rB)perp(rB)ᵀ/IB, so that uᵀKu is Hecker's
// denominator along any unit u.
template <class F>
inline Mat22T<F> pointMass(const JointMassT<F>& m, Vec2T<F> rA, Vec2T<F> rB) {
    const Vec2T<F> pA = perp(rA), pB = perp(rB);
    const F ms = m.mA + m.mB;
    const F xy = m.iA * pA.x * pA.y + m.iB * pB.x * pB.y;
    return {{ms + m.iA * pA.x * pA.x + m.iB * pB.x * pB.x, xy}, {xy, ms + m.iA * pA.y * pA.y + m.iB * pB.y * pB.y}};
}

// K⁻¹ b (zero when K is singular, e.g. both bodies static).
template <class F>
inline Vec2T<F> solve22(const Mat22T<F>& K, Vec2T<F> b) {
    F det = K.cx.x * K.cy.y - K.cy.x * K.cx.y;
    det = simd::select(det != F(0.0f), F(1.0f) / det, det);
    return {det * (K.cy.y * b.x - K.cy.x * b.y), det * (K.cx.x * b.y - K.cx.y * b.x)};
}

template <class F>
inline Vec2T<F> relativeVelocity(const JointPairT<F>& p, Vec2T<F> rA, Vec2T<F> rB) {
    return pointVelocity(p.b.v, p.b.w, rB) - pointVelocity(p.a.v, p.a.w, rA);
}

// Impulse P at the anchors: B gets +P, A gets −P (ω changes by perpDot(r, P)/I).
template <class F>
inline void applyPoint(JointPairT<F>& p, Vec2T<F> rA, Vec2T<F> rB, Vec2T<F> P) {
    p.a.v = p.a.v - p.m.mA * P;
    p.a.w = p.a.w - p.m.iA * perpDot(rA, P);
    p.b.v = p.b.v + p.m.mB * P;
    p.b.w = p.b.w + p.m.iB * perpDot(rB, P);
}

// The accumulated impulse after one pass of the point constraint C = pB − pA:
// λ − massScale·K⁻¹(v_rel + biasRate·C) − impulseScale·λ. Soft: a Softness, the same in every
// lane, or a SoftnessT<F>, one per lane.
template <class F, class Soft>
inline Vec2T<F> pointImpulse(const JointPairT<F>& p, Vec2T<F> rA, Vec2T<F> rB, Vec2T<F> C, const Soft& soft, Vec2T<F> lambda) {
    const Vec2T<F> b = solve22(pointMass(p.m, rA, rB), relativeVelocity(p, rA, rB) + F(soft.biasRate) * C);
    return lambda - F(soft.massScale) * b - F(soft.impulseScale) * lambda;
}

// One pass of the point rows: λ becomes pointImpulse, and the bodies take the difference.
template <class F, class Soft>
inline void solvePointRows(JointPairT<F>& p, Vec2T<F> rA, Vec2T<F> rB, Vec2T<F> C, const Soft& soft, Vec2T<F>& lambda) {
    const Vec2T<F> newLambda = pointImpulse(p, rA, rB, C, soft, lambda);
    applyPoint(p, rA, rB, newLambda - lambda);
    lambda = newLambda;
}

// The same with the accumulated |λ| capped at maxImpulse (motor and mouse joints): where
// |λ|² > maxImpulse², λ·(maxImpulse/|λ|), a select where one joint branches.
template <class F, class Soft>
inline void solvePointRows(JointPairT<F>& p, Vec2T<F> rA, Vec2T<F> rB, Vec2T<F> C, const Soft& soft, Vec2T<F>& lambda, F maxImpulse) {
    using simd::select;
    Vec2T<F> newLambda = pointImpulse(p, rA, rB, C, soft, lambda);
    const F squared = dot(newLambda, newLambda);
    const simd::MaskOf<F> over = squared > maxImpulse * maxImpulse;
    const F scale = maxImpulse / simd::sqrt(squared);
    newLambda = {select(over, newLambda.x * scale, newLambda.x), select(over, newLambda.y * scale, newLambda.y)};
    applyPoint(p, rA, rB, newLambda - lambda);
    lambda = newLambda;
}

// Two coupled rows solved as a block (prismatic: perpendicular + angle). K_ij is Hecker's
// denominator generalised: (1/mA + 1/mB) n_i·n_j + sA_i sA_j/IA + sB_i sB_j/IB. A row with no
// mass (an angle between two bodies that cannot turn) gets K = 1 so the other still solves.
template <class F>
inline void solveRowPair(JointPairT<F>& p, const RowT<F>& r1, const RowT<F>& r2, Vec2T<F> C, const Softness& soft, Vec2T<F>& lambda) {
    using simd::select;
    const JointMassT<F>& m = p.m;
    const F ms = m.mA + m.mB;
    F k11 = ms * dot(r1.n, r1.n) + m.iA * r1.sA * r1.sA + m.iB * r1.sB * r1.sB;
    F k22 = ms * dot(r2.n, r2.n) + m.iA * r2.sA * r2.sA + m.iB * r2.sB * r2.sB;
    const F k12 = ms * dot(r1.n, r2.n) + m.iA * r1.sA * r2.sA + m.iB * r1.sB * r2.sB;
    k11 = select(k11 != F(0.0f), k11, F(1.0f));
    k22 = select(k22 != F(0.0f), k22, F(1.0f));
    const Vec2T<F> v{rowVelocity(p, r1), rowVelocity(p, r2)};
    const Vec2T<F> b = solve22<F>({{k11, k12}, {k12, k22}}, v + F(soft.biasRate) * C);
    const Vec2T<F> impulse = -F(soft.massScale) * b - F(soft.impulseScale) * lambda;
    lambda = lambda + impulse;
    applyRow(p, r1, impulse.x);
    applyRow(p, r2, impulse.y);
}

// --- Geometry inside a substep ---

// The anchors now: r = rotate(Δq, r0), and d = pB − pA = (ΔpB − ΔpA) + (cB − cA)₀ + rB − rA.
template <class F>
struct JointFrameT {
    Vec2T<F> rA, rB, d;
};
using JointFrame = JointFrameT<float>;

template <class F>
inline JointFrameT<F> currentFrame(const JointPairT<F>& p, Vec2T<F> anchorA, Vec2T<F> anchorB, Vec2T<F> deltaCenter) {
    const Vec2T<F> rA = rotate(p.a.dq, anchorA), rB = rotate(p.b.dq, anchorB);
    return {rA, rB, (p.b.dp - p.a.dp) + deltaCenter + (rB - rA)};
}

inline JointFrame currentFrame(const PreparedJoint& j, const JointPair& p) {
    return currentFrame(p, j.anchorA, j.anchorB, j.deltaCenter);
}

// The rows along an axis fixed in A (prismatic and wheel joints), turned with A since the step
// began: along it and across it, both with A's arm to B's anchor, rA + d; and d along and across it.
template <class F>
struct AxisRowsT {
    RowT<F> axial, perpendicular;
    F translation{}, offset{};
};

template <class F>
inline AxisRowsT<F> axisRows(const JointPairT<F>& p, Vec2T<F> anchorA, Vec2T<F> anchorB, Vec2T<F> deltaCenter, Vec2T<F> axisA) {
    const JointFrameT<F> f = currentFrame(p, anchorA, anchorB, deltaCenter);
    const Vec2T<F> axis = rotate(p.a.dq, axisA);
    return {linearRow<F>(f.rA + f.d, f.rB, axis), linearRow<F>(f.rA + f.d, f.rB, perp(axis)), dot(axis, f.d), dot(perp(axis), f.d)};
}

// The effective mass along a world axis at step start, with A's arm to B's anchor, rA + d.
inline float axialMass(const PreparedJoint& j, Vec2 axis) {
    const Vec2 d = j.deltaCenter + j.anchorB - j.anchorA;
    return effectiveMass(j.mass, linearRow(j.anchorA + d, j.anchorB, axis));
}

// The joint angle now: θB − θA − referenceAngle.
inline float currentAngle(const PreparedJoint& j, const JointPair& p) { return j.deltaAngle + p.rotation; }

}  // namespace perpdot
