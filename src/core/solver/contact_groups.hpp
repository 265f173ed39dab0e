// Contact groups solved directly. A soft row solved one at a time settles where its spring holds
// its own load, C = F K_ii / ω² with K_ii its Hecker denominator: a row carrying many times the
// weight of the bodies it moves sinks in proportion (a 1 m box of density 1000 on one of density 1:
// 38 cm; the bottom of a 50-box column 3 cm, the column 0.82 m). Solved as one system per pass —
// the block form of the soft step,
//   λ ← λ − massScale·K⁻¹(v + biasRate·C) − impulseScale·λ,   K = J M⁻¹ Jᵀ,
// with one softness for every row — the rest state is C = K F / ω² instead: the relative
// acceleration the contact forces give each row, which is g at the rows on the ground and 0
// between bodies at rest on each other, whatever their masses (docs/stress.md).
//
// A group is the touching contacts joined through dynamic bodies (static and kinematic bodies join
// nothing). It is solved directly when it has at most maxRows normal rows, none of its bodies has
// a joint (joint rows stay sequential between the passes, and the anvil of a jointed bridge is
// already held by them), and one of its rows carried, last step, a load that would sink it one at
// a time more than loadTrigger times the direct solve's g/ω²; groups in constraint order, while
// the step's maxTotalRows last. Its normal rows then take the block solve as a linear
// complementarity problem (λn ≥ 0, block principal pivoting), K raised by 0.1 % on its diagonal;
// its friction and rolling rows stay sequential, after them. A pass whose pivoting does not settle
// is solved row by row.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/world/step_context.hpp"
#include "perpdot/world.hpp"

namespace perpdot {

struct ContactScratch;  // step_scratch.hpp
struct SolverBodies;
struct SolverWorld;     // solver_world.hpp

struct ContactGroups {
    static constexpr int maxRows = 128;        // K is n x n: about n³/6 multiply-adds to factor, once a step
    static constexpr int maxTotalRows = 1024;  // all groups of a step: bounds their work and storage
    static constexpr float loadTrigger = 8;    // in g: λn K_ii / hs of the most loaded row
    std::vector<int> constraints;            // indices into ContactScratch::constraints, group by group
    std::vector<int> start;                  // group g is constraints[start[g] .. start[g + 1])
    std::vector<std::array<int, 2>> rows;    // (constraint, point) of each normal row, group by group
    std::vector<int> rowStart;               // group g's rows are rows[rowStart[g] .. rowStart[g + 1])
    std::vector<size_t> matrixStart;         // group g's K and L at K[matrixStart[g]], n² each
    std::vector<double> K, L;                // K = J M⁻¹ Jᵀ of the normal rows and its Cholesky factor
    std::vector<uint8_t> direct;             // by constraint: 1 if a group solves it
    // Scratch, kept to reuse its memory: by solver slot its kind and union-find root, by root its
    // rows, load and group; per pass the impulses, targets and active rows of the pivoting.
    std::vector<int> root, rowCount, groupOf;
    std::vector<uint8_t> kind, loaded, active;
    std::vector<double> lambda, y, x, rhs, activeK;
    // The inputs of the last search that got as far as the group sizes: the constraints' slots and
    // point counts, the slots' kinds, and whether no group was small enough to solve directly.
    std::vector<std::array<int, 2>> lastSlots;
    std::vector<int> lastPointCounts;
    std::vector<uint8_t> lastKind;
    bool noneSmall = false;
};

// The groups of this step's constraints to solve directly (after the select of prepareContacts), their
// rows prepared and K factored.
void findContactGroups(const SolverWorld& world, const StepContext& ctx);
// A pass of every group: warm start, or its normal rows as one system then its tangent rows.
void contactGroupRows(ContactScratch& contacts, SolverBodies& bodies, const StepContext& ctx, RowPass pass);

}  // namespace perpdot
