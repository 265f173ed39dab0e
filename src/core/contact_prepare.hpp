// Preparing a contact constraint's rows (contact_solver.cpp): into its own ContactRows<float> (the
// overflow colour, contact groups) or straight into its lane of a block once the colouring has
// placed it. The effective mass and warm start are shared with the contact groups' load test,
// which reads them before any rows exist.
#pragma once

#include "core/body_store.hpp"
#include "core/step_context.hpp"
#include "perpdot/world.hpp"

namespace perpdot {

struct ContactConstraint;

// The inverse masses and inertias of a constraint's bodies.
struct RowMasses {
    float invMassA, invIA, invMassB, invIB;
};

inline RowMasses rowMasses(const Body& a, const Body& b) { return {a.invMass, a.invInertia, b.invMass, b.invInertia}; }

// 1 / (1/mA + 1/mB + perpDot(rA,d)²/IA + perpDot(rB,d)²/IB): the effective mass along d, 0 if
// nothing can move.
inline float effectiveMass(const RowMasses& m, Vec2 rA, Vec2 rB, Vec2 d) {
    const float rnA = perpDot(rA, d), rnB = perpDot(rB, d);
    const float k = m.invMassA + m.invMassB + m.invIA * rnA * rnA + m.invIB * rnB * rnB;
    return k > 0.0f ? 1.0f / k : 0.0f;
}

// Last step's accumulated impulse, the warm start of this step's (0 without warm starting).
inline float warmStartImpulse(const StepContext& ctx, float impulse) { return (ctx.enableWarmStarting ? 1.0f : 0.0f) * impulse; }

// The rows of constraint c (its contact and solver slots set): into its own rows, or into its lane
// of a block of `lanes` (4 or 8), field i at lane[i · lanes] (pack_lanes.hpp).
void prepareContactRows(const World::Impl& world, const StepContext& ctx, ContactConstraint& c);
void prepareContactLane(const World::Impl& world, const StepContext& ctx, const ContactConstraint& c, float* lane, int lanes);

}  // namespace perpdot
