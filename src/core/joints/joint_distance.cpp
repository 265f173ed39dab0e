// Distance joint: one row along the line between the anchors, n = d/|d|, with Hecker's
// effective mass 1/mA + 1/mB + perpDot(rA,n)²/IA + perpDot(rB,n)²/IB. Rigid (a rod of `length`)
// when hertz = 0; otherwise a spring, kept between minLength and maxLength by one-sided rows. The
// rows are written once over a lane type F, for one joint and for blocks of four
// (joint_solver_wide.hpp).
#include <cmath>
#include <cstddef>

#include "core/bodies/body_store.hpp"
#include "core/joints/joint_distance.hpp"
#include "core/joints/joint_solver_wide.hpp"
#include "core/joints/joint_type.hpp"

namespace perpdot {

namespace {

// The distance joint's rows: the row along d/|d|, rigid or a spring by lane, then where the joint
// is a spring (its optional rows, gathered and solved where optionalRows) the min and max rows.
struct DistanceRowSet {
    template <class F>
    struct Rows {
        Vec2T<F> anchorA, anchorB;  // rA, rB at step start
        Vec2T<F> deltaCenter;       // cB − cA at step start
        F impulse{}, lowerImpulse{}, upperImpulse{};  // λ of the row, of the min and max rows
        F restLength{};             // `length`
        F axialMass{};              // along the axis at step start
        Vec2T<F> axis;              // d/|d| at step start (for store: the reaction's direction)
        SoftnessT<F> spring;        // the spring's ({0, 1, 0} where hertz = 0)
        // Gathered where optionalRows: last, away from what every block reads.
        F springy{};                // 1 where hertz > 0, else 0
        F minLength{}, maxLength{};
    };

    static bool optionalRows(const PreparedJoint& j) { return j.data.as<DistanceJoint>().hertz > 0.0f; }
    static bool usesRotation(bool) { return false; }

    template <std::size_t lanes>
    static void gather(const PreparedJoint& j, RowLane<lanes> out, bool optionalRows) {
        using R = Rows<float>;
        const DistanceJoint& s = j.data.as<DistanceJoint>();
        gatherFrame<R>(j, out);
        out.set(offsetof(R, impulse), s.impulse);
        out.set(offsetof(R, lowerImpulse), s.lowerImpulse);
        out.set(offsetof(R, upperImpulse), s.upperImpulse);
        out.set(offsetof(R, restLength), s.length);
        out.set(offsetof(R, axialMass), s.axialMass);
        out.set(offsetof(R, axis), s.axis);
        out.set(offsetof(R, spring), s.spring);
        if (!optionalRows) return;
        out.set(offsetof(R, springy), s.hertz > 0.0f ? 1.0f : 0.0f);
        out.set(offsetof(R, minLength), s.minLength);
        out.set(offsetof(R, maxLength), s.maxLength);
    }

    // Re-apply last step's impulses (the row's, the min row's, the max row's) along d/|d| now.
    template <class F>
    static void warmStart(const Rows<F>& r, JointPairT<F>& p) {
        const JointFrameT<F> f = currentFrame(p, r.anchorA, r.anchorB, r.deltaCenter);
        applyRow(p, linearRow<F>(f.rA, f.rB, normalize(f.d)), r.impulse + r.lowerImpulse - r.upperImpulse);
    }

