// Prismatic joint: B slides along an axis fixed in A. A block of two rows holds the anchor on
// the line (row along perp(axis)) and the relative angle; along the axis there is an optional
// motor row and two one-sided limit rows. The axis rows use A's arm to B's anchor, rA + d. The rows
// are written once over a lane type F, for one joint and for blocks of four (joint_solver_wide.hpp).
#include <cmath>
#include <cstddef>

#include "core/bodies/body_store.hpp"
#include "core/joints/joint_prismatic.hpp"
#include "core/joints/joint_solver_wide.hpp"
#include "core/joints/joint_type.hpp"

namespace perpdot {

namespace {

// The prismatic joint's rows: along the axis an optional motor and two limits (gathered and solved
// where optionalRows), then the perpendicular and angle rows as one 2x2 block.
struct PrismaticRowSet {
    template <class F>
    struct Rows {
        Vec2T<F> anchorA, anchorB;  // rA, rB at step start
        Vec2T<F> deltaCenter;       // cB − cA at step start
        Vec2T<F> axisA;             // the axis in the world at step start
        Vec2T<F> impulse;           // λ of the (perpendicular, angle) rows
        F motorImpulse{}, lowerImpulse{}, upperImpulse{};  // λ of the axis rows
        F deltaAngle{};             // θB − θA − θref at step start
        F axialMass{};              // of the row along the axis
        MotorLimitsT<F> axial;      // motor force, limits: gathered where optionalRows
    };

    static bool optionalRows(const PreparedJoint& j) {
        const PrismaticJoint& s = j.data.as<PrismaticJoint>();
        return s.enableMotor || s.enableLimit;
    }
    static bool usesRotation(bool) { return true; }

    template <std::size_t lanes>
    static void gather(const PreparedJoint& j, RowLane<lanes> out, bool optionalRows) {
        using R = Rows<float>;
        const PrismaticJoint& s = j.data.as<PrismaticJoint>();
        gatherFrame<R>(j, out);
        out.set(offsetof(R, axisA), s.axisA);
        out.set(offsetof(R, impulse), s.impulse);
        out.set(offsetof(R, motorImpulse), s.motorImpulse);
        out.set(offsetof(R, lowerImpulse), s.lowerImpulse);
        out.set(offsetof(R, upperImpulse), s.upperImpulse);
        out.set(offsetof(R, deltaAngle), j.deltaAngle);
        out.set(offsetof(R, axialMass), s.axialMass);
        if (!optionalRows) return;
        gatherMotorLimits(out, offsetof(R, axial),
                          {s.motorSpeed, s.maxMotorForce, s.lower, s.upper, s.enableMotor ? 1.0f : 0.0f, s.enableLimit ? 1.0f : 0.0f});
    }

    // Re-apply last step's impulses: motor + lower − upper along the axis, then the block's.
    template <class F>
    static void warmStart(const Rows<F>& r, JointPairT<F>& p) {
        const AxisRowsT<F> rows = axisRows(p, r.anchorA, r.anchorB, r.deltaCenter, r.axisA);
        applyRow(p, rows.axial, r.motorImpulse + r.lowerImpulse - r.upperImpulse);
        applyRow(p, rows.perpendicular, r.impulse.x);
        applyRow(p, angularRowOf<F>(), r.impulse.y);
    }

    // One pass: the motor and the limits on the translation along the axis; then the
    // perpendicular and angle rows (θ = (θB − θA − θref)₀ + p.rotation) as one block.
    template <class F>
    static void solve(Rows<F>& r, JointPairT<F>& p, const StepContext& ctx, bool useBias, bool optionalRows) {
        const AxisRowsT<F> rows = axisRows(p, r.anchorA, r.anchorB, r.deltaCenter, r.axisA);
        if (optionalRows)
            solveMotorAndLimits(p, rows.axial, r.axialMass, rows.translation, r.axial, ctx, useBias, r.motorImpulse, r.lowerImpulse,
                                r.upperImpulse);
        solveRowPair(p, rows.perpendicular, angularRowOf<F>(), Vec2T<F>{rows.offset, r.deltaAngle + p.rotation},
                     rigidSoftness(ctx, useBias), r.impulse);
    }

