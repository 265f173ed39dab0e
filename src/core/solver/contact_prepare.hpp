// Preparing a contact constraint's rows (contact_solver.cpp): the contact's values gathered into
// its own ContactRows<float> (the overflow colour, contact groups) or straight into its lane of a
// block once the colouring has placed it, then the fields computed from them (deriveContactRows,
// contact_solver_wide.hpp) for one constraint or for a block's lanes at once. The masses, warm
// start and effective mass are shared with the contact groups' load test, which reads them before
// any rows exist.
#pragma once

#include "core/solver/contact_solver_wide.hpp"
#include "core/solver/solver_world.hpp"
#include "core/world/step_context.hpp"

namespace perpdot {

struct ContactConstraint;

using RowMasses = RowMassLanes<float>;

// Read from the solver slots: 1/m from their states, 1/I from SolverBodies::inverseInertias (dense
// arrays, where the bodies are not).
inline RowMasses rowMasses(const SolverBodies& bodies, int slotA, int slotB) {
    return {bodies.states[slotA].invMass, bodies.inverseInertias[slotA], bodies.states[slotB].invMass, bodies.inverseInertias[slotB]};
}

// The rows of constraint c (its contact and solver slots set, SolverBodies::freeVelocities filled):
// its own `rows`, gathered and derived (deriveContactRows, contact_solver_wide.hpp).
void prepareContactRows(const SolverWorld& world, const StepContext& ctx, const ContactConstraint& c, ContactRows<float>& rows);
// Or the gather alone into a block of four or eight lanes (row_lanes.hpp), the block's lanes to be
// derived together: lane l from constraints[l], l < used, the others zeros; present: 1 where a
// lane's point is a manifold point. Each contact's values in a row are read as runs of four or
// eight floats and turned into lanes.
void gatherContactLanes(const SolverWorld& world, const ContactConstraint* const (&constraints)[4], int used, ContactBlock<4>& block,
                        const float (&present)[2][4]);
#ifdef PERPDOT_AVX2
void gatherContactLanes(const SolverWorld& world, const ContactConstraint* const (&constraints)[8], int used, ContactBlock<8>& block,
                        const float (&present)[2][8]);
#endif

}  // namespace perpdot
