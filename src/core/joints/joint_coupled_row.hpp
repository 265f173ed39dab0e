// A row whose two bodies are measured along different directions (gear and pulley joints):
//   Ċ = nA·vA + sA ωA + nB·vB + sB ωB,
// a velocity along nA of A's point with arm rA has sA = perpDot(rA, nA); an angle has n = 0, s = 1.
// Its inverse effective mass is Hecker's denominator with each body's own terms,
//   1/m_eff = nA·nA/mA + sA²/IA + nB·nB/mB + sB²/IB,
// and λ changes the velocities by vA += λ nA/mA, ωA += λ sA/IA (and likewise for B).
#pragma once

#include "core/joints/joint_rows.hpp"

namespace perpdot {

struct CoupledRow {
    Vec2 nA;
    float sA = 0;
    Vec2 nB;
    float sB = 0;
};

inline float effectiveMass(const JointMass& m, const CoupledRow& r) {
    const float k = m.mA * dot(r.nA, r.nA) + m.iA * r.sA * r.sA + m.mB * dot(r.nB, r.nB) + m.iB * r.sB * r.sB;
    return k > 0.0f ? 1.0f / k : 0.0f;
}

inline float rowVelocity(const JointPair& p, const CoupledRow& r) {
    return dot(r.nA, p.a.v) + r.sA * p.a.w + dot(r.nB, p.b.v) + r.sB * p.b.w;
}

inline void applyRow(JointPair& p, const CoupledRow& r, float impulse) {
    p.a.v = p.a.v + (p.m.mA * impulse) * r.nA;
    p.a.w = p.a.w + p.m.iA * impulse * r.sA;
    p.b.v = p.b.v + (p.m.mB * impulse) * r.nB;
    p.b.w = p.b.w + p.m.iB * impulse * r.sB;
}

// The equality C = 0, soft-step style: Δλ = −m_eff·massScale·(Ċ + biasRate·C) − impulseScale·λ.
inline void solveRow(JointPair& p, const CoupledRow& r, float mass, float C, const Softness& soft, float& lambda) {
    const float impulse = -mass * soft.massScale * (rowVelocity(p, r) + soft.biasRate * C) - soft.impulseScale * lambda;
    lambda += impulse;
    applyRow(p, r, impulse);
}

}  // namespace perpdot
