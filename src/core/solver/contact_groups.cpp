#include "core/solver/contact_groups.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>

#include "core/solver/cholesky.hpp"
#include "core/solver/complementarity.hpp"
#include "core/solver/contact_prepare.hpp"
#include "core/solver/row_sides.hpp"
#include "core/base/union_find.hpp"

namespace perpdot {
namespace {

enum SlotKind : uint8_t { Fixed, Free, Jointed };

// K's diagonal is raised by this fraction: more rows than the bodies have freedoms (a box on two
// tiles: four rows, three freedoms) make K singular, and rows pushing against each other would
// take any impulse. The rest state gains compliance·F K_ii / ω², a thousandth of the sequential sink.
constexpr double compliance = 1e-3;

// −n, −perpDot(rA, n) for A; n, perpDot(rB, n) for B.
std::array<RowSide, 2> sidesOf(const SolverBodies& bodies, const ContactConstraint& c, const ContactRows<float>& rows,
                               const ContactPointRows<float>& cp) {
    const Vec2 n = rows.normal;
    const RowMasses m = rowMasses(bodies, c.indexA, c.indexB);
    return {RowSide{c.indexA, -n, -perpDot(cp.anchorA, n), m.invMassA, m.invIA},
            RowSide{c.indexB, n, perpDot(cp.anchorB, n), m.invMassB, m.invIB}};
}

// A joint row's: −n, −sA for A; n, sB for B (joint_rows.hpp).
std::array<RowSide, 2> sidesOf(const SolverBodies& bodies, const JointScratch& joints, const ContactGroups::JointRow& row) {
    const auto [a, b] = jointSlots(joints, row.joint);
    const RowMasses m = rowMasses(bodies, a, b);
    const DirectJointRow& j = row.jacobian;
    return {RowSide{a, -j.n, -j.sA, m.invMassA, m.invIA}, RowSide{b, j.n, j.sB, m.invMassB, m.invIB}};
}

// Row `row` of the groups (an index into g.rows): a contact's normal row or a joint's row.
std::array<RowSide, 2> sidesOf(const ContactScratch& contacts, const SolverBodies& bodies, const JointScratch& joints, int row) {
    const auto [k, i] = contacts.groups.rows[row];
    if (k < 0) return sidesOf(bodies, joints, contacts.groups.jointRows[i]);
    const ContactRows<float>& rows = contacts.constraintRows[k];
    return sidesOf(bodies, contacts.constraints[k], rows, rows.points[i]);
}

// J v of a row: Σ over its sides lin·v + ang ω.
float rowVelocity(const std::array<RowSide, 2>& sides, const SolverBodies& bodies) {
    float v = 0.0f;
    for (const RowSide& p : sides) v += dot(p.lin, bodies.states[p.slot].v) + p.ang * bodies.states[p.slot].w;
    return v;
}

// λ along a row: each side's body moves by M⁻¹ Jᵀ λ.
void applyRow(const std::array<RowSide, 2>& sides, SolverBodies& bodies, float impulse) {
    for (const RowSide& p : sides) {
        if (p.slot == 0) continue;
        BodyState& s = bodies.states[p.slot];
        s.v = s.v + (p.invMass * impulse) * p.lin;
        s.w += p.invInertia * impulse * p.ang;
    }
}

// Group `group`'s K, stored on its envelope.
EnvelopeShape shapeOf(const ContactGroups& g, int group) {
    const int first = g.rowStart[group];
    return {g.rowStart[group + 1] - first, &g.firstColumn[first], &g.lastRow[first], &g.diagonal[first]};
}

// Rows of group `group` assembled into K and factored into L; false if K is singular.
bool assemble(const SolverWorld& w, ContactGroups& g, int group) {
    const int first = g.rowStart[group], n = g.rowStart[group + 1] - first;
    const EnvelopeShape shape = shapeOf(g, group);
    double* K = &g.K[g.matrixStart[group]];
    double* L = &g.L[g.matrixStart[group]];
    auto sides = [&](int row) { return sidesOf(w.scratch.contacts, w.scratch.bodies, w.scratch.joints, first + row); };
    for (int r = 0; r < n; ++r) {
        const std::array<RowSide, 2> sr = sides(r);
        for (int s = shape.first(r); s <= r; ++s) K[shape.origin(r) + s] = coupling(sr, sides(s));
        K[shape.origin(r) + r] *= 1.0 + compliance;
    }
    std::copy(K, &g.K[g.matrixStart[group + 1]], L);
    return choleskyFactor(L, shape);
}

// Whether this step's constraints join the same slots with the same point counts, and the slots
// have the same kinds, as when remember last ran.
bool sameAsLastStep(const ContactScratch& s, const ContactGroups& g) {
    auto same = [](const auto& a, const auto& b) {  // one memcmp, not one per element
        return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(a[0])) == 0);
    };
    if (!same(s.constraintSlots, g.lastSlots) || !same(g.kind, g.lastKind)) return false;
    for (size_t k = 0; k < s.constraints.size(); ++k)
        if (s.constraints[k].pointCount != g.lastPointCounts[k]) return false;
    return true;
}

