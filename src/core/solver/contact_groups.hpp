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
// nothing). Its rows are in constraint order, and K is stored and factored on its envelope
// (cholesky.hpp): row r from the first row that shares a moving body with it. It is solved
// directly when it has at most denseRows normal rows, or more in a band (a column of boxes, each
// touching two others: a few multiply-adds a row; admitted), none of its bodies is jointed to
// another dynamic body or by a joint with a motor, spring or break limit (such rows stay sequential
// between the passes: chains keep their joint trees, and the anvil of a jointed bridge is
// already held by them), and
//   - without joints, one of its rows carried, last step, a load that would sink it one at a time
//     more than loadTrigger times the direct solve's g/ω²;
//   - with an anchored body (every joint of it revolute, rigid weld or prismatic, to a static or
//     kinematic body), a hit: a point closing faster than hitSpeed on it from a body hitRatio
//     times heavier. The group then takes its joints' rows (joint.hpp DirectJointRow: equality rows
//     with free λ, limits as one-sided rows, speculative while C > 0) into K, so the blow meets the
//     ground through the joint in one solve (a 0.1 kg hinged arm struck by 5 kg at 10 m/s holds its
//     ±0.05 rad limit, where the sequential passes let it reach −0.37 rad; docs/stress.md).
// Groups in constraint order, while the step's maxTotalRows last. Its normal (and joint) rows then
// take the block solve as a linear complementarity problem (λn ≥ 0, block principal pivoting), K
// raised by 0.1 % on its diagonal; its friction and rolling rows stay sequential, after them. A
// pass whose pivoting does not settle is solved row by row.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <initializer_list>
#include <vector>

#include "core/joints/joint.hpp"
#include "core/solver/complementarity.hpp"
#include "core/world/step_context.hpp"
#include "perpdot/world.hpp"

namespace perpdot {

struct ContactScratch;  // step_scratch.hpp
struct SolverBodies;
struct SolverWorld;     // solver_world.hpp

struct ContactGroups {
    // A group of at most denseRows rows is solved whatever its envelope: at most n³/6 multiply-adds
    // to factor, once a step. A longer one when its factor costs no more than a band of bandRows
    // rows, Σ_r p_r² ≤ n·bandRows² (cholesky.hpp); a larger pile, its rows reaching far back, stays
    // row by row (the card_house scene's group of 160 rows costs 1,480 a row, not 256, and the
    // house collapses when it is solved directly).
    static constexpr int denseRows = 128;
    static constexpr int bandRows = 16;
    static constexpr int maxTotalRows = 1024;  // all groups of a step: bounds their work and storage
    static constexpr float loadTrigger = 8;    // in g: λn K_ii / hs of the most loaded row
    // A hit: a contact point closing faster than hitSpeed (m/s) between two moving bodies whose
    // inverse masses differ by hitRatio (contact_cache.hpp) or more; it has no load yet.
    static constexpr float hitSpeed = 1;
    std::vector<int> constraints;            // indices into ContactScratch::constraints, group by group
    std::vector<int> start;                  // group g is constraints[start[g] .. start[g + 1])
    std::vector<std::array<int, 2>> rows;    // (constraint, point) of each normal row, group by group; (-1, j): jointRows[j]
    // The joint rows the groups take: the awake joint, its row, its Jacobian, its λ this step and C this pass.
    struct JointRow {
        int joint, row;
        DirectJointRow jacobian;
        double lambda = 0;
        float C = 0;
    };
    std::vector<JointRow> jointRows;
    std::vector<uint8_t> freeRow;            // by row: an equality row, λ of either sign
    std::vector<int> rowStart;               // group g's rows are rows[rowStart[g] .. rowStart[g + 1])
    std::vector<int> firstColumn, lastRow;   // by row, group by group: K's envelope (EnvelopeShape)
    std::vector<size_t> diagonal;
    std::vector<size_t> matrixStart;         // group g's K and L envelopes at K[matrixStart[g]]
    std::vector<double> K, L;                // K = J M⁻¹ Jᵀ of the normal rows and its Cholesky factor
    std::vector<uint8_t> direct;             // by constraint: 1 if a group solves it
    // Scratch, kept to reuse its memory: by solver slot its kind, union-find root and first row
    // (envelopeFirst), by root its rows, load, rows placed, factor cost and group; per pass its
    // complementarity problem (the impulses, targets and pivoting).
    std::vector<int> root, rowCount, firstRow, placed, groupOf, jointRowCount;
    std::vector<int64_t> cost;
    std::vector<uint8_t> kind, loaded, withJoints;
    Complementarity lcp;
    // The inputs of the last search that got as far as the group sizes: the constraints' slots and
    // point counts, the slots' kinds, and whether no group was small enough to solve directly.
    std::vector<std::array<int, 2>> lastSlots;
    std::vector<int> lastPointCounts;
    std::vector<uint8_t> lastKind;
    bool noneSmall = false;
};

// Whether a group of n rows whose factor costs Σ_r p_r² = cost is solved directly.
inline bool admitted(int n, int64_t cost) {
    return n <= ContactGroups::denseRows || cost <= int64_t{n} * ContactGroups::bandRows * ContactGroups::bandRows;
}

// The first column of a group's next rows, at `row`, coupling slots a and b (−1: a slot that moves
// nothing): the first row that touched either. firstRow, by slot, is the group's first row touching
// it, −1 before; the rows' slots are entered.
inline int envelopeFirst(std::vector<int>& firstRow, int row, int a, int b) {
    int first = row;
    for (const int slot : {a, b}) {
        if (slot < 0) continue;
        if (firstRow[slot] < 0) firstRow[slot] = row;
        first = std::min(first, firstRow[slot]);
    }
    return first;
}

// The groups of this step's constraints to solve directly (by selectContacts, after its
// select, before colorJoints: the joints they take get no colour), their rows prepared and K factored.
void findContactGroups(const SolverWorld& world, const StepContext& ctx);
// A pass of every group: warm start, or its normal rows as one system then its tangent rows.
void contactGroupRows(ContactScratch& contacts, SolverBodies& bodies, JointScratch& joints, const StepContext& ctx, RowPass pass);

}  // namespace perpdot
