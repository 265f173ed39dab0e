// Joint trees, solved directly. Sequential passes converge slowly along a chain whose masses
// differ: 20 links ending in a body of 100 times a link's mass opened 12 % of a link at their
// hinges at 4 substeps (`perpdot stress stress_chain`). A group of 2 to 32 unbreakable revolute,
// prismatic and rigid weld joints linked through moving bodies — a tree, or a closed loop such as a
// bridge between two posts (the name stays "tree") — has its rows (joint_direct.hpp) solved instead
// as one system per pass (a joint's motor row first, one by one): the equality rows, and the limit
// rows of its joints with limits, which are one-sided (λ ≥ 0, speculative while the joint is inside
// the limit) — a linear complementarity problem (complementarity.hpp) in the block form of the
// rows' soft step (joint_rows.hpp):
//   K Δλ = −massScale·(Ċ + biasRate·C) − impulseScale·K λ,   K = J M⁻¹ Jᵀ,
// where K's diagonal blocks are each joint's Hecker denominators and an off-diagonal block couples
// two joints through the body they share. K is factored by Cholesky, in double precision. A group
// with limits, welds or sliders is taken only where its bodies' masses differ by unlikeMasses or
// more (a chain ending in a heavy body): the limited hinges of figures of like masses (ragdolls, by
// the thousand in a game) and welded or sliding structures of like parts (`joint_rack`'s: as trees
// they cost 10 times the instructions) keep the cheaper sequential passes.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/joints/joint.hpp"
#include "core/solver/complementarity.hpp"
#include "core/world/step_context.hpp"
#include "perpdot/world.hpp"

namespace perpdot {

struct JointKey;
struct PreparedJoint;
struct SolverBodies;  // step_scratch.hpp

struct JointTrees {
    static constexpr int maxJoints = 32;  // K is m x m for m ≤ 4n rows: about m³/6 multiply-adds a pass
    // K's diagonal × (1 + diagonalRaise). A closed loop pulled straight (a bridge between two
    // posts) has a singular K: a tension along it moves no body. Its entries come from floats
    // (relative rounding 6e-8), so a singular K may fail to factor or factor with pivots of noise;
    // raised by 1e-6 it factors, and the tension along the loop takes what the warm start and the
    // soft step's impulseScale·λ leave it. 1e-7 … 1e-4 all hold a straight 20-plank bridge with a
    // middle plank of 1000 times the others' mass to 0.02 … 0.7 mm (RevoluteLoop tests); 1e-8 opens
    // it 2.2 mm and 1e-9 8.4 m; 1e-3 opens `chain10k`'s 2 % of a link.
    static constexpr double diagonalRaise = 1e-6;
    // A group with limits, welds or sliders is a tree where its lightest moving body is this many
    // times lighter than its heaviest (inverse masses); a ragdoll's are within 6 times.
    static constexpr float unlikeMasses = 10;
    // A slider past its limit is pushed back at most this fast (m/s), as contacts are by
    // WorldDef::contactPushMaxVelocity. The push is speed the limit hands to the bodies: a 500 kg
    // end that snaps the sliders of `stress_mixed1000` taut drives them centimetres past their
    // limits, and pushed back at the soft step's biasRate·C (metres a second) the end took more
    // energy each swing until the chain came apart within 2 s at 10,000 : 1. 0.3 m/s holds every
    // joint of that chain within 3 mm of its axis up to 50,000 : 1 (docs/stress.md). Angular
    // limits keep the soft step: capped alike, the limited hinge chain's limits gave way (1.7 rad
    // against ±1 rad).
    static constexpr float slidePushMaxVelocity = 0.3f;
    std::vector<int> joints;    // indices into JointStore::prepared, tree by tree, in prepared order
    std::vector<int> start;     // tree t is joints[start[t] .. start[t + 1])
    std::vector<int> rowStart;  // tree t's rows are rowJoint/rowIndex/rowFree[rowStart[t] .. rowStart[t + 1]), by joint
    std::vector<int> rowJoint;  // the row's joint, an index into joints
    std::vector<uint8_t> rowIndex;  // which of its joint's rows (joint_direct.hpp's order)
    std::vector<uint8_t> rowFree;   // 1 for an equality row, 0 for a limit
    std::vector<uint8_t> inTree;  // by prepared index: 1 if the joint is in a tree
    // Scratch, kept to reuse its memory: union-find by solver slot, each root's joint count, whether
    // it has a selective joint (a limited hinge, a weld, a slider) and its lightest and heaviest
    // moving body (inverse masses), each joint's tree root; a pass's rows, its system (K, its factor
    // L, on an envelope from column 0) and its complementarity problem; each joint's rows and
    // position errors now.
    std::vector<int> root, jointCount, treeIndex, treeOf;
    std::vector<uint8_t> selective;
    std::vector<float> lightest, heaviest;
    std::vector<DirectJointRow> rows;
    std::vector<int> passRows;               // each one's index in rowJoint/rowIndex/rowFree
    std::vector<uint8_t> freeRow;
    std::vector<int> firstColumn, lastRow;
    std::vector<size_t> diagonal;
    std::vector<double> K, L;
    Complementarity lcp;
    std::vector<float> stiffness;  // by solver slot: Σ|r·λ| (joint_tree_stiffness.hpp)
    std::vector<std::array<DirectJointRow, maxDirectJointRows>> jointRows;
    std::vector<std::array<float, maxDirectJointRows>> errors;
};

// The trees among this step's prepared joints, by their keys and the solver's body states (slots).
void findJointTrees(JointTrees& trees, const std::vector<JointKey>& keys, const std::vector<BodyState>& states);

// Warm start (each joint's accumulated impulse) and one pass (with soft bias, or the relax pass
// without) of every tree. A tree whose system is not solved (K does not factor, or its pivoting
// does not settle) has the same rows solved one by one.
void warmStartJointTrees(SolverBodies& bodies, JointTrees& trees, std::vector<PreparedJoint>& prepared);
void solveJointTrees(SolverBodies& bodies, JointTrees& trees, std::vector<PreparedJoint>& prepared,
                        const StepContext& ctx, bool useBias);
// After the substeps: one Newton step on each tree's positions, K P = −C over its equality rows, so
// the joints a step ends with hold (the velocity passes leave the drift of rotating arms).
void projectJointTrees(SolverBodies& bodies, JointTrees& trees, const std::vector<PreparedJoint>& prepared);

}  // namespace perpdot