void remember(const ContactScratch& s, ContactGroups& g, bool noneSmall) {
    g.lastSlots = s.constraintSlots;
    g.lastKind = g.kind;
    g.lastPointCounts.resize(s.constraints.size());
    for (size_t k = 0; k < s.constraints.size(); ++k) g.lastPointCounts[k] = s.constraints[k].pointCount;
    g.noneSmall = noneSmall;
}

}  // namespace

void findContactGroups(const SolverWorld& w, const StepContext& ctx) {
    ContactGroups& g = w.scratch.contacts.groups;
    const int slots = static_cast<int>(w.scratch.bodies.states.size());
    const int count = static_cast<int>(w.scratch.contacts.constraints.size());
    g.direct.assign(static_cast<size_t>(count), 0);
    g.constraints.clear();
    g.start.assign(1, 0);
    g.rows.clear();
    g.jointRows.clear();
    g.freeRow.clear();
    g.firstColumn.clear();
    g.lastRow.clear();
    g.diagonal.clear();
    g.rowStart.assign(1, 0);
    g.matrixStart.assign(1, 0);
    // Loads are measured in g: λn K_ii / hs ≥ loadTrigger·g, i.e. λn ≥ loadTrigger·g·hs·normalMass.
    const float loadImpulse = ContactGroups::loadTrigger * length(w.gravity) * ctx.hs;
    // From the contact: the rows are prepared once the groups are known (contact_prepare.hpp).
    auto loaded = [&](const ContactConstraint& c) {
        const Contact& contact = w.contactCache.contacts[c.contact];
        const RowMasses m = rowMasses(w.scratch.bodies, c.indexA, c.indexB);
        for (int i = 0; i < c.pointCount; ++i) {
            const ContactPointState& p = contact.points[i];
            const float normalMass = effectiveMass<float>(m, p.anchorA, p.anchorB, contact.normal);
            if (warmStartImpulse(ctx, p.normalImpulse) >= loadImpulse * normalMass && normalMass > 0.0f) return true;
        }
        return false;
    };
    // A hit: a point closing faster than hitSpeed on a body with joints from one hitRatio times
    // heavier; its group is solved only where that body is anchored (Free below).
    auto struck = [&](const ContactConstraint& c) {
        const BodyState &a = w.scratch.bodies.states[c.indexA], &b = w.scratch.bodies.states[c.indexB];
        const float lighter = std::max(a.invMass, b.invMass), heavier = std::min(a.invMass, b.invMass);
        if (!(heavier > 0.0f) || lighter < hitRatio * heavier) return false;
        if (w.bodies[w.scratch.bodies.awakeBodies[(a.invMass > b.invMass ? c.indexA : c.indexB) - 1]].jointCount == 0) return false;
        const Contact& contact = w.contactCache.contacts[c.contact];
        for (int i = 0; i < c.pointCount; ++i) {
            const ContactPointState& p = contact.points[i];
            if (dot(relativeVelocity(a, b, p.anchorA, p.anchorB), contact.normal) < -ContactGroups::hitSpeed) return true;
        }
        return false;
    };
    auto triggers = [&](const ContactConstraint& c) { return (loadImpulse > 0.0f && loaded(c)) || struck(c); };
    if (std::none_of(w.scratch.contacts.constraints.begin(), w.scratch.contacts.constraints.end(), triggers)) return;

    // Each solver slot's kind: Fixed (the static slot, kinematic bodies: they join nothing),
    // Free (dynamic, anchored or without joints: each of its joints ties it to a Fixed slot with
    // rows its group takes), Jointed (dynamic with a joint to another dynamic body, or one whose
    // rows stay sequential: its group is not solved directly, so chains keep their joint trees).
    JointScratch& joints = w.scratch.joints;
    const int jointCount = awakeJointCount(joints);
    std::array<DirectJointRow, maxDirectJointRows> jointRows;
    g.jointRowCount.resize(static_cast<size_t>(jointCount));
    g.kind.resize(static_cast<size_t>(slots));
    g.kind[0] = Fixed;
    for (int k = 1; k < slots; ++k) g.kind[k] = w.bodies[w.scratch.bodies.awakeBodies[k - 1]].type != BodyType::Dynamic ? Fixed : Free;
    for (int j = 0; j < jointCount; ++j) {
        const auto [a, b] = jointSlots(joints, j);
        g.jointRowCount[j] = directJointRows(joints, j, jointRows.data());
        if (g.jointRowCount[j] > 0 && (g.kind[a] == Fixed || g.kind[b] == Fixed)) continue;
        for (const int slot : {a, b})
            if (g.kind[slot] == Free) g.kind[slot] = Jointed;
    }
    for (int j = 0; j < jointCount; ++j) {  // the rows of an anchored body's joints only
        const auto [a, b] = jointSlots(joints, j);
        if (g.kind[a] != Free && g.kind[b] != Free) g.jointRowCount[j] = 0;
    }
    // A settled pile keeps its constraints from step to step: with last step's slots, point counts
    // and kinds, the groups are last step's, and if none was small enough then, none is now.
    if (g.noneSmall && sameAsLastStep(w.scratch.contacts, g)) return;

    // Join the slots the constraints couple, and count each constraint's rows at its slot (its
    // dynamic one; a slot that moves nothing stays its own root), 2 in `loaded` if it is jointed.
    g.root.resize(static_cast<size_t>(slots));
    std::iota(g.root.begin(), g.root.end(), 0);
    g.rowCount.assign(static_cast<size_t>(slots), 0);
    g.loaded.assign(static_cast<size_t>(slots), 0);
    auto slotOf = [&](int k) {
        const auto [a, b] = w.scratch.contacts.constraintSlots[k];
        return g.kind[a] != Fixed ? a : b;
    };
    auto jointSlotOf = [&](int j) {
        const auto [a, b] = jointSlots(joints, j);
        return g.kind[a] != Fixed ? a : b;
    };
    for (int k = 0; k < count; ++k) {
        const auto [a, b] = w.scratch.contacts.constraintSlots[k];
        if (g.kind[a] != Fixed && g.kind[b] != Fixed) unite(g.root, a, b);
        g.rowCount[slotOf(k)] += w.scratch.contacts.constraints[k].pointCount;
    }
    for (int j = 0; j < jointCount; ++j) g.rowCount[jointSlotOf(j)] += g.jointRowCount[j];  // an anchored body's joints
    for (int k = 0; k < slots; ++k)
        if (g.kind[k] == Jointed) g.loaded[k] = 2;
    // unite keeps the smaller slot as the root, so every parent precedes its child: one sweep in
    // slot order points every slot at its root and sums the rows there, jointed if any slot is.
    for (int k = 0; k < slots; ++k) {
        const int root = g.root[k] = g.root[g.root[k]];
        if (root == k) continue;
        g.rowCount[root] += g.rowCount[k];
        g.loaded[root] = std::max(g.loaded[root], g.loaded[k]);
    }
    g.withJoints.assign(static_cast<size_t>(slots), 0);  // by root: the group takes joint rows
    for (int j = 0; j < jointCount; ++j)
        if (g.jointRowCount[j] > 0) g.withJoints[g.root[jointSlotOf(j)]] = 1;
    // Each group's factor cost, its rows in constraint order: row r's envelope reaches back to the
    // first row sharing a moving body with it (envelopeFirst), Σ_r p_r² (cholesky.hpp).
    g.firstRow.assign(static_cast<size_t>(slots), -1);
    g.placed.assign(static_cast<size_t>(slots), 0);
    g.cost.assign(static_cast<size_t>(slots), 0);
    auto moving = [&](int slot) { return g.kind[slot] != Fixed ? slot : -1; };
    // `rows` rows between slots a and b placed next in root's group: each adds its profile².
    auto place = [&](int root, int a, int b, int rows) {
        if (g.loaded[root] != 0) return;  // jointed
        const int first = envelopeFirst(g.firstRow, g.placed[root], moving(a), moving(b));
        for (int i = 0; i < rows; ++i, ++g.placed[root])
            g.cost[root] += static_cast<int64_t>(g.placed[root] - first + 1) * (g.placed[root] - first + 1);
    };
    for (int k = 0; k < count; ++k) {
        const auto [a, b] = w.scratch.contacts.constraintSlots[k];
        place(g.root[slotOf(k)], a, b, w.scratch.contacts.constraints[k].pointCount);
    }
    for (int j = 0; j < jointCount; ++j) {  // a group's joint rows follow its contacts', in joint order
        const auto [a, b] = jointSlots(joints, j);
        if (g.jointRowCount[j] > 0) place(g.root[jointSlotOf(j)], a, b, g.jointRowCount[j]);
    }
    auto small = [&](int root) { return g.loaded[root] != 2 && admitted(g.rowCount[root], g.cost[root]); };
    bool anySmall = false;  // a group, not jointed, small or banded enough to solve directly
    for (int k = 0; k < slots; ++k) anySmall = anySmall || (g.root[k] == k && g.rowCount[k] > 0 && small(k));
    remember(w.scratch.contacts, g, !anySmall);
    if (!anySmall) return;  // a settled pile: one group, too large
    // Per small root: whether one of its rows is loaded or struck (1); costlier groups are never
    // direct. A group with joint rows is solved on a hit only: under a steady load its joints keep
    // their sequential passes.
    for (int k = 0; k < count; ++k) {
        const int root = g.root[slotOf(k)];
        const ContactConstraint& c = w.scratch.contacts.constraints[k];
        if (g.loaded[root] == 0 && small(root) && (struck(c) || (!g.withJoints[root] && loadImpulse > 0.0f && loaded(c)))) g.loaded[root] = 1;
    }

    // Groups in the order of their first constraint while the step's rows last; the constraints of
    // each in constraint order. Storage for the most rows is taken once, then reused.
    g.groupOf.assign(static_cast<size_t>(slots), -1);
    int groups = 0, rowsLeft = ContactGroups::maxTotalRows;
    for (int k = 0; k < count; ++k) {
        const int root = g.root[slotOf(k)], n = g.rowCount[root];
        if (g.loaded[root] != 1 || n > rowsLeft || g.groupOf[root] >= 0) continue;
        g.groupOf[root] = groups++;
        rowsLeft -= n;
    }
    if (groups == 0) return;
    for (std::vector<int>* v : {&g.constraints, &g.start, &g.rowStart, &g.firstColumn, &g.lastRow}) v->reserve(ContactGroups::maxTotalRows + 1);
    for (std::vector<size_t>* v : {&g.matrixStart, &g.diagonal}) v->reserve(ContactGroups::maxTotalRows + 1);
    g.rows.reserve(ContactGroups::maxTotalRows);
    for (std::vector<double>* v : {&g.K, &g.L}) v->reserve(static_cast<size_t>(ContactGroups::denseRows) * ContactGroups::maxTotalRows);
    g.start.assign(static_cast<size_t>(groups) + 1, 0);
    auto groupOf = [&](int k) { return g.groupOf[g.root[slotOf(k)]]; };
    for (int k = 0; k < count; ++k)
        if (groupOf(k) >= 0) ++g.start[groupOf(k) + 1];
    std::partial_sum(g.start.begin(), g.start.end(), g.start.begin());
    g.constraints.resize(static_cast<size_t>(g.start.back()));
    g.rowCount.assign(static_cast<size_t>(groups), 0);  // now: constraints placed per group
    for (int k = 0; k < count; ++k)
        if (const int group = groupOf(k); group >= 0) g.constraints[g.start[group] + g.rowCount[group]++] = k;

    // Each group's rows, K and factor; a group whose K does not factor stays with the sequential rows.
    for (int k : g.constraints) prepareContactRows(w, ctx, w.scratch.contacts.constraints[k], w.scratch.contacts.constraintRows[k]);
    int kept = 0, mostRows = 0;
    size_t largest = 0;
    for (int group = 0; group < groups; ++group) {
        const int rowsBefore = static_cast<int>(g.rows.size()), jointRowsBefore = static_cast<int>(g.jointRows.size());
        for (int s = g.start[group]; s < g.start[group + 1]; ++s) {
            const int k = g.constraints[s];
            const auto [a, b] = w.scratch.contacts.constraintSlots[k];
            const int first = envelopeFirst(g.firstRow, static_cast<int>(g.rows.size()) - rowsBefore, moving(a), moving(b));
            for (int i = 0; i < w.scratch.contacts.constraints[k].pointCount; ++i) {
                g.rows.push_back({k, i});
                g.freeRow.push_back(0);
                g.firstColumn.push_back(first);
            }
        }
        for (int j = 0; j < jointCount; ++j) {
            if (g.jointRowCount[j] == 0 || g.groupOf[g.root[jointSlotOf(j)]] != group) continue;
            const auto [a, b] = jointSlots(joints, j);
            const int first = envelopeFirst(g.firstRow, static_cast<int>(g.rows.size()) - rowsBefore, moving(a), moving(b));
            directJointRows(joints, j, jointRows.data());
            for (int i = 0; i < g.jointRowCount[j]; ++i) {
                g.rows.push_back({-1, static_cast<int>(g.jointRows.size())});
                g.jointRows.push_back({j, i, jointRows[i], directJointImpulse(joints, j, i)});
                g.freeRow.push_back(jointRows[i].oneSided ? 0 : 1);
                g.firstColumn.push_back(first);
            }
        }
        const int n = static_cast<int>(g.rows.size()) - rowsBefore;
        g.lastRow.resize(g.rows.size());
        g.diagonal.resize(g.rows.size());
        envelopeLastRows(&g.firstColumn[rowsBefore], n, &g.lastRow[rowsBefore]);
        const size_t envelope = envelopeLayout(&g.firstColumn[rowsBefore], n, &g.diagonal[rowsBefore]);
        g.rowStart.push_back(static_cast<int>(g.rows.size()));
        g.matrixStart.push_back(g.matrixStart.back() + envelope);
        g.K.resize(g.matrixStart.back());
        g.L.resize(g.matrixStart.back());
        if (!assemble(w, g, kept)) {
            for (std::vector<int>* v : {&g.firstColumn, &g.lastRow}) v->resize(static_cast<size_t>(rowsBefore));
            g.diagonal.resize(static_cast<size_t>(rowsBefore));
            g.rows.resize(static_cast<size_t>(rowsBefore));
            g.freeRow.resize(static_cast<size_t>(rowsBefore));
            g.jointRows.resize(static_cast<size_t>(jointRowsBefore));
            g.rowStart.pop_back();
            g.matrixStart.pop_back();
            continue;
        }
        mostRows = std::max(mostRows, n);
        largest = std::max(largest, envelope);
        // Keep the group: its constraints move down to follow the groups kept before it.
        const int size = g.start[group + 1] - g.start[group];
        std::copy(g.constraints.begin() + g.start[group], g.constraints.begin() + g.start[group + 1],
                  g.constraints.begin() + g.start[kept]);
        g.start[kept + 1] = g.start[kept] + size;
        for (int s = g.start[kept]; s < g.start[kept + 1]; ++s) g.direct[g.constraints[s]] = 1;
        for (int j = jointRowsBefore; j < static_cast<int>(g.jointRows.size()); ++j)
            if (g.jointRows[j].row == 0) solveJointDirectly(joints, g.jointRows[j].joint);
        ++kept;
    }
    g.start.resize(static_cast<size_t>(kept) + 1);
    g.constraints.resize(static_cast<size_t>(g.start.back()));
    // The pivoting's scratch, for the most rows and the largest envelope (its active systems' are within).
    g.lcp.reserve(mostRows, largest);
}

