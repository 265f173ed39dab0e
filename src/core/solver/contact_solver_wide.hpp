// The contact rows, written once over a lane type F: float solves one constraint (the overflow
// colour, contact_solver.cpp, and the contact groups), simd::Float4 and the AVX2 Float8 solve four
// or eight constraints of one graph colour at once (contact_solver_wide.cpp). Each row is Hecker's collision impulse
//   j = -(v_rel·n + bias) / (1/mA + 1/mB + perpDot(rA,n)²/IA + perpDot(rB,n)²/IB)
// accumulated and clamped (λn ≥ 0, |λt| ≤ μ λn), softened by the substep's Softness.
//
// A lane that is not a real manifold point (a one-point manifold's second point, an empty lane of
// a block) has zero masses and zero impulses: its rows compute like the others and apply zero.
#pragma once

#include <array>
#include <bit>
#include <cstddef>
#include <type_traits>
#include <utility>
#include <vector>

#include "collide/collision.hpp"
#include "core/contacts/contact_cache.hpp"
#include "core/solver/body_lanes.hpp"
#include "core/solver/lane_block.hpp"
#include "core/solver/row_lanes.hpp"

namespace perpdot {

template <class F>
struct ContactPointRows {
    Vec2T<F> anchorA, anchorB;  // fixed for the step: rA, rB
    F baseSeparation{};         // separation minus (rB - rA)·n, so s = base + (ΔpB + rB' - ΔpA - rA')·n
    F normalImpulse{}, tangentImpulse{};
    F normalMass{}, tangentMass{};  // effectiveMass = 1/K of each row; 0 for no manifold point
};

// The fields every pass reads come first, up to the points; the others only where a lane of the
// block uses them (RowUses). With the block's solver slots before them (ContactBlock<8>), a pass over
// blocks of flat, plain contacts streams 13 of a block's 19 cache lines.
template <class F>
struct ContactRows {
    F invIA{}, invIB{};  // 1/I of the bodies (their 1/m is in their states: BodyLanes::invMass)
    Vec2T<F> normal;
    F friction{};
    ContactPointRows<F> points[2];
    // 1 where a body's surface is flat: its anchor is a point of the body and turns with it. 0 for a
    // round surface, whose contact point stays under its centre as it rolls.
    F turnsA{}, turnsB{};
    F tangentSpeed{};
    F rollingResistance{}, rollingMass{}, rollingImpulse{};  // angular row: 1/(1/IA + 1/IB), accumulated λ
    F restitution{};
    F maxNormalImpulse[2]{};  // the largest push of each point this step, where recorded (recordPush)
    F relativeVelocity[2]{};  // v_rel·n at each point before solving, for restitution
};

// Which of the rows' fields after the points a block's lanes use, found once it is laid out
// (rowUses), so that its passes leave the lines of the others unread. One constraint's own rows
// take RowUses{}, all of them: a general path gives a lane that does not use a field the bits the
// path without it gives.
struct RowUses {
    bool roundSurface = true;  // an anchor that does not turn with its body (turnsA or turnsB 0)
    bool conveyor = true;      // a tangent speed
    bool rolling = true;       // rolling resistance: the rolling row
    bool elastic = true;       // restitution: the restitution pass, which reads each point's largest push
};

// Apply impulse P at the anchors: vA -= P/mA, ωA -= perpDot(rA,P)/IA, and + for B.
template <class F>
inline void applyImpulse(const ContactRows<F>& c, BodyLanes<F>& a, BodyLanes<F>& b, Vec2T<F> rA, Vec2T<F> rB, Vec2T<F> P) {
    a.v = a.v - a.invMass * P;
    a.w = a.w - c.invIA * perpDot(rA, P);
    b.v = b.v + b.invMass * P;
    b.w = b.w + c.invIB * perpDot(rB, P);
}

// Rolling impulse λ on ωB − ωA where a lane has rolling resistance: ωA -= λ/IA, ωB += λ/IB.
template <class F>
inline void applyRollingImpulse(const ContactRows<F>& c, BodyLanes<F>& a, BodyLanes<F>& b, F impulse) {
    const simd::MaskOf<F> rolls = c.rollingResistance > F(0.0f);
    a.w = simd::select(rolls, a.w - c.invIA * impulse, a.w);
    b.w = simd::select(rolls, b.w + c.invIB * impulse, b.w);
}

// v_rel = v_B + ωB perp(rB) − (v_A + ωA perp(rA)).
template <class F>
inline Vec2T<F> relativeVelocity(const BodyLanes<F>& a, const BodyLanes<F>& b, Vec2T<F> rA, Vec2T<F> rB) {
    return pointVelocity(b.v, b.w, rB) - pointVelocity(a.v, a.w, rA);
}

// Last step's accumulated impulse, the warm start of this step's (0 without warm starting).
template <class F>
F warmStartImpulse(const StepContext& ctx, F impulse) {
    return F(ctx.enableWarmStarting ? 1.0f : 0.0f) * impulse;
}

// The inverse masses and inertias of a contact's bodies, for one constraint (F = float: RowMasses)
// or a block's lanes.
template <class F>
struct RowMassLanes {
    F invMassA{}, invIA{}, invMassB{}, invIB{};
};

// 1 / (1/mA + 1/mB + perpDot(rA,d)²/IA + perpDot(rB,d)²/IB): the effective mass along d, 0 if
// nothing can move.
template <class F>
F effectiveMass(const RowMassLanes<F>& m, Vec2T<F> rA, Vec2T<F> rB, Vec2T<F> d) {
    const F rnA = perpDot(rA, d), rnB = perpDot(rB, d);
    const F k = m.invMassA + m.invMassB + m.invIA * rnA * rnA + m.invIB * rnB * rnB;
    return simd::select(k > F(0.0f), F(1.0f) / k, F(0.0f));
}

// The rows' fields computed from the others, for one constraint (F = float) or a block's lanes at
// once, after the contact's values were gathered into them (prepareContactRows, contact_prepare.hpp):
// each point's separation in baseSeparation and its last accumulated impulses, zeros for no point.
// a, b: the bodies' velocities without contacts (v, ω); present[i]: 1 where point i is a manifold
// point, else 0. Warm start, rolling mass, and per point base separation, approach speed and
// effective masses.
template <class F>
void deriveContactRows(ContactRows<F>& c, const BodyLanes<F>& a, const BodyLanes<F>& b, const F (&present)[2], const StepContext& ctx) {
    using simd::select;
    if (!ctx.enableWarmStarting) c.rollingImpulse = F(0.0f);
    c.rollingImpulse = select(c.rollingResistance > F(0.0f), c.rollingImpulse, F(0.0f));  // no rolling row: none ever
    const F kRolling = c.invIA + c.invIB;
    c.rollingMass = select(c.rollingResistance > F(0.0f), select(kRolling > F(0.0f), F(1.0f) / kRolling, F(0.0f)), F(0.0f));
    const Vec2T<F> n = c.normal, t = perp(n);
    const RowMassLanes<F> m{a.invMass, c.invIA, b.invMass, c.invIB};
    for (int i = 0; i < 2; ++i) {
        ContactPointRows<F>& cp = c.points[i];
        const simd::MaskOf<F> point = present[i] > F(0.0f);
        const Vec2T<F> rA = cp.anchorA, rB = cp.anchorB;
        cp.baseSeparation = select(point, cp.baseSeparation - dot(rB - rA, n), F(0.0f));
        c.relativeVelocity[i] = select(point, dot(relativeVelocity(a, b, rA, rB), n), F(0.0f));
        cp.normalImpulse = warmStartImpulse(ctx, cp.normalImpulse);
        cp.tangentImpulse = warmStartImpulse(ctx, cp.tangentImpulse);
        c.maxNormalImpulse[i] = F(0.0f);
        cp.normalMass = select(point, effectiveMass<F>(m, rA, rB, n), F(0.0f));
        cp.tangentMass = select(point, effectiveMass<F>(m, rA, rB, t), F(0.0f));
    }
}

// Re-apply last step's accumulated impulses: λn n + λt perp(n) at each point, λr on the angle.
template <class F>
void warmStartContact(const ContactRows<F>& c, BodyLanes<F>& a, BodyLanes<F>& b, RowUses uses = {}) {
    const Vec2T<F> n = c.normal, t = perp(n);
    for (const ContactPointRows<F>& cp : c.points)
        applyImpulse(c, a, b, cp.anchorA, cp.anchorB, cp.normalImpulse * n + cp.tangentImpulse * t);
    if (uses.rolling) applyRollingImpulse(c, a, b, c.rollingImpulse);
}

// Anchor r turned with its body by Δq where its surface is flat (turns ≠ 0), else r.
template <class F>
Vec2T<F> turnedAnchor(RotT<F> dq, Vec2T<F> r, F turns, bool roundSurface) {
    const Vec2T<F> turned = rotate(dq, r);
    if (!roundSurface) return turned;
    const simd::MaskOf<F> flat = turns != F(0.0f);
    return {simd::select(flat, turned.x, r.x), simd::select(flat, turned.y, r.y)};
}

// Current separation of a point without a new narrowphase: s = base + (ΔpB + rB' − ΔpA − rA')·n,
// with r' the anchor turned with its body where the surface is flat.
template <class F>
F currentSeparation(const ContactRows<F>& c, const ContactPointRows<F>& cp, const BodyLanes<F>& a, const BodyLanes<F>& b,
                    RowUses uses = {}) {
    const Vec2T<F> turnedA = turnedAnchor(a.dq, cp.anchorA, c.turnsA, uses.roundSurface);
    const Vec2T<F> turnedB = turnedAnchor(b.dq, cp.anchorB, c.turnsB, uses.roundSurface);
    return cp.baseSeparation + dot(b.dp - a.dp + turnedB - turnedA, c.normal);
}

// Point i's largest push this step, λn,max, recorded where it is read: every lane when some shape
// reports hits (StepContext::hitEvents), else the elastic lanes (restituteContact); the others keep 0.
template <class F>
void recordPush(ContactRows<F>& c, int i, F impulse, const StepContext& ctx) {
    const F larger = simd::max(c.maxNormalImpulse[i], impulse);
    c.maxNormalImpulse[i] = ctx.hitEvents ? larger : simd::select(c.restitution != F(0.0f), larger, c.maxNormalImpulse[i]);
}

// One pass over a constraint's rows: non-penetration (λn ≥ 0) unless `normalRows` is false (a
// contact group solved them, contact_groups.hpp), then Coulomb friction along t = perp(n),
// |λt| ≤ μ λn, then rolling resistance, |λr| ≤ rollingResistance·Σλn. useBias: the solve pass
// (soft push-out), else the relax pass; template arguments, so that each pass compiles to its own
// loop with only the values it uses.
template <bool useBias, bool normalRows = true, class F>
void solveContact(ContactRows<F>& c, BodyLanes<F>& a, BodyLanes<F>& b, const StepContext& ctx, RowUses uses = {}) {
    using simd::max;
    using simd::select;
    const Vec2T<F> n = c.normal;
    // The rows' Softness (softness.hpp): stiffer against a body that cannot move, the static one.
    // Chosen here from the masses rather than kept in the rows: three fields less to stream through
    // every pass.
    [[maybe_unused]] SoftnessT<F> soft;
    if constexpr (useBias && normalRows) {
        auto pick = [&](float contactValue, float staticValue) {
            return select(a.invMass != F(0.0f), select(b.invMass != F(0.0f), F(contactValue), F(staticValue)), F(staticValue));
        };
        soft = {pick(ctx.contactSoftness.biasRate, ctx.staticSoftness.biasRate),
                pick(ctx.contactSoftness.massScale, ctx.staticSoftness.massScale),
                pick(ctx.contactSoftness.impulseScale, ctx.staticSoftness.impulseScale)};
    }
    F totalNormalImpulse = 0.0f;
    for (int i = 0; i < 2; ++i) {
        ContactPointRows<F>& cp = c.points[i];
        if constexpr (normalRows) {
            const Vec2T<F> rA = cp.anchorA, rB = cp.anchorB;
            const F s = currentSeparation(c, cp, a, b, uses);
            // Speculative (s > 0): bias = s/hs, a rigid row that may close the gap this substep, no more.
            const simd::MaskOf<F> speculative = s > F(0.0f);
            F bias = select(speculative, s * F(ctx.invHs), F(0.0f));
            F massScale = 1.0f, impulseScale = 0.0f;
            if constexpr (useBias) {
                // Soft push-out of the overlap, at most maxBiasVelocity.
                const F push = max(soft.biasRate * simd::min(s + F(ctx.pushSlop), F(0.0f)), F(-ctx.maxBiasVelocity));
                bias = select(speculative, bias, push);
                massScale = select(speculative, massScale, soft.massScale);
                impulseScale = select(speculative, impulseScale, soft.impulseScale);
            }
            const F vn = dot(relativeVelocity(a, b, rA, rB), n);
            F impulse = -cp.normalMass * massScale * (vn + bias) - impulseScale * cp.normalImpulse;
            const F newImpulse = max(cp.normalImpulse + impulse, F(0.0f));
            impulse = newImpulse - cp.normalImpulse;
            cp.normalImpulse = newImpulse;
            if (ctx.hitEvents || uses.elastic) recordPush(c, i, impulse, ctx);
            totalNormalImpulse += newImpulse;
            applyImpulse(c, a, b, rA, rB, impulse * n);
        } else {
            totalNormalImpulse += cp.normalImpulse;
        }
    }

    // A conveyor's surfaces move clockwise around their shapes, which is −tangentSpeed along
    // perp(n): the friction row drives v_rel·t to it.
    const Vec2T<F> t = perp(n);
    for (ContactPointRows<F>& cp : c.points) {
        const Vec2T<F> rA = cp.anchorA, rB = cp.anchorB;
        F vt = dot(relativeVelocity(a, b, rA, rB), t);
        if (uses.conveyor) vt = select(c.tangentSpeed != F(0.0f), vt + c.tangentSpeed, vt);
        const F maxFriction = c.friction * cp.normalImpulse;
        const F newImpulse = simd::clamp(cp.tangentImpulse - cp.tangentMass * vt, -maxFriction, maxFriction);
        const F impulse = newImpulse - cp.tangentImpulse;
        cp.tangentImpulse = newImpulse;
        applyImpulse(c, a, b, rA, rB, impulse * t);
    }
    if (!uses.rolling) return;
    const F maxLambda = c.rollingResistance * totalNormalImpulse;
    const F lambda = c.rollingImpulse;
    c.rollingImpulse = simd::clamp(lambda - c.rollingMass * (b.w - a.w), -maxLambda, maxLambda);
    applyRollingImpulse(c, a, b, c.rollingImpulse - lambda);
}

// The rebound speed of an approach at speed V: Hecker's e V, corrected so that the climb it starts
// reaches e² of the height the fall took in the discrete integrator. Under a steady deceleration a
// along n (gravity: a = g), a symplectic-Euler climb from speed v rises v²/2a − h v/2 and the fall
// that ended at V took V²/2a − h V/2; equal to e² times: v = (a h + √(a²h² + 4e²(V² − a h V)))/2,
// which is V for e = 1 (docs/stress.md). Without such a deceleration (a h ≥ V or a ≤ 0): e V.
template <class F>
F reboundSpeed(F e, F V, F a, float h) {
    using simd::select;
    const F ah = a * F(h);
    const F climb = F(0.5f) * (ah + simd::sqrt(ah * ah + F(4.0f) * e * e * (V * V - ah * V)));
    return select(ah > F(0.0f), select(V > ah, climb, e * V), e * V);
}

// Hecker's bounce, once per step after the substeps: λn += -(v_rel·n − rebound) / K, λn ≥ 0, at
// each point whose approach (v_rel·n before solving) was faster than the restitution threshold and
// that pushed this step (λn,max > 0), for constraints with restitution; the other lanes apply
// nothing. dvA, dvB: each body's velocity change per substep from its forces, whose pull along n
// is the deceleration of the rebound.
template <class F>
void restituteContact(ContactRows<F>& c, BodyLanes<F>& a, BodyLanes<F>& b, Vec2T<F> dvA, Vec2T<F> dvB, const StepContext& ctx) {
    using simd::max;
    using simd::select;
    const simd::MaskOf<F> elastic = c.restitution != F(0.0f);
    const F deceleration = F(-static_cast<float>(ctx.substeps)) * dot(dvB - dvA, c.normal) * F(ctx.invH);
    for (int i = 0; i < 2; ++i) {
        ContactPointRows<F>& cp = c.points[i];
        const simd::MaskOf<F> slow = c.relativeVelocity[i] > F(-ctx.restitutionThreshold);
        const simd::MaskOf<F> pushed = c.maxNormalImpulse[i] != F(0.0f);
        const auto ifBouncing = [&](F value, F otherwise) {
            return select(slow, otherwise, select(pushed, select(elastic, value, otherwise), otherwise));
        };
        const Vec2T<F> rA = cp.anchorA, rB = cp.anchorB;
        const F vn = dot(relativeVelocity(a, b, rA, rB), c.normal);
        const F rebound = reboundSpeed(c.restitution, -c.relativeVelocity[i], deceleration, ctx.h);
        const F newImpulse = max(cp.normalImpulse + -cp.normalMass * (vn - rebound), F(0.0f));
        const F impulse = ifBouncing(newImpulse - cp.normalImpulse, F(0.0f));
        cp.normalImpulse = ifBouncing(newImpulse, cp.normalImpulse);
        c.maxNormalImpulse[i] = ifBouncing(max(c.maxNormalImpulse[i], impulse), c.maxNormalImpulse[i]);
        applyImpulse(c, a, b, rA, rB, impulse * c.normal);
    }
}

// ContactRows<float> is nothing but floats, and ContactRows<F> of an N-lane F is the same fields as
// N floats each, in the same order: field i of lane l is float i·N + l of the rows (row_lanes.hpp).
constexpr std::size_t rowFloats = rowFloatsOf<ContactRows>();

// The one table of the contact rows' fields: where each float of ContactRows<float> comes from,
// whether it goes back into the contact, and which RowUses flag it sets. The gathers read the runs
// it makes (contactRunFields, pointRunFields) and its Solver fields (solverRowFields, gathered by
// gatherOtherFields, contact_solver.cpp), the stores its stored fields (storeContactRows,
// contact_solver_wide.cpp), rowUses its gating fields; checks at compile time below fail the build
// where a field lacks a line or a line lacks what its source needs.
enum class RowSource : unsigned char {
    Run,      // in one of the contact's runs of floats: from Contact::friction, or from a point's anchorA
    Solver,   // from the solver's slots and the contact's flags: its SolverValue
    Derived,  // computed from the others (deriveContactRows)
};
// The value of a Solver field (solverFieldValue, contact_solver.cpp).
enum class SolverValue : unsigned char {
    None,             // not a Solver field
    InverseInertiaA,  // 1/I of body A (SolverBodies::inverseInertias by its solver slot)
    InverseInertiaB,
    TurnsA,           // 1 where A's surface is flat (Contact::turnsA), else 0
    TurnsB,
};
// The test a lane's value passes where it uses the RowUses flag its field gates.
enum class LaneTest : unsigned char { Zero, Nonzero, Positive };
struct ContactRowField {
    std::size_t row;          // offsetof in ContactRows<float> (a point field: point 0's)
    std::size_t floats;       // 1, or 2 for a Vec2
    std::size_t pointStride;  // a point field: how far point 1's is from point 0's; 0 for the contact's
    RowSource source;
    std::size_t contact;  // offsetof in Contact (a point field: in ContactPointState) it is read from
                          // (Run) or stored to; 0 for neither
    bool stored;          // written back into the contact after the step (storeContactRows)
    SolverValue solverValue = SolverValue::None;  // a Solver field's
    bool RowUses::*gates = nullptr;               // the flag a lane sets where its value passes usedWhen (rowUses)
    LaneTest usedWhen = LaneTest::Nonzero;
};

namespace contact_rows {
using R = ContactRows<float>;
using P = ContactPointRows<float>;
using C = Contact;
using S = ContactPointState;
constexpr std::size_t point = sizeof(P), each = sizeof(float);  // the strides of points[i] and of R's arrays [2]
}  // namespace contact_rows

// clang-format off
inline constexpr ContactRowField contactRowFields[] = {
    {offsetof(contact_rows::R, invIA),             1, 0, RowSource::Solver,  0, false, SolverValue::InverseInertiaA},
    {offsetof(contact_rows::R, invIB),             1, 0, RowSource::Solver,  0, false, SolverValue::InverseInertiaB},
    {offsetof(contact_rows::R, normal),            2, 0, RowSource::Run,     offsetof(contact_rows::C, normal), false},
    {offsetof(contact_rows::R, friction),          1, 0, RowSource::Run,     offsetof(contact_rows::C, friction), false},
    {offsetof(contact_rows::R, points[0].anchorA), 2, contact_rows::point, RowSource::Run, offsetof(contact_rows::S, anchorA), false},
    {offsetof(contact_rows::R, points[0].anchorB), 2, contact_rows::point, RowSource::Run, offsetof(contact_rows::S, anchorB), false},
    {offsetof(contact_rows::R, points[0].baseSeparation), 1, contact_rows::point, RowSource::Run, offsetof(contact_rows::S, separation), false},
    {offsetof(contact_rows::R, points[0].normalImpulse),  1, contact_rows::point, RowSource::Run, offsetof(contact_rows::S, normalImpulse), true},
    {offsetof(contact_rows::R, points[0].tangentImpulse), 1, contact_rows::point, RowSource::Run, offsetof(contact_rows::S, tangentImpulse), true},
    {offsetof(contact_rows::R, points[0].normalMass),     1, contact_rows::point, RowSource::Derived, 0, false},
    {offsetof(contact_rows::R, points[0].tangentMass),    1, contact_rows::point, RowSource::Derived, 0, false},
    {offsetof(contact_rows::R, turnsA),            1, 0, RowSource::Solver,  0, false, SolverValue::TurnsA, &RowUses::roundSurface, LaneTest::Zero},
    {offsetof(contact_rows::R, turnsB),            1, 0, RowSource::Solver,  0, false, SolverValue::TurnsB, &RowUses::roundSurface, LaneTest::Zero},
    {offsetof(contact_rows::R, tangentSpeed),      1, 0, RowSource::Run,     offsetof(contact_rows::C, tangentSpeed), false, SolverValue::None, &RowUses::conveyor, LaneTest::Nonzero},
    {offsetof(contact_rows::R, rollingResistance), 1, 0, RowSource::Run,     offsetof(contact_rows::C, rollingResistance), false, SolverValue::None, &RowUses::rolling, LaneTest::Positive},
    {offsetof(contact_rows::R, rollingMass),       1, 0, RowSource::Derived, 0, false},
    {offsetof(contact_rows::R, rollingImpulse),    1, 0, RowSource::Run,     offsetof(contact_rows::C, rollingImpulse), true},
    {offsetof(contact_rows::R, restitution),       1, 0, RowSource::Run,     offsetof(contact_rows::C, restitution), false, SolverValue::None, &RowUses::elastic, LaneTest::Nonzero},
    {offsetof(contact_rows::R, maxNormalImpulse),  1, contact_rows::each, RowSource::Derived, offsetof(contact_rows::S, maxNormalImpulse), true},
    {offsetof(contact_rows::R, relativeVelocity),  1, contact_rows::each, RowSource::Derived, 0, false},
};
// clang-format on

// Every float of ContactRows<float> in exactly one line of contactRowFields.
constexpr bool everyRowFloatOnce() {
    std::size_t named[rowFloats] = {};
    for (const ContactRowField& f : contactRowFields)
        for (std::size_t i = 0; i < (f.pointStride != 0 ? 2 : 1); ++i)
            for (std::size_t k = 0; k < f.floats; ++k) {
                const std::size_t index = (f.row + i * f.pointStride) / sizeof(float) + k;
                if (index >= rowFloats) return false;
                ++named[index];
            }
    for (std::size_t count : named)
        if (count != 1) return false;
    return true;
}
static_assert(everyRowFloatOnce(), "contactRowFields must name every field of ContactRows once: give a new field its line");

// A contact's runs of floats, each read four or eight contacts at a time and turned into lanes:
// the head (from Contact::friction) and each point's (from ContactPointState::anchorA), seven
// floats each (the eighth, the point count or the largest push, comes along unused). Run float f
// goes to the row field at byte offset (the run's array)[f]: in ContactRows<float> for the head,
// in ContactPointRows<float> for a point's. Every float of a run must be a Run field of the table.
template <bool points>
constexpr std::array<std::size_t, 7> runFields() {
    std::array<std::size_t, 7> fields{};
    std::array<int, 7> named{};
    const std::size_t start = points ? offsetof(Contact, points) + offsetof(ContactPointState, anchorA) : offsetof(Contact, friction);
    if (start + 8 * sizeof(float) > (points ? offsetof(Contact, points) + sizeof(ContactPointState) : sizeof(Contact)))
        throw "a run of eight floats must lie inside its contact or point";
    for (const ContactRowField& f : contactRowFields) {
        if (f.source != RowSource::Run || (f.pointStride != 0) != points) continue;
        const std::size_t at = points ? offsetof(Contact, points) + f.contact : f.contact;
        for (std::size_t k = 0; k < f.floats; ++k) {
            const std::size_t run = (at - start) / sizeof(float) + k;
            if (at < start || run >= 7) throw "a Run field outside its run of seven floats";
            fields[run] = (points ? f.row - offsetof(ContactRows<float>, points) : f.row) + k * sizeof(float);
            ++named[run];
        }
    }
    for (int count : named)
        if (count != 1) throw "every float of a run must be one Run field";
    return fields;
}
inline constexpr std::array<std::size_t, 7> contactRunFields = runFields<false>();
inline constexpr std::array<std::size_t, 7> pointRunFields = runFields<true>();

// Each Solver field one float of the contact's with its SolverValue, and no other field with one.
constexpr bool everySolverFieldValued() {
    for (const ContactRowField& f : contactRowFields) {
        const bool solver = f.source == RowSource::Solver;
        if (solver != (f.solverValue != SolverValue::None) || (solver && (f.floats != 1 || f.pointStride != 0))) return false;
    }
    return true;
}
static_assert(everySolverFieldValued(), "a Solver field is one float of the contact's and names its SolverValue; no other field names one");

// Every flag of RowUses (bools only) gated by a field of the contact's, one float.
constexpr bool everyUseGated() {
    RowUses ungated{};
    for (const ContactRowField& f : contactRowFields) {
        if (f.gates == nullptr) continue;
        if (f.floats != 1 || f.pointStride != 0) return false;
        ungated.*f.gates = false;
    }
    for (bool flag : std::bit_cast<std::array<bool, sizeof(RowUses)>>(ungated))
        if (flag) return false;
    return true;
}
static_assert(everyUseGated(), "every RowUses flag must be gated by a field of contactRowFields (a contact's float)");

// The lines of contactRowFields that `keep`, in order of the table.
constexpr std::size_t rowFieldCount(bool (*keep)(const ContactRowField&)) {
    std::size_t count = 0;
    for (const ContactRowField& f : contactRowFields) count += keep(f) ? 1 : 0;
    return count;
}
template <bool (*keep)(const ContactRowField&)>
inline constexpr auto rowFieldsWhere = [] {
    std::array<ContactRowField, rowFieldCount(keep)> kept{};
    std::size_t n = 0;
    for (const ContactRowField& f : contactRowFields)
        if (keep(f)) kept[n++] = f;
    return kept;
}();
constexpr bool isStored(const ContactRowField& f) { return f.stored; }
constexpr bool isSolver(const ContactRowField& f) { return f.source == RowSource::Solver; }
constexpr bool isGating(const ContactRowField& f) { return f.gates != nullptr; }
inline constexpr auto storedRowFields = rowFieldsWhere<isStored>;  // stored back into the contact
inline constexpr auto solverRowFields = rowFieldsWhere<isSolver>;  // gathered by gatherOtherFields
inline constexpr auto gatingRowFields = rowFieldsWhere<isGating>;  // read by rowUses

// fn(field) on each line of `fields` (one of the arrays above), unrolled: field is a
// std::integral_constant, and decltype(field)::value the line as a constant expression.
template <const auto& fields, class Fn>
[[gnu::always_inline]] inline void forEachRowField(Fn&& fn) {
    [&]<std::size_t... k>(std::index_sequence<k...>) {
        (fn(std::integral_constant<ContactRowField, fields[k]>{}), ...);
    }(std::make_index_sequence<fields.size()>());
}

// The uses of a block's `used` lanes, from its rows (`lanes` wide): each flag set where a lane's
// value of a field that gates it passes the field's test.
inline RowUses rowUses(const float* rows, int lanes, int used) {
    RowUses uses{};
    forEachRowField<gatingRowFields>([&](auto field) { uses.*decltype(field)::value.gates = false; });
    forEachRowField<gatingRowFields>([&](auto field) {
        constexpr LaneTest test = decltype(field)::value.usedWhen;
        bool& flag = uses.*decltype(field)::value.gates;
        if (flag) return;  // set by an earlier field
        const float* values = rows + decltype(field)::value.row / sizeof(float) * static_cast<std::size_t>(lanes);
        for (int lane = 0; lane < used; ++lane) {
            const float value = values[lane];
            if (test == LaneTest::Zero ? value == 0.0f : test == LaneTest::Nonzero ? value != 0.0f : value > 0.0f) {
                flag = true;
                return;
            }
        }
    });
    return uses;
}

// N constraints of one graph colour as the lanes of one row set (LaneBlock, lane_block.hpp): N = 4
// (simd::Float4) or, for CPUs with AVX2, 8 (Float8, contact_solver_avx2.cpp). The rows are
// ContactRows<F> of an N-lane F; the head is the lanes' RowUses (rowUses), the fields after the
// points they read; item[l] is lane l's contact, -1 for an empty lane (layOutBlocks).
template <std::size_t N>
using ContactBlock = LaneBlock<N, rowFloats, RowUses>;

// A block's rows as ContactRows<F>, F N lanes wide.
template <class F, std::size_t N>
ContactRows<F>& contactRowsOf(ContactBlock<N>& block) {
    static_assert(sizeof(ContactRows<F>) == sizeof block.rows, "F must be N lanes wide");
    return block.rows.template as<ContactRows<F>>();
}
// What a pass over blocks of flat, plain contacts reads: whole cache lines, 13 of them.
static_assert(offsetof(ContactBlock<8>, rows) + offsetof(ContactRows<float>, turnsA) * 8 == 13 * 64);

// A run of seven floats of N contacts turned into lanes of F: transpose(runs, fields) sets
// fields[f] to float f of each lane's run (runs[lane]). Float4's is here; Float8's is in the AVX2
// file (contact_solver_avx2.cpp).
template <class F>
struct ContactRuns;

template <>
struct ContactRuns<simd::Float4> {
    static void transpose(const float* const (&runs)[4], simd::Float4 (&fields)[7]) {
        using simd::Float4;
        Float4 head[4], tail[4];  // floats 0-3 and 4-7 of the runs
        for (int k = 0; k < 4; ++k) {
            head[k] = Float4::loadBytes(runs[k]);
            tail[k] = Float4::loadBytes(reinterpret_cast<const char*>(runs[k]) + 4 * sizeof(float));
        }
        simd::transpose(head);
        simd::transpose(tail);
        for (int f = 0; f < 7; ++f) fields[f] = f < 4 ? head[f] : tail[f - 4];
    }
};

// A block's contact values from its lanes' runs (contactRunFields, pointRunFields): head[l] is
// lane l's contact from its friction, points[i][l] its point i from the anchor A; a point's fields
// are zeros where present[i] is 0, as gatherRows writes them (contact_solver.cpp).
template <class F, std::size_t N>
[[gnu::always_inline]] inline void gatherContactRuns(ContactBlock<N>& block, const float* const (&head)[N], const float* const (&points)[2][N],
                       const float (&present)[2][N]) {
    auto store = [&](std::size_t offset, F value) { value.store(block.rows.data + offset / sizeof(float) * N); };
    F fields[7];
    ContactRuns<F>::transpose(head, fields);
    for (std::size_t f = 0; f < 7; ++f) store(contactRunFields[f], fields[f]);
    for (std::size_t i = 0; i < 2; ++i) {
        ContactRuns<F>::transpose(points[i], fields);
        const auto point = F::load(present[i]) > F(0.0f);
        for (std::size_t f = 0; f < 7; ++f)
            store(offsetof(ContactRows<float>, points) + i * sizeof(ContactPointRows<float>) + pointRunFields[f],
                  simd::select(point, fields[f], F(0.0f)));
    }
}

// One pass (RowPass) of the rows on lanes of F, handed to `loop(rows, elasticOnly)`:
// rows(c, a, b, slotsA, slotsB, uses) runs it on one row set whose bodies are in solver slots
// slotsA, slotsB; elasticOnly (std::true_type for restitution) says only rows with an elastic lane
// need it. The one switch of the passes, for blocks of every width and for single constraints.
template <class F, class Loop>
void forPass(RowPass pass, const StepContext& ctx, const SubstepForces* forces, Loop loop) {
    using Lanes = BodyLanes<F>;
    switch (pass) {
        case RowPass::WarmStart:
            return loop([](ContactRows<F>& c, Lanes& a, Lanes& b, const auto&, const auto&, RowUses uses) { warmStartContact(c, a, b, uses); },
                        std::false_type{});
        case RowPass::Solve:
            return loop([&ctx](ContactRows<F>& c, Lanes& a, Lanes& b, const auto&, const auto&,
                               RowUses uses) { solveContact<true>(c, a, b, ctx, uses); },
                        std::false_type{});
        case RowPass::Relax:
            return loop([&ctx](ContactRows<F>& c, Lanes& a, Lanes& b, const auto&, const auto&,
                               RowUses uses) { solveContact<false>(c, a, b, ctx, uses); },
                        std::false_type{});
        case RowPass::Restitution:
            return loop(
                [&ctx, forces](ContactRows<F>& c, Lanes& a, Lanes& b, const auto& slotsA, const auto& slotsB, RowUses) {
                    restituteContact(c, a, b, LaneBodies<F>::velocityChange(forces, slotsA), LaneBodies<F>::velocityChange(forces, slotsB), ctx);
                },
                std::true_type{});
    }
}

// deriveContactRows on a block's N lanes of F at once, its bodies' velocities without contacts in
// freeVelocities (by solver slot); present[i]: 1 where a lane's point i is a manifold point.
template <class F, std::size_t N>
void deriveContactBlock(ContactBlock<N>& block, const BodyState* freeVelocities, const float (&present)[2][N], const StepContext& ctx) {
    const BodyLanes<F> a = LaneBodies<F>::gather(freeVelocities, block.bodyA);
    const BodyLanes<F> b = LaneBodies<F>::gather(freeVelocities, block.bodyB);
    const F points[2] = {F::load(present[0]), F::load(present[1])};
    deriveContactRows(contactRowsOf<F>(block), a, b, points, ctx);
}

// One pass over the blocks [begin, end) of N lanes of F (forBlocks, body_lanes.hpp).
template <class F, std::size_t N>
void contactBlockRows(ContactBlock<N>* blocks, int begin, int end, BodyState* states, const SubstepForces* forces, const StepContext& ctx,
                      RowPass pass) {
    forPass<F>(pass, ctx, forces, [&](auto rows, auto elasticOnly) {
        forBlocks<F, bodiesAhead>(
            blocks, begin, end, states,
            [&](ContactBlock<N>& block, BodyLanes<F>& a, BodyLanes<F>& b) {
                rows(contactRowsOf<F>(block), a, b, block.bodyA, block.bodyB, block.head);
            },
            [](const ContactBlock<N>& block) { return !decltype(elasticOnly)::value || block.head.elastic; });
    });
}

// The lane width of a new world's contact blocks: 8 where contactLanes8Available() (this build
// has the AVX2 rows and the CPU runs AVX2), else 4; the environment's PERPDOT_CONTACT_LANES=4 picks 4.
bool contactLanes8Available();
int chooseContactLanes();

// The eight-lane rows (src/core/solver/avx2/contact_solver_avx2.cpp, built where PERPDOT_AVX2 is defined):
// contactRows8 is contactBlockRows on Float8 lanes;
// deriveContactRows8 is deriveContactBlock on them; gatherContactRows8 is gatherContactRuns.
void deriveContactRows8(ContactBlock<8>& block, const BodyState* freeVelocities, const float (&present)[2][8], const StepContext& ctx);
void gatherContactRows8(ContactBlock<8>& block, const float* const (&head)[8], const float* const (&points)[2][8], const float (&present)[2][8]);
void contactRows8(ContactBlock<8>* blocks, int begin, int end, BodyState* states, const SubstepForces* forces, const StepContext& ctx,
                  RowPass pass);

}  // namespace perpdot
