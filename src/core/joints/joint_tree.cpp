#include "core/joints/joint_tree.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <utility>

#include "core/joints/joint_revolute.hpp"
#include "core/joints/joint_rows.hpp"
#include "core/base/union_find.hpp"
#include "core/solver/cholesky.hpp"
#include "core/solver/row_sides.hpp"
#include "core/world/step_scratch.hpp"

namespace perpdot {

// Union-find over the moving bodies the joints link, keeping each group's joint count; groups too
// large for a dense K stay with the sequential passes, and so do groups with limits whose bodies'
// masses are alike. A group may close a loop or hang between two fixed anchors (assemble: K's
// raised diagonal).
void findRevoluteTrees(RevoluteTrees& t, const std::vector<JointKey>& keys, const std::vector<BodyState>& states) {
    const int slots = static_cast<int>(states.size());
    const int count = static_cast<int>(keys.size());
    t.joints.clear();
    t.start.assign(1, 0);
    t.rowStart.assign(1, 0);
    t.rowJoint.clear();
    t.rowKind.clear();
    t.inTree.assign(keys.size(), 0);
    if (count < 2) return;
    // Limited joints join the groups only where one joins bodies of unlike masses: a world of
    // ragdolls alone is not searched for them.
    const auto unlike = [](float lighter, float heavier) { return lighter >= RevoluteTrees::unlikeMasses * heavier; };
    bool unlikeLimited = false;
    for (const JointKey& j : keys) {
        if (!j.hinge || !j.limited || !j.movesA || !j.movesB) continue;
        const float a = states[j.indexA].invMass, b = states[j.indexB].invMass;
        if (unlike(std::max(a, b), std::min(a, b))) {
            unlikeLimited = true;
            break;
        }
    }
    const auto takes = [&](const JointKey& j) { return j.hinge && (!j.limited || unlikeLimited); };
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
    // By root: whether a joint has limits, and if so the lightest and heaviest moving body (inverse
    // masses).
    if (unlikeLimited) {
        t.limited.assign(slots, 0);
        for (const JointKey& j : keys)
            if (j.hinge && j.limited && (j.movesA || j.movesB)) t.limited[findRoot(t.root, j.movesA ? j.indexA : j.indexB)] = 1;
        t.lightest.assign(slots, 0.0f);
        t.heaviest.assign(slots, std::numeric_limits<float>::infinity());
        for (int k = 0; k < count; ++k) {
            const JointKey& j = keys[k];
            if (!j.hinge || (!j.movesA && !j.movesB)) continue;
            const int r = findRoot(t.root, j.movesA ? j.indexA : j.indexB);
            if (!t.limited[r]) continue;
            for (const float invMass : {states[j.indexA].invMass, states[j.indexB].invMass}) {
                if (!(invMass > 0.0f)) continue;
                t.lightest[r] = std::max(t.lightest[r], invMass);
                t.heaviest[r] = std::min(t.heaviest[r], invMass);
            }
        }
    }
    const auto isTree = [&](int r) {
        const bool sized = t.jointCount[r] >= 2 && t.jointCount[r] <= RevoluteTrees::maxJoints;
        return sized && (!unlikeLimited || !t.limited[r] || unlike(t.lightest[r], t.heaviest[r]));
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
    // Each tree's rows, joint by joint: the point rows, then a limited joint's lower and upper limit.
    using Kind = RevoluteTrees::RowKind;
    for (int tree = 0; tree < trees; ++tree) {
        for (int i = 0; i < t.start[tree + 1] - t.start[tree]; ++i) {
            const bool limit = keys[t.joints[t.start[tree] + i]].limited;
            for (const Kind kind : {Kind::PointX, Kind::PointY, Kind::Lower, Kind::Upper}) {
                if (!limit && (kind == Kind::Lower || kind == Kind::Upper)) continue;
                t.rowJoint.push_back(i);
                t.rowKind.push_back(kind);
            }
        }
        t.rowStart.push_back(static_cast<int>(t.rowJoint.size()));
    }
}

void warmStartRevoluteTrees(SolverBodies& bodies, RevoluteTrees& t, std::vector<PreparedJoint>& prepared) {
    for (int k : t.joints) {
        JointPair p = pairOf(bodies.states, bodies.stepRotation, prepared[k]);
        warmStartRevolute(prepared[k], p);
    }
}

namespace {

using Kind = RevoluteTrees::RowKind;

bool isPointRow(Kind kind) { return kind == Kind::PointX || kind == Kind::PointY; }

Row rowOf(const std::array<float, 4>& r) { return {{r[0], r[1]}, r[2], r[3]}; }

// A tree row's Jacobian at the current frame f of its joint: along x or y at the anchors, or on ωB − ωA.
Row treeRow(Kind kind, const JointFrame& f) {
    switch (kind) {
        case Kind::PointX: return linearRow(f.rA, f.rB, Vec2{1.0f, 0.0f});
        case Kind::PointY: return linearRow(f.rA, f.rB, Vec2{0.0f, 1.0f});
        case Kind::Lower: return angularRow;
        default: return negated(angularRow);
    }
}

// A joint row's sides (row_sides.hpp): −n, −sA on A, n, sB on B, with the joint's inverse masses
// (its inertias raised by the geometric stiffness, joint_tree_stiffness.hpp, alike for every tree
// joint at a body).
std::array<RowSide, 2> sidesOf(const PreparedJoint& j, const Row& r) {
    return {RowSide{j.indexA, -r.n, -r.sA, j.mass.mA, j.mass.iA}, RowSide{j.indexB, r.n, r.sB, j.mass.mB, j.mass.iB}};
}

// The rows of tree `tree` at the anchors now (those `keep` takes, by index into rowJoint), into t.rows, and
// their K, raised on its diagonal, into t.K and its Cholesky factor into t.L, both on an envelope
// from column 0; t.rA, t.rB hold each joint's arms. Returns the shape, n = 0 where K does not factor.
template <class Keep>
EnvelopeShape assemble(SolverBodies& bodies, RevoluteTrees& t, const std::vector<PreparedJoint>& prepared, size_t tree, Keep keep) {
    const int first = t.start[tree], joints = t.start[tree + 1] - first;
    t.rA.resize(joints);
    t.rB.resize(joints);
    for (int i = 0; i < joints; ++i) {
        const PreparedJoint& j = prepared[t.joints[first + i]];
        const JointFrame f = currentFrame(j, pairOf(bodies.states, bodies.stepRotation, j));
        t.rA[i] = f.rA;
        t.rB[i] = f.rB;
    }
    t.rows.clear();
    t.freeRow.clear();
    t.passRows.clear();
    for (int r = t.rowStart[tree]; r < t.rowStart[tree + 1]; ++r) {
        if (!keep(r)) continue;
        const int i = t.rowJoint[r];
        const Row row = treeRow(t.rowKind[r], JointFrame{t.rA[i], t.rB[i], {}});
        t.rows.push_back({row.n.x, row.n.y, row.sA, row.sB});
        t.freeRow.push_back(isPointRow(t.rowKind[r]) ? 1 : 0);
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
    auto sides = [&](int r) { return sidesOf(prepared[t.joints[first + t.rowJoint[t.passRows[r]]]], rowOf(t.rows[r])); };
    for (int r = 0; r < n; ++r) {
        const std::array<RowSide, 2> sr = sides(r);
        for (int s = 0; s <= r; ++s) t.K[shape.origin(r) + s] = coupling(sr, sides(s));
        t.K[shape.origin(r) + r] *= 1.0 + RevoluteTrees::diagonalRaise;
    }
    t.L = t.K;
    if (!choleskyFactor(t.L.data(), shape)) return {0, nullptr, nullptr, nullptr};
    return shape;
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

// A tree row's position error now: the gap along x or y, or how far the angle is inside a limit.
float rowError(const PreparedJoint& j, const JointPair& p, Kind kind) {
    const RevoluteJoint& r = j.data.as<RevoluteJoint>();
    const float angle = j.deltaAngle + p.rotation;
    switch (kind) {
        case Kind::PointX: return currentFrame(j, p).d.x;
        case Kind::PointY: return currentFrame(j, p).d.y;
        case Kind::Lower: return angle - r.lowerAngle;
        default: return r.upperAngle - angle;
    }
}

// Where row `kind` of a revolute joint keeps its accumulated λ.
float& impulseOf(RevoluteJoint& r, Kind kind) {
    switch (kind) {
        case Kind::PointX: return r.linearImpulse.x;
        case Kind::PointY: return r.linearImpulse.y;
        case Kind::Lower: return r.lowerImpulse;
        default: return r.upperImpulse;
    }
}

}  // namespace

void solveRevoluteTrees(SolverBodies& bodies, RevoluteTrees& t, std::vector<PreparedJoint>& prepared, const StepContext& ctx,
                        bool useBias) {
    const Softness soft = rigidSoftness(ctx, useBias);
    for (size_t tree = 0; tree + 1 < t.start.size(); ++tree) {
        const int first = t.start[tree], joints = t.start[tree + 1] - first;
        // A joint's motor first, one by one, as its own solve orders it (joint_revolute.cpp).
        for (int i = 0; i < joints; ++i) {
            PreparedJoint& j = prepared[t.joints[first + i]];
            if (pointRowsOnly(j)) continue;
            JointPair p = pairOf(bodies.states, bodies.stepRotation, j);
            solveRevoluteAngleRows(j, p, ctx, useBias, true, false);
        }
        const EnvelopeShape shape = assemble(bodies, t, prepared, tree, [](int) { return true; });
        const int n = shape.n;
        t.lcp.reserve(n, t.K.size());
        bool solved = n > 0;
        if (solved) {
            // y_r from the velocities now: a limit inside its range (C > 0) rigid, Ċ → −C/hs (it may
            // close the gap); the others the soft step, Ċ + biasRate·C and the leak of K λ.
            for (int r = 0; r < n; ++r) {
                const int row = t.passRows[r];
                PreparedJoint& j = prepared[t.joints[first + t.rowJoint[row]]];
                RevoluteJoint& revolute = j.data.as<RevoluteJoint>();
                t.lcp.lambda[r] = impulseOf(revolute, t.rowKind[row]);
            }
            for (int r = 0; r < n; ++r) {
                const int row = t.passRows[r], i = t.rowJoint[row];
                PreparedJoint& j = prepared[t.joints[first + i]];
                const JointPair p = pairOf(bodies.states, bodies.stepRotation, j);
                const float v = rowVelocity(p, rowOf(t.rows[r]));
                const float C = rowError(j, p, t.rowKind[row]);
                if (!t.freeRow[r] && C > 0.0f) {
                    t.lcp.y[r] = -static_cast<double>(v + C * ctx.invHs);
                    continue;
                }
                double kLambda = 0.0;  // (K λ)_r
                forEachInRow(t.K.data(), shape, r, [&](int s, double k) { kLambda += k * t.lcp.lambda[s]; });
                t.lcp.y[r] = -soft.massScale * (v + soft.biasRate * C) - soft.impulseScale * kLambda;
            }
            solved = solveComplementarity(t.lcp, shape, t.K.data(), t.L.data(), t.freeRow.data());
        }
        if (!solved) {  // joint by joint: the limits, then the point rows
            for (int i = 0; i < joints; ++i) {
                PreparedJoint& j = prepared[t.joints[first + i]];
                JointPair p = pairOf(bodies.states, bodies.stepRotation, j);
                solveRevoluteAngleRows(j, p, ctx, useBias, false, true);
                const JointFrame f = currentFrame(j, p);
                solvePointRows(p, f.rA, f.rB, f.d, soft, j.data.as<RevoluteJoint>().linearImpulse);
            }
            continue;
        }
        // Every Δλ from the velocities before any is applied: the solve already couples them.
        for (int r = 0; r < n; ++r) {
            const int row = t.passRows[r];
            PreparedJoint& j = prepared[t.joints[first + t.rowJoint[row]]];
            float& lambda = impulseOf(j.data.as<RevoluteJoint>(), t.rowKind[row]);
            float newLambda = lambda + static_cast<float>(t.lcp.x[r]);
            if (!t.freeRow[r]) newLambda = std::max(newLambda, 0.0f);
            t.lcp.x[r] = newLambda - lambda;
            lambda = newLambda;
        }
        for (int r = 0; r < n; ++r) {
            const PreparedJoint& j = prepared[t.joints[first + t.rowJoint[t.passRows[r]]]];
            JointPair p = pairOf(bodies.states, bodies.stepRotation, j);
            applyRow(p, rowOf(t.rows[r]), static_cast<float>(t.lcp.x[r]));
        }
    }
}

// Newton's step on the positions: K P = −C over the point rows, then each body moves by the
// position impulses (Box2D 2.4's position pass, exact for the whole tree instead of joint by joint).
// The limits stay out: taken in where the angle is past them, the 10,000 : 1 limited chain of
// RevoluteTree.LimitedHeavyChainKeepsItsHingesClosed opened 2.3 cm instead of 0.05 mm.
void projectRevoluteTrees(SolverBodies& bodies, RevoluteTrees& t, const std::vector<PreparedJoint>& prepared) {
    for (size_t tree = 0; tree + 1 < t.start.size(); ++tree) {
        const int first = t.start[tree];
        const EnvelopeShape shape = assemble(bodies, t, prepared, tree, [&](int row) { return isPointRow(t.rowKind[row]); });
        if (shape.n == 0) continue;
        t.lcp.reserve(shape.n, 0);
        std::vector<double>& P = t.lcp.x;
        for (int r = 0; r < shape.n; ++r) {
            const int row = t.passRows[r];
            const PreparedJoint& j = prepared[t.joints[first + t.rowJoint[row]]];
            P[r] = -rowError(j, pairOf(bodies.states, bodies.stepRotation, j), t.rowKind[row]);
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