namespace {

// One pass of a group's rows as one system, the targets from the velocities before any impulse of
// the pass: a speculative one-sided row (a contact point or a limit with C > 0) rigid, v → −C/hs
// (it may close the gap); with bias, the soft step K Δλ = −massScale·(v + bias) − impulseScale·K λ,
// each row with its softness (contacts: the contact softness and push limits; joints: the joint
// softness, bias = biasRate·C); without, v → 0. False when its complementarity problem did not
// settle: then only the joint rows are solved, one by one (projected Gauss-Seidel on the same
// targets), and the caller solves the contact rows as the sequential passes do.
bool solveGroupRows(ContactScratch& contacts, SolverBodies& bodies, JointScratch& joints, int group, const StepContext& ctx, bool useBias) {
    ContactGroups& g = contacts.groups;
    const int first = g.rowStart[group], n = g.rowStart[group + 1] - first;
    const EnvelopeShape shape = shapeOf(g, group);
    const double* K = &g.K[g.matrixStart[group]];
    const double* L = &g.L[g.matrixStart[group]];
    std::array<float, maxDirectJointRows> errors{};
    for (int r = 0; r < n; ++r) {
        const auto [k, i] = g.rows[first + r];
        if (k >= 0) {
            g.lcp.lambda[r] = contacts.constraintRows[k].points[i].normalImpulse;
            continue;
        }
        ContactGroups::JointRow& row = g.jointRows[i];
        if (row.row == 0) directJointErrors(joints, bodies, row.joint, errors.data());
        row.C = errors[row.row];
        g.lcp.lambda[r] = row.lambda;
    }
    auto target = [&](int r) {  // y_r from the velocities now
        const auto [k, i] = g.rows[first + r];
        float v = 0.0f, C = 0.0f, bias = 0.0f;
        Softness soft = ctx.jointSoftness;
        if (k >= 0) {
            const ContactRows<float>& rows = contacts.constraintRows[k];
            const ContactPointRows<float>& cp = rows.points[i];
            const BodyState &a = bodies.states[contacts.constraints[k].indexA], &b = bodies.states[contacts.constraints[k].indexB];
            v = dot(relativeVelocity(a, b, cp.anchorA, cp.anchorB), rows.normal);
            C = currentSeparation(rows, cp, a, b);
            soft = ctx.contactSoftness;  // one softness for all contact rows: the rest state C = K F / ω²
            bias = std::max(soft.biasRate * std::min(C + ctx.pushSlop, 0.0f), -ctx.maxBiasVelocity);
        } else {
            v = rowVelocity(sidesOf(contacts, bodies, joints, first + r), bodies);
            C = g.jointRows[i].C;
            bias = soft.biasRate * C;
        }
        if (!g.freeRow[first + r] && C > 0.0f) return -static_cast<double>(v + C * ctx.invHs);
        if (!useBias) return -static_cast<double>(v);
        double kLambda = 0.0;  // (K λ)_r
        forEachInRow(K, shape, r, [&](int q, double kq) { kLambda += kq * g.lcp.lambda[q]; });
        return -soft.massScale * (v + bias) - soft.impulseScale * kLambda;
    };
    auto applyJointRow = [&](int r, double impulse) {
        ContactGroups::JointRow& row = g.jointRows[g.rows[first + r][1]];
        row.lambda += impulse;
        setDirectJointImpulse(joints, row.joint, row.row, static_cast<float>(row.lambda));
        applyRow(sidesOf(contacts, bodies, joints, first + r), bodies, static_cast<float>(impulse));
    };
    for (int r = 0; r < n; ++r) g.lcp.y[r] = target(r);
    if (!solveComplementarity(g.lcp, shape, K, L, &g.freeRow[first])) {
        for (int r = 0; r < n; ++r) {
            if (g.rows[first + r][0] >= 0) continue;
            double impulse = target(r) / K[shape.origin(r) + r];  // K_rr Δλ = y_r
            if (!g.freeRow[first + r]) impulse = std::max(g.lcp.lambda[r] + impulse, 0.0) - g.lcp.lambda[r];
            g.lcp.lambda[r] += impulse;
            applyJointRow(r, impulse);
        }
        return false;
    }
    for (int r = 0; r < n; ++r) {
        const auto [k, i] = g.rows[first + r];
        if (k < 0) {
            applyJointRow(r, g.lcp.x[r]);
            continue;
        }
        const ContactConstraint& c = contacts.constraints[k];
        ContactRows<float>& rows = contacts.constraintRows[k];
        ContactPointRows<float>& cp = rows.points[i];
        const float newImpulse = std::max(cp.normalImpulse + static_cast<float>(g.lcp.x[r]), 0.0f);
        const float impulse = newImpulse - cp.normalImpulse;
        cp.normalImpulse = newImpulse;
        recordPush(rows, i, impulse, ctx);
        applyImpulse(rows, bodies.states[c.indexA], bodies.states[c.indexB], cp.anchorA, cp.anchorB, impulse * rows.normal);
    }
    return true;
}

}  // namespace

