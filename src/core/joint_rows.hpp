// The row math every joint shares. A scalar row measures
//   Ċ = n·(vB − vA) + sB ωB − sA ωA,   sA = perpDot(rA, n), sB = perpDot(rB, n),
// the velocity along n of B's anchor relative to A's (Hecker: v_P = v + ω perp(r)); with n = 0
// and sA = sB = 1 it is the angular row ωB − ωA. Its inverse effective mass is Hecker's
// denominator 1/mA + 1/mB + perpDot(rA,n)²/IA + perpDot(rB,n)²/IB (1/IA + 1/IB for an angle),
// and every impulse is solved soft-step style: Δλ = −m_eff·massScale·(Ċ + biasRate·C) − impulseScale·λ.
#pragma once

#include <algorithm>
#include <limits>

#include "core/joint_store.hpp"

namespace perpdot {

struct Row {
    Vec2 n;
    float sA = 0, sB = 0;
};

inline Row linearRow(Vec2 rA, Vec2 rB, Vec2 n) { return {n, perpDot(rA, n), perpDot(rB, n)}; }
inline constexpr Row angularRow{{}, 1.0f, 1.0f};
inline Row negated(Row r) { return {-r.n, -r.sA, -r.sB}; }

inline float effectiveMass(const JointMass& m, Row r) {
    const float k = (m.mA + m.mB) * dot(r.n, r.n) + m.iA * r.sA * r.sA + m.iB * r.sB * r.sB;
    return k > 0.0f ? 1.0f / k : 0.0f;
}

inline float rowVelocity(const JointPair& p, Row r) { return dot(r.n, p.b.v - p.a.v) + r.sB * p.b.w - r.sA * p.a.w; }

// λ along the row: B gets +λ, A gets −λ (vA −= λ n/mA, ωA −= λ sA/IA).
inline void applyRow(JointPair& p, Row r, float impulse) {
    p.a.v -= (p.m.mA * impulse) * r.n;
    p.a.w -= p.m.iA * impulse * r.sA;
    p.b.v += (p.m.mB * impulse) * r.n;
    p.b.w += p.m.iB * impulse * r.sB;
}

// A rigid row is soft (the world's joint stiffness) in the biased pass and rigid, without bias,
// in the relax pass.
inline Softness rigidSoftness(const StepContext& ctx, bool useBias) { return useBias ? ctx.jointSoftness : Softness{}; }

// An equality row C = 0 (rigid or spring, by `soft`).
inline void solveRow(JointPair& p, Row r, float mass, float C, const Softness& soft, float& lambda) {
    const float impulse = -mass * soft.massScale * (rowVelocity(p, r) + soft.biasRate * C) - soft.impulseScale * lambda;
    lambda += impulse;
    applyRow(p, r, impulse);
}

// A one-sided row C ≥ 0 with λ ≥ 0 (limits). While C > 0 it is speculative: it lets the gap
// close this substep and no further.
inline void solveLimitRow(JointPair& p, Row r, float mass, float C, const StepContext& ctx, bool useBias, float& lambda) {
    Softness soft;
    if (C > 0.0f) soft.biasRate = ctx.invHs;
    else soft = rigidSoftness(ctx, useBias);
    const float impulse = -mass * soft.massScale * (rowVelocity(p, r) + soft.biasRate * C) - soft.impulseScale * lambda;
    const float newLambda = std::max(lambda + impulse, 0.0f);
    applyRow(p, r, newLambda - lambda);
    lambda = newLambda;
}

// A motor drives Ċ to `speed` with |λ| ≤ maxImpulse (max torque or force × hs).
inline void solveMotorRow(JointPair& p, Row r, float mass, float speed, float maxImpulse, float& lambda) {
    const float impulse = -mass * (rowVelocity(p, r) - speed);
    const float newLambda = std::clamp(lambda + impulse, -maxImpulse, maxImpulse);
    applyRow(p, r, newLambda - lambda);
    lambda = newLambda;
}

// --- Point rows: B's anchor held on A's, both directions at once. ---

struct Mat22 {
    Vec2 cx, cy;  // columns
};

// K = (1/mA + 1/mB)·𝟙 + perp(rA)perp(rA)ᵀ/IA + perp(rB)perp(rB)ᵀ/IB, so that uᵀKu is Hecker's
// denominator along any unit u.
inline Mat22 pointMass(const JointMass& m, Vec2 rA, Vec2 rB) {
    const Vec2 pA = perp(rA), pB = perp(rB);
    const float ms = m.mA + m.mB;
    const float xy = m.iA * pA.x * pA.y + m.iB * pB.x * pB.y;
    return {{ms + m.iA * pA.x * pA.x + m.iB * pB.x * pB.x, xy}, {xy, ms + m.iA * pA.y * pA.y + m.iB * pB.y * pB.y}};
}

// K⁻¹ b (zero when K is singular, e.g. both bodies static).
inline Vec2 solve22(const Mat22& K, Vec2 b) {
    float det = K.cx.x * K.cy.y - K.cy.x * K.cx.y;
    if (det != 0.0f) det = 1.0f / det;
    return {det * (K.cy.y * b.x - K.cy.x * b.y), det * (K.cx.x * b.y - K.cx.y * b.x)};
}

inline Vec2 relativeVelocity(const JointPair& p, Vec2 rA, Vec2 rB) {
    return pointVelocity(p.b.v, p.b.w, rB) - pointVelocity(p.a.v, p.a.w, rA);
}

// Impulse P at the anchors: B gets +P, A gets −P (ω changes by perpDot(r, P)/I).
inline void applyPoint(JointPair& p, Vec2 rA, Vec2 rB, Vec2 P) {
    p.a.v -= p.m.mA * P;
    p.a.w -= p.m.iA * perpDot(rA, P);
    p.b.v += p.m.mB * P;
    p.b.w += p.m.iB * perpDot(rB, P);
}

// Δλ = −massScale·K⁻¹(v_rel + biasRate·C) − impulseScale·λ for the point constraint C = pB − pA,
// with the accumulated |λ| capped at maxImpulse (motor and mouse joints).
inline void solvePointRows(JointPair& p, Vec2 rA, Vec2 rB, Vec2 C, const Softness& soft, Vec2& lambda,
                           float maxImpulse = std::numeric_limits<float>::infinity()) {
    const Vec2 b = solve22(pointMass(p.m, rA, rB), relativeVelocity(p, rA, rB) + soft.biasRate * C);
    Vec2 newLambda = lambda - soft.massScale * b - soft.impulseScale * lambda;
    if (lengthSquared(newLambda) > maxImpulse * maxImpulse) newLambda *= maxImpulse / length(newLambda);
    applyPoint(p, rA, rB, newLambda - lambda);
    lambda = newLambda;
}

// Two coupled rows solved as a block (prismatic: perpendicular + angle). K_ij is Hecker's
// denominator generalised: (1/mA + 1/mB) n_i·n_j + sA_i sA_j/IA + sB_i sB_j/IB. A row with no
// mass (an angle between two bodies that cannot turn) gets K = 1 so the other still solves.
inline void solveRowPair(JointPair& p, Row r1, Row r2, Vec2 C, const Softness& soft, Vec2& lambda) {
    const JointMass& m = p.m;
    const float ms = m.mA + m.mB;
    float k11 = ms * dot(r1.n, r1.n) + m.iA * r1.sA * r1.sA + m.iB * r1.sB * r1.sB;
    float k22 = ms * dot(r2.n, r2.n) + m.iA * r2.sA * r2.sA + m.iB * r2.sB * r2.sB;
    const float k12 = ms * dot(r1.n, r2.n) + m.iA * r1.sA * r2.sA + m.iB * r1.sB * r2.sB;
    if (k11 == 0.0f) k11 = 1.0f;
    if (k22 == 0.0f) k22 = 1.0f;
    const Vec2 v{rowVelocity(p, r1), rowVelocity(p, r2)};
    const Vec2 b = solve22({{k11, k12}, {k12, k22}}, v + soft.biasRate * C);
    const Vec2 impulse = -soft.massScale * b - soft.impulseScale * lambda;
    lambda += impulse;
    applyRow(p, r1, impulse.x);
    applyRow(p, r2, impulse.y);
}

// --- Geometry inside a substep ---

// The anchors now: r = rotate(Δq, r0), and d = pB − pA = (ΔpB − ΔpA) + (cB − cA)₀ + rB − rA.
struct JointFrame {
    Vec2 rA, rB, d;
};

inline JointFrame currentFrame(const PreparedJoint& j, const JointPair& p) {
    const Vec2 rA = rotate(p.a.dq, j.anchorA), rB = rotate(p.b.dq, j.anchorB);
    return {rA, rB, (p.b.dp - p.a.dp) + j.deltaCenter + (rB - rA)};
}

// The joint angle now: θB − θA − referenceAngle.
inline float currentAngle(const PreparedJoint& j, const JointPair& p) { return j.deltaAngle + p.rotation; }

}  // namespace perpdot
