// The contact solver's stages (contact_solver.cpp, and contact_solver_wide.cpp for the rows solved
// in graph-coloured blocks of four or eight), in the order World::step and the solver's stages
// (solver_stages.hpp) run them. They read the world through its solver view (solver_world.hpp).
#pragma once

#include <cstddef>

#include "core/solver/solver_world.hpp"

namespace perpdot {

// The step's contact constraints selected, their impacts propagated and their groups found, which
// take the joints of their bodies (before colorJoints: those joints take no colour).
void selectContacts(const SolverWorld& world, const StepContext& ctx);
// Then their rows prepared or their blocks sized (after colorJoints).
void prepareContactBlocks(const SolverWorld& world, const StepContext& ctx);
// The blocks of colour `color` (below GraphColoring::overflow), laid out (the solver's first
// stages) and then in a pass: they share no moving body, so they run in any order or side by
// side; then the overflow constraints, one by one.
int contactBlockCount(const ContactScratch& contacts, int color);
void layOutContactBlocks(const SolverWorld& world, const StepContext& ctx, int color, int begin, int end);
void contactRows(ContactScratch& contacts, SolverBodies& bodies, const StepContext& ctx, RowPass pass, int color, int begin, int end);
void serialContactRows(ContactScratch& contacts, SolverBodies& bodies, const StepContext& ctx, RowPass pass);
// The accumulated impulses, restitution's included, into the contacts: those of colour `color`'s
// blocks [begin, end) straight from their lanes (the solver's last stages), and those of the
// constraints solved from their own rows.
void storeContactBlocks(const ContactScratch& contacts, ContactCache& cache, int color, int begin, int end);
void storeContactImpulses(const ContactScratch& contacts, ContactCache& cache);
// Field `field` (a float index of ContactRows<float>, pointField) of a constraint's rows, once
// locateContactRows has found where each constraint's rows are.
void locateContactRows(ContactScratch& contacts);
float contactRowField(const ContactScratch& contacts, int constraint, std::size_t field);

}  // namespace perpdot
