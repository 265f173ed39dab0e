// Revolute trees, solved directly. Sequential passes converge slowly along a chain whose masses
// differ: 20 links ending in a body of 100 times a link's mass opened 12 % of a link at their
// hinges at 4 substeps (`perpdot stress stress_chain`). A group of 2 to 32 revolute joints without
// limit, linked through moving bodies — a tree, or a closed loop such as a bridge between two posts
// (the name stays "tree") — has its point rows solved instead as one linear system per pass (a
// joint's motor row first, one by one) — the block form of the point rows' soft step (joint_rows.hpp):
//   λ ← λ − massScale·K⁻¹(v_rel + biasRate·C) − impulseScale·λ,   K = J M⁻¹ Jᵀ,
// where K's 2x2 diagonal blocks are each joint's Hecker denominator and an off-diagonal block
// couples two joints through the body they share. K is factored by Cholesky, in double precision.
#pragma once

#include <cstdint>
#include <vector>

#include "core/world/step_context.hpp"
#include "perpdot/world.hpp"

namespace perpdot {

struct JointKey;
struct PreparedJoint;
struct SolverBodies;  // step_scratch.hpp

struct RevoluteTrees {
    static constexpr int maxJoints = 32;  // K is 2n x 2n: about (2n)³/6 multiply-adds a pass
    // K's diagonal × (1 + diagonalRaise). A closed loop pulled straight (a bridge between two
    // posts) has a singular K: a tension along it moves no body. Its entries come from floats
    // (relative rounding 6e-8), so a singular K may fail to factor or factor with pivots of noise;
    // raised by 1e-6 it factors, and the tension along the loop takes what the warm start and the
    // soft step's impulseScale·λ leave it. 1e-7 … 1e-4 all hold a straight 20-plank bridge with a
    // middle plank of 1000 times the others' mass to 0.02 … 0.7 mm (RevoluteLoop tests); 1e-8 opens
    // it 2.2 mm and 1e-9 8.4 m; 1e-3 opens `chain10k`'s 2 % of a link.
    static constexpr double diagonalRaise = 1e-6;
    std::vector<int> joints;    // indices into JointStore::prepared, tree by tree, in prepared order
    std::vector<int> start;     // tree t is joints[start[t] .. start[t + 1])
    std::vector<uint8_t> inTree;  // by prepared index: 1 if the joint is in a tree
    // Scratch, kept to reuse its memory: union-find by solver slot, and each joint's tree root.
    std::vector<int> root, jointCount, treeIndex, treeOf;
    std::vector<double> K, x;
    std::vector<float> stiffness;  // by solver slot: Σ|r·λ| (joint_tree_stiffness.hpp)
    std::vector<Vec2> rA, rB;
};

// The trees among this step's prepared joints, by their keys; `slots` is the solver's body count.
void findRevoluteTrees(RevoluteTrees& trees, const std::vector<JointKey>& keys, int slots);

// Warm start (each joint's accumulated impulse) and one pass (with soft bias, or the relax pass
// without) of every tree. A tree whose K does not factor has its point rows solved joint by joint.
void warmStartRevoluteTrees(SolverBodies& bodies, RevoluteTrees& trees, std::vector<PreparedJoint>& prepared);
void solveRevoluteTrees(SolverBodies& bodies, RevoluteTrees& trees, std::vector<PreparedJoint>& prepared,
                        const StepContext& ctx, bool useBias);
// After the substeps: one Newton step on each tree's positions, K P = −C, so the anchors a step
// ends with meet (the velocity passes leave the drift of rotating arms).
void projectRevoluteTrees(SolverBodies& bodies, RevoluteTrees& trees, const std::vector<PreparedJoint>& prepared);

}  // namespace perpdot