    // One pass on |d| now: the row holds it at `length` (rigid, or the spring's softness); a spring
    // then keeps it ≥ minLength and ≤ maxLength.
    template <class F>
    static void solve(Rows<F>& r, JointPairT<F>& p, const StepContext& ctx, bool useBias, bool optionalRows) {
        const JointFrameT<F> f = currentFrame(p, r.anchorA, r.anchorB, r.deltaCenter);
        const F length = simd::sqrt(dot(f.d, f.d));
        const RowT<F> row = linearRow<F>(f.rA, f.rB, normalize(f.d));
        const Softness rigid = rigidSoftness(ctx, useBias);
        if (!optionalRows) {
            solveRow(p, row, r.axialMass, length - r.restLength, everyLane<F>(rigid), r.impulse);
            return;
        }
        const simd::MaskOf<F> springy = r.springy != F(0.0f);
        solveRow(p, row, r.axialMass, length - r.restLength, selectSoftness<F>(springy, r.spring, rigid), r.impulse);
        solveWhere(
            springy, p,
            [&] {
                solveLimitRow(p, row, r.axialMass, length - r.minLength, ctx, useBias, r.lowerImpulse);
                solveLimitRow(p, negated(row), r.axialMass, r.maxLength - length, ctx, useBias, r.upperImpulse);
            },
            r.lowerImpulse, r.upperImpulse);
    }

    // The impulses, and what prepareDistance wrote (snapshots carry it).
    template <std::size_t lanes>
    static void store(RowLane<lanes, const float> rows, JointData& data, bool) {
        using R = Rows<float>;
        DistanceJoint& s = data.as<DistanceJoint>();
        s.axis = rows.vec(offsetof(R, axis));
        s.axialMass = rows[offsetof(R, axialMass)];
        s.spring = rows.softness(offsetof(R, spring));
        s.impulse = rows[offsetof(R, impulse)];
        s.lowerImpulse = rows[offsetof(R, lowerImpulse)];
        s.upperImpulse = rows[offsetof(R, upperImpulse)];
    }
};

constexpr JointLaneStages distanceLanes = jointLaneStages<DistanceRowSet>();

}  // namespace

Joint& makeJoint(World::Impl& w, const DistanceJointDef& def) {
    requireFinite(std::isfinite(def.length) && std::isfinite(def.minLength), "DistanceJointDef lengths");
    requireFinite(std::isfinite(def.hertz) && std::isfinite(def.dampingRatio), "DistanceJointDef spring");
    if (!(def.length > 0.0f)) throw Error("DistanceJointDef.length must be > 0");
    if (def.minLength < 0.0f || def.minLength > def.maxLength) throw Error("DistanceJointDef: need 0 <= minLength <= maxLength");
    if (def.hertz < 0.0f || def.dampingRatio < 0.0f) throw Error("DistanceJointDef: hertz and dampingRatio must be >= 0");
    Joint& j = addJoint(w, JointType::Distance, def.bodyA, def.bodyB, def.localAnchorA, def.localAnchorB, 0.0f,
                        def.collideConnected, def.userData);
    DistanceJoint& s = j.data.emplace<DistanceJoint>();
    s.length = def.length;
    s.minLength = def.minLength;
    s.maxLength = def.maxLength;
    s.hertz = def.hertz;
    s.dampingRatio = def.dampingRatio;
    return j;
}

void prepareDistance(PreparedJoint& j, const StepContext& ctx, const Body&, const Body&) {
    DistanceJoint& s = j.data.as<DistanceJoint>();
    s.axis = normalize(j.deltaCenter + j.anchorB - j.anchorA);
    s.axialMass = effectiveMass(j.mass, linearRow(j.anchorA, j.anchorB, s.axis));
    s.spring = makeSoftness(s.hertz, s.dampingRatio, ctx.hs);
    if (!ctx.enableWarmStarting) s.impulse = s.lowerImpulse = s.upperImpulse = 0.0f;
}

JointReaction reactionDistance(const JointData& data) {
    const DistanceJoint& s = data.as<DistanceJoint>();
    return {(s.impulse + s.lowerImpulse - s.upperImpulse) * s.axis, 0.0f};
}

template JointId World::createJoint(const DistanceJointDef&);
extern const JointKind distanceKind = jointKind<DistanceJoint>(
    {prepareDistance, warmStartJoint<DistanceRowSet>, solveJoint<DistanceRowSet>, reactionDistance, &distanceLanes});

}  // namespace perpdot
