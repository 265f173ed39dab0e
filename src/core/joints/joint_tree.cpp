#include "core/joints/joint_tree.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <utility>

#include "core/base/union_find.hpp"
#include "core/joints/joint_direct.hpp"
#include "core/joints/joint_rows.hpp"
#include "core/solver/cholesky.hpp"
#include "core/solver/row_sides.hpp"
#include "core/world/step_scratch.hpp"

namespace perpdot {

// Union-find over the moving bodies the joints link, keeping each group's joint count; groups too
// large for a dense K stay with the sequential passes, and so do groups with limits, welds or
// sliders whose bodies' masses are alike. A group may close a loop or hang between two fixed anchors (assemble: K's
// raised diagonal).
void findJointTrees(JointTrees& t, const std::vector<JointKey>& keys, const std::vector<BodyState>& states) {
    const int slots = static_cast<int>(states.size());
    const int count = static_cast<int>(keys.size());
    t.joints.clear();
    t.start.assign(1, 0);
    t.rowStart.assign(1, 0);
    t.rowJoint.clear();
    t.rowIndex.clear();
    t.rowFree.clear();
    t.inTree.assign(keys.size(), 0);
    if (count < 2) return;
    // Selective joints (limited hinges, welds, sliders) join the groups only where some joint joins
    // bodies of unlike masses: a world of ragdolls or welded structures alone is not searched for them.
    const auto selective = [](const JointKey& j) { return j.limited || j.type != JointType::Revolute; };
    const auto unlike = [](float lighter, float heavier) { return lighter >= JointTrees::unlikeMasses * heavier; };
    bool unlikeSelective = false;
    if (std::any_of(keys.begin(), keys.end(), [&](const JointKey& j) { return j.treeJoint && selective(j); })) {
        for (const JointKey& j : keys) {
            if (!j.treeJoint || !j.movesA || !j.movesB) continue;
            const float a = states[j.indexA].invMass, b = states[j.indexB].invMass;
            if (unlike(std::max(a, b), std::min(a, b))) {
                unlikeSelective = true;
                break;
            }
        }
    }
    const auto takes = [&](const JointKey& j) { return j.treeJoint && (!selective(j) || unlikeSelective); };
    t.root.resize(slots);
    std::iota(t.root.begin(), t.root.end(), 0);
    t.jointCount.assign(slots, 0);
    // A side that cannot move (static, asleep, kinematic) couples nothing: it anchors the tree.
    for (const JointKey& j : keys) {
        if (!takes(j)) continue;
        const bool a = j.movesA, b = j.movesB;
        if (a && b) {
            int ra = findRoot(t.root, j.indexA), rb = findRoot(t.root, j.indexB);
            if (ra != rb) {
                if (t.jointCount[ra] < t.jointCount[rb]) std::swap(ra, rb);  // the larger group stays the root
                t.root[rb] = ra;
                t.jointCount[ra] += t.jointCount[rb];
            }
            ++t.jointCount[ra];
        } else if (a || b) {
            ++t.jointCount[findRoot(t.root, a ? j.indexA : j.indexB)];
        }
    }
    // By root: whether a joint is selective, and if so the lightest and heaviest moving body (inverse
    // masses).
    if (unlikeSelective) {
        t.selective.assign(slots, 0);
        for (const JointKey& j : keys)
            if (j.treeJoint && selective(j) && (j.movesA || j.movesB)) t.selective[findRoot(t.root, j.movesA ? j.indexA : j.indexB)] = 1;
        t.lightest.assign(slots, 0.0f);
        t.heaviest.assign(slots, std::numeric_limits<float>::infinity());
        for (int k = 0; k < count; ++k) {
            const JointKey& j = keys[k];
            if (!j.treeJoint || (!j.movesA && !j.movesB)) continue;
            const int r = findRoot(t.root, j.movesA ? j.indexA : j.indexB);
            if (!t.selective[r]) continue;
            for (const float invMass : {states[j.indexA].invMass, states[j.indexB].invMass}) {
                if (!(invMass > 0.0f)) continue;
                t.lightest[r] = std::max(t.lightest[r], invMass);
                t.heaviest[r] = std::min(t.heaviest[r], invMass);
            }
        }
    }
    const auto isTree = [&](int r) {
        const bool sized = t.jointCount[r] >= 2 && t.jointCount[r] <= JointTrees::maxJoints;
        return sized && (!unlikeSelective || !t.selective[r] || unlike(t.lightest[r], t.heaviest[r]));
    };
    bool any = false;
    for (int r = 1; r < slots && !any; ++r) any = t.root[r] == r && isTree(r);
    if (!any) return;
    // Each joint's group, if it is a tree: -1 otherwise (t.treeOf, by prepared index).
    t.treeOf.assign(keys.size(), -1);
    int inTrees = 0;
    for (int k = 0; k < count; ++k) {
        const JointKey& j = keys[k];
        if (!takes(j) || (!j.movesA && !j.movesB)) continue;
        const int r = findRoot(t.root, j.movesA ? j.indexA : j.indexB);
        if (!isTree(r)) continue;
        t.treeOf[k] = r;
        ++inTrees;
    }
    if (inTrees == 0) return;
    // Trees in order of their first joint; a counting sort keeps each tree's joints in prepared order.
    std::vector<int>& treeIndex = t.treeIndex;  // by root: the tree's index
    treeIndex.assign(slots, -1);
    int trees = 0;
    for (int k = 0; k < count; ++k)
        if (const int r = t.treeOf[k]; r >= 0 && treeIndex[r] < 0) treeIndex[r] = trees++;
    t.start.assign(trees + 1, 0);
    for (int k = 0; k < count; ++k)
        if (const int r = t.treeOf[k]; r >= 0) ++t.start[treeIndex[r] + 1];
    std::partial_sum(t.start.begin(), t.start.end(), t.start.begin());
    t.joints.resize(t.start.back());
    std::vector<int>& next = t.jointCount;  // reused, by tree index
    std::copy(t.start.begin(), t.start.end() - 1, next.begin());
    for (int k = 0; k < count; ++k) {
        if (const int r = t.treeOf[k]; r >= 0) {
            t.joints[next[treeIndex[r]]++] = k;
            t.inTree[k] = 1;
        }
    }
    // Each tree's rows, joint by joint: its equality rows, then a limited joint's lower and upper limit.
    for (int tree = 0; tree < trees; ++tree) {
        for (int i = 0; i < t.start[tree + 1] - t.start[tree]; ++i) {
            const JointKey& j = keys[t.joints[t.start[tree] + i]];
            const int equalities = equalityRowCount(j.type);
            for (int row = 0; row < directRowCount(j.type, j.limited); ++row) {
                t.rowJoint.push_back(i);
                t.rowIndex.push_back(static_cast<uint8_t>(row));
                t.rowFree.push_back(row < equalities ? 1 : 0);
            }
        }
        t.rowStart.push_back(static_cast<int>(t.rowJoint.size()));
    }
}

void warmStartJointTrees(SolverBodies& bodies, JointTrees& t, std::vector<PreparedJoint>& prepared) {
    for (int k : t.joints) {
        JointPair p = pairOf(bodies.states, bodies.stepRotation, prepared[k]);
        stagesOf(prepared[k].type).warmStart(prepared[k], p);
    }
}

namespace {

Row rowOf(const DirectJointRow& r) { return {r.n, r.sA, r.sB}; }

// A joint row's sides (row_sides.hpp): −n, −sA on A, n, sB on B, with the joint's inverse masses
// (its inertias raised by the geometric stiffness, joint_tree_stiffness.hpp, alike for every tree
// joint at a body).
std::array<RowSide, 2> sidesOf(const PreparedJoint& j, const DirectJointRow& r) {
    return {RowSide{j.indexA, -r.n, -r.sA, j.mass.mA, j.mass.iA}, RowSide{j.indexB, r.n, r.sB, j.mass.mB, j.mass.iB}};
}

// Each joint of tree `tree` with its bodies where they are now: its rows into t.jointRows and their
// position errors into t.errors.
void measureJoints(SolverBodies& bodies, JointTrees& t, const std::vector<PreparedJoint>& prepared, size_t tree) {
    const int first = t.start[tree], joints = t.start[tree + 1] - first;
    t.jointRows.resize(joints);
    t.errors.resize(joints);
    for (int i = 0; i < joints; ++i) {
        const PreparedJoint& j = prepared[t.joints[first + i]];
        const JointPair p = pairOf(bodies.states, bodies.stepRotation, j);
        jointRowsNow(j, p, t.jointRows[i].data());
        jointRowErrors(j, p, t.errors[i].data());
    }
}

// The rows of tree `tree` that `keep` takes (by index into rowJoint), as measureJoints found them,
// into t.rows, and their K, raised on its diagonal, into t.K, both on an envelope from column 0.
// Returns the shape and whether K's Cholesky factor, into t.L, exists.
template <class Keep>
std::pair<EnvelopeShape, bool> assemble(JointTrees& t, const std::vector<PreparedJoint>& prepared, size_t tree, Keep keep) {
    const int first = t.start[tree];
    t.rows.clear();
    t.freeRow.clear();
    t.passRows.clear();
    for (int r = t.rowStart[tree]; r < t.rowStart[tree + 1]; ++r) {
        if (!keep(r)) continue;
        t.rows.push_back(t.jointRows[t.rowJoint[r]][t.rowIndex[r]]);
        t.freeRow.push_back(t.rowFree[r]);
        t.passRows.push_back(r);
    }
    const int n = static_cast<int>(t.rows.size());
    t.firstColumn.assign(n, 0);
    t.lastRow.resize(n);
    t.diagonal.resize(n);
    envelopeLastRows(t.firstColumn.data(), n, t.lastRow.data());
    const size_t size = envelopeLayout(t.firstColumn.data(), n, t.diagonal.data());
    t.K.resize(size);
    const EnvelopeShape shape{n, t.firstColumn.data(), t.lastRow.data(), t.diagonal.data()};
    auto sides = [&](int r) { return sidesOf(prepared[t.joints[first + t.rowJoint[t.passRows[r]]]], t.rows[r]); };
    for (int r = 0; r < n; ++r) {
        const std::array<RowSide, 2> sr = sides(r);
        for (int s = 0; s <= r; ++s) t.K[shape.origin(r) + s] = coupling(sr, sides(s));
        t.K[shape.origin(r) + r] *= 1.0 + JointTrees::diagonalRaise;
    }
    t.L = t.K;
    return {shape, n > 0 && choleskyFactor(t.L.data(), shape)};
}

// Moves a body's solver state by a position impulse along a row: Δc = P n/m, Δθ = P s/I.
void displace(SolverBodies& bodies, int slot, float invMass, float invInertia, Vec2 n, float arm, float P) {
    if (slot == 0) return;
    BodyState& s = bodies.states[slot];
    const float dAngle = invInertia * arm * P;
    s.dp += (invMass * P) * n;
    bodies.stepRotation[slot] += dAngle;
    s.dq = integrateRotation(s.dq, dAngle);
}

}  // namespace

void solveJointTrees(SolverBodies& bodies, JointTrees& t, std::vector<PreparedJoint>& prepared, const StepContext& ctx, bool useBias) {
    const Softness soft = rigidSoftness(ctx, useBias);
    for (size_t tree = 0; tree + 1 < t.start.size(); ++tree) {
        const int first = t.start[tree], joints = t.start[tree + 1] - first;
        // A joint's motor first, one by one, as its own solve orders it.
        for (int i = 0; i < joints; ++i) {
            PreparedJoint& j = prepared[t.joints[first + i]];
            JointPair p = pairOf(bodies.states, bodies.stepRotation, j);
            if (j.type == JointType::Revolute) solveRevoluteMotor(j, p, ctx);
            if (j.type == JointType::Prismatic) solvePrismaticMotor(j, p, ctx);
        }
        measureJoints(bodies, t, prepared, tree);
        const auto [shape, factored] = assemble(t, prepared, tree, [](int) { return true; });
        const int n = shape.n;
        t.lcp.reserve(n, t.K.size());
        auto jointOf = [&](int r) -> PreparedJoint& { return prepared[t.joints[first + t.rowJoint[t.passRows[r]]]]; };
        auto errorOf = [&](int r) { return t.errors[t.rowJoint[t.passRows[r]]][t.rowIndex[t.passRows[r]]]; };
        auto impulseOf = [&](int r) -> float& { return jointRowImpulse(jointOf(r), t.rowIndex[t.passRows[r]]); };
        bool solved = factored;
        if (solved) {
            // y_r from the velocities now: a limit inside its range (C > 0) rigid, Ċ → −C/hs (it may
            // close the gap); the others the soft step, Ċ + biasRate·C and the leak of K λ, a
            // slider past its limit pushed back at most slidePushMaxVelocity.
            for (int r = 0; r < n; ++r) t.lcp.lambda[r] = impulseOf(r);
            for (int r = 0; r < n; ++r) {
                const PreparedJoint& j = jointOf(r);
                const JointPair p = pairOf(bodies.states, bodies.stepRotation, j);
                const float v = rowVelocity(p, rowOf(t.rows[r]));
                const float C = errorOf(r);
                if (!t.freeRow[r] && C > 0.0f) {
                    t.lcp.y[r] = -static_cast<double>(v + C * ctx.invHs);
                    continue;
                }
                double kLambda = 0.0;  // (K λ)_r
                forEachInRow(t.K.data(), shape, r, [&](int s, double k) { kLambda += k * t.lcp.lambda[s]; });
                float bias = soft.biasRate * C;
                if (!t.freeRow[r] && j.type == JointType::Prismatic) bias = std::max(bias, -JointTrees::slidePushMaxVelocity);
                t.lcp.y[r] = -soft.massScale * (v + bias) - soft.impulseScale * kLambda;
            }
            solved = solveComplementarity(t.lcp, shape, t.K.data(), t.L.data(), t.freeRow.data());
        }
        if (!solved) {  // row by row, as the joints' own passes solve them
            for (int r = 0; r < n; ++r) {
                PreparedJoint& j = jointOf(r);
                JointPair p = pairOf(bodies.states, bodies.stepRotation, j);
                const Row row = rowOf(t.rows[r]);
                const float mass = effectiveMass(j.mass, row);
                if (t.freeRow[r])
                    solveRow(p, row, mass, errorOf(r), soft, impulseOf(r));
                else
                    solveLimitRow(p, row, mass, errorOf(r), ctx, useBias, impulseOf(r));
            }
            continue;
        }
        // Every Δλ from the velocities before any is applied: the solve already couples them.
        for (int r = 0; r < n; ++r) {
            float& lambda = impulseOf(r);
            float newLambda = lambda + static_cast<float>(t.lcp.x[r]);
            if (!t.freeRow[r]) newLambda = std::max(newLambda, 0.0f);
            t.lcp.x[r] = newLambda - lambda;
            lambda = newLambda;
        }
        for (int r = 0; r < n; ++r) {
            JointPair p = pairOf(bodies.states, bodies.stepRotation, jointOf(r));
            applyRow(p, rowOf(t.rows[r]), static_cast<float>(t.lcp.x[r]));
        }
    }
}

// Newton's step on the positions: K P = −C over the equality rows, then each body moves by the
// position impulses (Box2D 2.4's position pass, exact for the whole tree instead of joint by joint).
// The limits stay out: taken in, as the complementarity problem of the velocity pass with λ = 0
// and y = −C, the 10,000 : 1 limited chain of RevoluteTree.LimitedHeavyChainKeepsItsHingesClosed
// opened 1.4 cm instead of 0.05 mm.
void projectJointTrees(SolverBodies& bodies, JointTrees& t, const std::vector<PreparedJoint>& prepared) {
    for (size_t tree = 0; tree + 1 < t.start.size(); ++tree) {
        const int first = t.start[tree];
        measureJoints(bodies, t, prepared, tree);
        const auto [shape, factored] = assemble(t, prepared, tree, [&](int row) { return t.rowFree[row] != 0; });
        if (!factored) continue;
        t.lcp.reserve(shape.n, 0);
        std::vector<double>& P = t.lcp.x;
        for (int r = 0; r < shape.n; ++r) {
            const int row = t.passRows[r];
            P[r] = -t.errors[t.rowJoint[row]][t.rowIndex[row]];
        }
        choleskySolve(t.L.data(), shape, P.data());
        for (int r = 0; r < shape.n; ++r) {
            const PreparedJoint& j = prepared[t.joints[first + t.rowJoint[t.passRows[r]]]];
            const Row row = rowOf(t.rows[r]);
            const float impulse = static_cast<float>(P[r]);
            displace(bodies, j.indexA, j.mass.mA, j.mass.iA, row.n, row.sA, -impulse);
            displace(bodies, j.indexB, j.mass.mB, j.mass.iB, row.n, row.sB, impulse);
        }
    }
}

}  // namespace perpdot
