#include "core/joints/joint_tree.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

#include "core/solver/cholesky.hpp"
#include "core/joints/joint_revolute.hpp"
#include "core/joints/joint_rows.hpp"
#include "core/base/union_find.hpp"
#include "core/world/step_scratch.hpp"

namespace perpdot {
namespace {

// The moving body a joint's side stands for, with its inverse mass and inertia and the arm from
// its centre of mass to the anchor; sign +1 for B (B's anchor velocity counts positive), −1 for A.
struct Side {
    int slot;
    double sign, invMass, invInertia;
    Vec2 r;
};

// Adds the coupling of joints i and l through a body they share to K's blocks (i, l) and (l, i):
// sᵢ sₗ (invMass·𝟙 + invInertia·perp(rᵢ) perp(rₗ)ᵀ).
void couple(std::vector<double>& K, int n, int i, int l, const Side& a, const Side& b) {
    const Vec2 pa = perp(a.r), pb = perp(b.r);
    const double s = a.sign * b.sign;
    const double block[2][2] = {{s * (a.invMass + a.invInertia * pa.x * pb.x), s * a.invInertia * pa.x * pb.y},
                                {s * a.invInertia * pa.y * pb.x, s * (a.invMass + a.invInertia * pa.y * pb.y)}};
    for (int r = 0; r < 2; ++r)
        for (int c = 0; c < 2; ++c) {
            K[(2 * i + r) * n + 2 * l + c] += block[r][c];
            K[(2 * l + c) * n + 2 * i + r] += block[r][c];
        }
}

}  // namespace

// Union-find over the moving bodies the joints link, keeping each group's joint count; groups too
// large for a dense K stay with the sequential passes. A group may close a loop or hang between
// two fixed anchors (assemble: K's raised diagonal).
void findRevoluteTrees(RevoluteTrees& t, const std::vector<JointKey>& keys, int slots) {
    const int count = static_cast<int>(keys.size());
    t.joints.clear();
    t.start.assign(1, 0);
    t.inTree.assign(keys.size(), 0);
    if (count < 2) return;
    t.root.resize(slots);
    std::iota(t.root.begin(), t.root.end(), 0);
    t.jointCount.assign(slots, 0);
    // A side that cannot move (static, asleep, kinematic) couples nothing: it anchors the tree.
    for (const JointKey& j : keys) {
        if (!j.hinge) continue;
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
    const auto isTree = [&](int r) { return t.jointCount[r] >= 2 && t.jointCount[r] <= RevoluteTrees::maxJoints; };
    bool any = false;
    for (int r = 1; r < slots && !any; ++r) any = t.root[r] == r && isTree(r);
    if (!any) return;
    // Each joint's group, if it is a tree: -1 otherwise (t.treeOf, by prepared index).
    t.treeOf.assign(keys.size(), -1);
    int inTrees = 0;
    for (int k = 0; k < count; ++k) {
        const JointKey& j = keys[k];
        if (!j.hinge || (!j.movesA && !j.movesB)) continue;
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
}

void warmStartRevoluteTrees(SolverBodies& bodies, RevoluteTrees& t, std::vector<PreparedJoint>& prepared) {
    for (int k : t.joints) {
        JointPair p = pairOf(bodies.states, bodies.stepRotation, prepared[k]);
        warmStartRevolute(prepared[k], p);
    }
}

namespace {

// K of tree `tree` (2n x 2n, row-major) at the anchors now, with t.rA, t.rB set and t.x[2i..2i+1]
// = `row(joint, pair, frame)`, the right-hand side of joint i.
template <class Row>
int assemble(SolverBodies& bodies, RevoluteTrees& t, const std::vector<PreparedJoint>& prepared, size_t tree, Row row) {
    const int first = t.start[tree], joints = t.start[tree + 1] - first, n = 2 * joints;
    t.K.assign(static_cast<size_t>(n) * n, 0.0);
    t.x.resize(n);
    t.rA.resize(joints);
    t.rB.resize(joints);
    for (int i = 0; i < joints; ++i) {
        const PreparedJoint& j = prepared[t.joints[first + i]];
        const JointPair p = pairOf(bodies.states, bodies.stepRotation, j);
        const JointFrame f = currentFrame(j, p);
        t.rA[i] = f.rA;
        t.rB[i] = f.rB;
        const Vec2 b = row(p, f);
        t.x[2 * i] = b.x;
        t.x[2 * i + 1] = b.y;
        const Mat22T<float> Kii = pointMass(j.mass, f.rA, f.rB);
        t.K[(2 * i) * n + 2 * i] = (1.0 + RevoluteTrees::diagonalRaise) * Kii.cx.x;
        t.K[(2 * i + 1) * n + 2 * i] = Kii.cx.y;
        t.K[(2 * i) * n + 2 * i + 1] = Kii.cy.x;
        t.K[(2 * i + 1) * n + 2 * i + 1] = (1.0 + RevoluteTrees::diagonalRaise) * Kii.cy.y;
    }
    for (int i = 0; i < joints; ++i) {
        const PreparedJoint& ji = prepared[t.joints[first + i]];
        const Side si[2] = {{ji.indexA, -1.0, ji.mass.mA, ji.mass.iA, t.rA[i]}, {ji.indexB, 1.0, ji.mass.mB, ji.mass.iB, t.rB[i]}};
        for (int l = i + 1; l < joints; ++l) {
            const PreparedJoint& jl = prepared[t.joints[first + l]];
            const Side sl[2] = {{jl.indexA, -1.0, jl.mass.mA, jl.mass.iA, t.rA[l]}, {jl.indexB, 1.0, jl.mass.mB, jl.mass.iB, t.rB[l]}};
            for (const Side& a : si)
                for (const Side& b : sl)
                    if (a.slot == b.slot && (a.invMass != 0.0 || a.invInertia != 0.0)) couple(t.K, n, i, l, a, b);
        }
    }
    return n;
}

Vec2 lambdaOf(const std::vector<double>& x, int i) { return {static_cast<float>(x[2 * i]), static_cast<float>(x[2 * i + 1])}; }

// Moves a body's solver state by a position impulse P at arm r: Δc = P/m, Δθ = perpDot(r, P)/I.
void displace(SolverBodies& bodies, int slot, float invMass, float invInertia, Vec2 r, Vec2 P) {
    if (slot == 0) return;
    BodyState& s = bodies.states[slot];
    const float dAngle = invInertia * perpDot(r, P);
    s.dp += invMass * P;
    bodies.stepRotation[slot] += dAngle;
    s.dq = integrateRotation(s.dq, dAngle);
}

}  // namespace

void solveRevoluteTrees(SolverBodies& bodies, RevoluteTrees& t, std::vector<PreparedJoint>& prepared, const StepContext& ctx,
                        bool useBias) {
    const Softness soft = rigidSoftness(ctx, useBias);
    for (size_t tree = 0; tree + 1 < t.start.size(); ++tree) {
        const int first = t.start[tree], joints = t.start[tree + 1] - first;
        // A joint's motor and limits first, one by one, as its own solve orders them (joint_revolute.cpp):
        // the point rows, solved last, win.
        for (int i = 0; i < joints; ++i) {
            PreparedJoint& j = prepared[t.joints[first + i]];
            if (pointRowsOnly(j)) continue;
            JointPair p = pairOf(bodies.states, bodies.stepRotation, j);
            solveRevoluteAngleRows(j, p, ctx, useBias);
        }
        const int n = assemble(bodies, t, prepared, tree, [&](const JointPair& p, const JointFrame& f) {
            return relativeVelocity(p, f.rA, f.rB) + soft.biasRate * f.d;  // v_rel + biasRate·C
        });
        if (!choleskyFactor(t.K.data(), DenseShape{n})) {  // the point rows joint by joint
            for (int i = 0; i < joints; ++i) {
                PreparedJoint& j = prepared[t.joints[first + i]];
                JointPair p = pairOf(bodies.states, bodies.stepRotation, j);
                const JointFrame f = currentFrame(j, p);
                solvePointRows(p, f.rA, f.rB, f.d, soft, j.data.as<RevoluteJoint>().linearImpulse);
            }
            continue;
        }
        choleskySolve(t.K.data(), DenseShape{n}, t.x.data());
        // Every Δλ from the velocities before any is applied: the solve already couples them.
        for (int i = 0; i < joints; ++i) {
            PreparedJoint& j = prepared[t.joints[first + i]];
            Vec2& lambda = j.data.as<RevoluteJoint>().linearImpulse;
            const Vec2 newLambda = lambda - soft.massScale * lambdaOf(t.x, i) - soft.impulseScale * lambda;
            const Vec2 delta = newLambda - lambda;
            t.x[2 * i] = delta.x;
            t.x[2 * i + 1] = delta.y;
            lambda = newLambda;
        }
        for (int i = 0; i < joints; ++i) {
            const PreparedJoint& j = prepared[t.joints[first + i]];
            JointPair p = pairOf(bodies.states, bodies.stepRotation, j);
            applyPoint(p, t.rA[i], t.rB[i], lambdaOf(t.x, i));
        }
    }
}

// Newton's step on the positions: K P = −C, then each body moves by the position impulses at its
// anchors (Box2D 2.4's position pass, exact for the whole tree instead of joint by joint).
void projectRevoluteTrees(SolverBodies& bodies, RevoluteTrees& t, const std::vector<PreparedJoint>& prepared) {
    for (size_t tree = 0; tree + 1 < t.start.size(); ++tree) {
        const int first = t.start[tree], joints = t.start[tree + 1] - first;
        const int n = assemble(bodies, t, prepared, tree, [](const JointPair&, const JointFrame& f) { return -f.d; });
        if (!choleskyFactor(t.K.data(), DenseShape{n})) continue;
        choleskySolve(t.K.data(), DenseShape{n}, t.x.data());
        for (int i = 0; i < joints; ++i) {
            const PreparedJoint& j = prepared[t.joints[first + i]];
            const Vec2 P = lambdaOf(t.x, i);
            displace(bodies, j.indexA, j.mass.mA, j.mass.iA, t.rA[i], -P);
            displace(bodies, j.indexB, j.mass.mB, j.mass.iB, t.rB[i], P);
        }
    }
}

}  // namespace perpdot
