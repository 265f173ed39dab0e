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
// A group is the touching contacts joined through moving bodies; it is solved directly when it has
// at most maxRows normal rows and one of them carried, last step, a load that would sink it one
// at a time more than loadTrigger times the direct solve's g/ω² (and while the step's maxTotalRows
// last, groups in constraint order). Its normal rows then take the
// block solve (λn ≥ 0 by dropping rows whose impulse would turn negative and solving again); its
// friction and rolling rows stay sequential.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/step_context.hpp"
#include "perpdot/world.hpp"

namespace perpdot {

struct ContactGroups {
    static constexpr int maxRows = 128;      // K is n x n: about n³/6 multiply-adds to factor, once a step
    static constexpr int maxTotalRows = 1024;  // all groups of a step: bounds their work and storage
    static constexpr float loadTrigger = 8;  // in g: λn K_ii / hs of the most loaded row
    std::vector<int> constraints;            // indices into World::Impl::constraints, group by group
    std::vector<int> start;                  // group g is constraints[start[g] .. start[g + 1])
    std::vector<std::array<int, 2>> rows;    // (constraint, point) of each normal row, group by group
    std::vector<int> rowStart;               // group g's rows are rows[rowStart[g] .. rowStart[g + 1])
    std::vector<size_t> matrixStart;         // group g's K and L at K[matrixStart[g]], n² each
    std::vector<double> K, L;                // K = J M⁻¹ Jᵀ of the normal rows and its Cholesky factor
    std::vector<uint8_t> direct;             // by constraint: 1 if a group solves it
    // Scratch, kept to reuse its memory: union-find by solver slot, and per pass the targets.
    std::vector<int> root, rowCount, groupOf;
    std::vector<uint8_t> loaded, active;
    std::vector<double> lambda, y, x, rhs, activeK;
};

// The groups of this step's constraints to solve directly, their K factored (after prepareContact).
void findContactGroups(World::Impl& world, const StepContext& ctx);
// A pass of every group: warm start, or its normal rows as one system then its tangent rows.
void contactGroupRows(World::Impl& world, const StepContext& ctx, RowPass pass);

}  // namespace perpdot