    // The impulses, and what preparePrismatic wrote (snapshots carry it).
    template <std::size_t lanes>
    static void store(RowLane<lanes, const float> rows, JointData& data, bool optionalRows) {
        using R = Rows<float>;
        PrismaticJoint& s = data.as<PrismaticJoint>();
        s.axisA = rows.vec(offsetof(R, axisA));
        s.axialMass = rows[offsetof(R, axialMass)];
        s.impulse = rows.vec(offsetof(R, impulse));
        if (!optionalRows) return;  // without motor or limit in a lane, their λ stay as they were
        s.motorImpulse = rows[offsetof(R, motorImpulse)];
        s.lowerImpulse = rows[offsetof(R, lowerImpulse)];
        s.upperImpulse = rows[offsetof(R, upperImpulse)];
    }
};

constexpr JointLaneStages prismaticLanes = jointLaneStages<PrismaticRowSet>();

}  // namespace

Joint& makeJoint(World::Impl& w, const PrismaticJointDef& def) {
    requireFinite(isFinite(def.localAxisA), "PrismaticJointDef.localAxisA");
    requireFinite(std::isfinite(def.lower) && std::isfinite(def.upper), "PrismaticJointDef limits");
    requireFinite(std::isfinite(def.motorSpeed) && std::isfinite(def.maxMotorForce), "PrismaticJointDef motor");
    if (lengthSquared(def.localAxisA) == 0.0f) throw Error("PrismaticJointDef.localAxisA must not be zero");
    if (def.lower > def.upper) throw Error("PrismaticJointDef: lower must be <= upper");
    if (def.maxMotorForce < 0.0f) throw Error("PrismaticJointDef.maxMotorForce must be >= 0");
    Joint& j = addJoint(w, JointType::Prismatic, def.bodyA, def.bodyB, def.localAnchorA, def.localAnchorB,
                        def.referenceAngle, def.collideConnected, def.userData);
    PrismaticJoint& s = j.data.emplace<PrismaticJoint>();
    s.localAxisA = normalize(def.localAxisA);
    s.enableLimit = def.enableLimit;
    s.lower = def.lower;
    s.upper = def.upper;
    s.enableMotor = def.enableMotor;
    s.motorSpeed = def.motorSpeed;
    s.maxMotorForce = def.maxMotorForce;
    return j;
}

Vec2 prismaticLocalAxis(const Joint& prismatic) { return prismatic.data.as<PrismaticJoint>().localAxisA; }

void preparePrismatic(PreparedJoint& j, const StepContext& ctx, const Body& a, const Body&) {
    const Rot qA = a.xf.q;
    PrismaticJoint& s = j.data.as<PrismaticJoint>();
    s.axisA = rotate(qA, s.localAxisA);
    s.axialMass = axialMass(j, s.axisA);
    if (!ctx.enableWarmStarting) {
        s.impulse = {};
        s.motorImpulse = s.lowerImpulse = s.upperImpulse = 0.0f;
    }
}

void solvePrismaticMotor(PreparedJoint& j, JointPair& p, const StepContext& ctx) {
    PrismaticJoint& s = j.data.as<PrismaticJoint>();
    if (!s.enableMotor) return;
    const AxisRowsT<float> rows = axisRows(p, j.anchorA, j.anchorB, j.deltaCenter, s.axisA);
    solveMotorRow(p, rows.axial, s.axialMass, s.motorSpeed, s.maxMotorForce * ctx.hs, s.motorImpulse);
}
JointReaction reactionPrismatic(const JointData& data) {
    const PrismaticJoint& s = data.as<PrismaticJoint>();
    return {(s.motorImpulse + s.lowerImpulse - s.upperImpulse) * s.axisA + s.impulse.x * perp(s.axisA), s.impulse.y};
}

template JointId World::createJoint(const PrismaticJointDef&);
extern const JointKind prismaticKind = jointKind<PrismaticJoint, &PrismaticJoint::motorSpeed>(
    {preparePrismatic, warmStartJoint<PrismaticRowSet>, solveJoint<PrismaticRowSet>, reactionPrismatic, &prismaticLanes});

}  // namespace perpdot