void contactGroupRows(ContactScratch& contacts, SolverBodies& bodies, JointScratch& joints, const StepContext& ctx, RowPass pass) {
    ContactGroups& g = contacts.groups;
    if (pass == RowPass::Restitution) {  // the bounce is row by row, as for every constraint
        const std::vector<SubstepForces>& forces = bodies.substepForces;
        for (int index : g.constraints) {
            const ContactConstraint& c = contacts.constraints[index];
            restituteContact(contacts.constraintRows[index], bodies.states[c.indexA], bodies.states[c.indexB], LaneBodies<float>::velocityChange(forces.data(), c.indexA),
                             LaneBodies<float>::velocityChange(forces.data(), c.indexB), ctx);
        }
        return;
    }
    for (int group = 0; group + 1 < static_cast<int>(g.start.size()); ++group) {
        const bool useBias = pass == RowPass::Solve;
        if (pass == RowPass::WarmStart)  // the group's joint rows re-apply their λ of this step
            for (int row = g.rowStart[group]; row < g.rowStart[group + 1]; ++row)
                if (g.rows[row][0] < 0) applyRow(sidesOf(contacts, bodies, joints, row), bodies, static_cast<float>(g.jointRows[g.rows[row][1]].lambda));
        const bool solved = pass != RowPass::WarmStart && solveGroupRows(contacts, bodies, joints, group, ctx, useBias);
        for (int s = g.start[group]; s < g.start[group + 1]; ++s) {
            const ContactConstraint& c = contacts.constraints[g.constraints[s]];
            ContactRows<float>& rows = contacts.constraintRows[g.constraints[s]];
            BodyState &a = bodies.states[c.indexA], &b = bodies.states[c.indexB];
            if (pass == RowPass::WarmStart) warmStartContact(rows, a, b);
            else if (solved && useBias) solveContact<true, false>(rows, a, b, ctx);  // its tangent rows
            else if (solved) solveContact<false, false>(rows, a, b, ctx);
            else if (useBias) solveContact<true>(rows, a, b, ctx);
            else solveContact<false>(rows, a, b, ctx);
        }
    }
}

}  // namespace perpdot
