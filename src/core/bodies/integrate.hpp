// The body stages inside the substeps (integrate.cpp), which the solver's stages run
// (solver_stages.hpp) on the solver slots; the stages around the solve are in stages.hpp.
#pragma once

#include "core/world/step_context.hpp"
#include "core/world/step_scratch.hpp"

namespace perpdot {

// A substep's share of the forces on the constrained bodies, solver slots [begin, end).
void applySubstepForces(SolverBodies& bodies, int begin, int end);
// Integrate positions: x += hs v, θ += hs ω, solver slots [begin, end).
void integratePositions(SolverBodies& bodies, const StepContext& ctx, int begin, int end);

}  // namespace perpdot
