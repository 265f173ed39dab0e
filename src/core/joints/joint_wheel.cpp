// Wheel joint: B's anchor (the axle) moves along a suspension axis fixed in A and B turns freely.
// One rigid row holds the axle on the line (along perp(axis)), a spring row acts along the axis
// (rigid when hertz = 0), and an optional motor row drives ωB − ωA. The rows are written once over
// a lane type F, for one joint and for blocks of four (joint_solver_wide.hpp).
#include <cmath>
#include <cstddef>

#include "core/bodies/body_store.hpp"
#include "core/joints/joint_solver_wide.hpp"
#include "core/joints/joint_type.hpp"
#include "core/joints/joint_wheel.hpp"

namespace perpdot {

namespace {

// The wheel joint's rows: the motor on ωB − ωA (gathered and solved where optionalRows), the
// suspension along the axis (a spring or rigid by lane), the rigid row across it.
struct WheelRowSet {
    template <class F>
    struct Rows {
        Vec2T<F> anchorA, anchorB;  // rA, rB at step start
        Vec2T<F> deltaCenter;       // cB − cA at step start
        Vec2T<F> axisA;             // the axis in the world at step start
        F perpImpulse{}, springImpulse{}, motorImpulse{};  // λ across, along, and of the motor
        F axialMass{};              // of the row along the axis
        F springy{};                // 1 where hertz > 0, else 0
        SoftnessT<F> spring;        // the suspension's
        F motorMass{};              // 1 / (1/IA + 1/IB)
        // The motor's constants, gathered where optionalRows.
        F motorSpeed{}, maxMotorTorque{};
        F motor{};                  // 1 where enabled, else 0
    };

    static bool optionalRows(const PreparedJoint& j) { return j.data.as<WheelJoint>().enableMotor; }
    static bool usesRotation(bool) { return false; }

    template <std::size_t lanes>
    static void gather(const PreparedJoint& j, RowLane<lanes> out, bool optionalRows) {
        using R = Rows<float>;
        const WheelJoint& s = j.data.as<WheelJoint>();
        gatherFrame<R>(j, out);
        out.set(offsetof(R, axisA), s.axisA);
        out.set(offsetof(R, perpImpulse), s.perpImpulse);
        out.set(offsetof(R, springImpulse), s.springImpulse);
        out.set(offsetof(R, motorImpulse), s.motorImpulse);
        out.set(offsetof(R, axialMass), s.axialMass);
        out.set(offsetof(R, springy), s.hertz > 0.0f ? 1.0f : 0.0f);
        out.set(offsetof(R, spring), s.spring);
        out.set(offsetof(R, motorMass), s.motorMass);
        if (!optionalRows) return;
        out.set(offsetof(R, motorSpeed), s.motorSpeed);
        out.set(offsetof(R, maxMotorTorque), s.maxMotorTorque);
        out.set(offsetof(R, motor), s.enableMotor ? 1.0f : 0.0f);
    }

    // Re-apply last step's impulses: the suspension's along the axis, the row's across it, the motor's.
    template <class F>
    static void warmStart(const Rows<F>& r, JointPairT<F>& p) {
        const AxisRowsT<F> rows = axisRows(p, r.anchorA, r.anchorB, r.deltaCenter, r.axisA);
        applyRow(p, rows.axial, r.springImpulse);
        applyRow(p, rows.perpendicular, r.perpImpulse);
        applyRow(p, angularRowOf<F>(), r.motorImpulse);
    }

    // One pass: the motor drives ωB − ωA to motorSpeed (|λ| ≤ maxMotorTorque·hs); the suspension
    // holds the translation at 0, then the row across the axis its offset, each on the rows as the
    // velocities before it left them.
    template <class F>
    static void solve(Rows<F>& r, JointPairT<F>& p, const StepContext& ctx, bool useBias, bool optionalRows) {
        if (optionalRows)
            solveWhere(
                r.motor != F(0.0f), p,
                [&] { solveMotorRow(p, angularRowOf<F>(), r.motorMass, r.motorSpeed, r.maxMotorTorque * F(ctx.hs), r.motorImpulse); },
                r.motorImpulse);
        const Softness rigid = rigidSoftness(ctx, useBias);
        AxisRowsT<F> rows = axisRows(p, r.anchorA, r.anchorB, r.deltaCenter, r.axisA);
        const SoftnessT<F> suspension = selectSoftness<F>(r.springy != F(0.0f), r.spring, rigid);
        solveRow(p, rows.axial, r.axialMass, rows.translation, suspension, r.springImpulse);
        rows = axisRows(p, r.anchorA, r.anchorB, r.deltaCenter, r.axisA);
        solveRow(p, rows.perpendicular, effectiveMass(p.m, rows.perpendicular), rows.offset, everyLane<F>(rigid), r.perpImpulse);
    }

    // The impulses, and what prepareWheel wrote (snapshots carry it).
    template <std::size_t lanes>
    static void store(RowLane<lanes, const float> rows, JointData& data, bool) {
        using R = Rows<float>;
        WheelJoint& s = data.as<WheelJoint>();
        s.axisA = rows.vec(offsetof(R, axisA));
        s.axialMass = rows[offsetof(R, axialMass)];
        s.motorMass = rows[offsetof(R, motorMass)];
        s.spring = rows.softness(offsetof(R, spring));
        s.perpImpulse = rows[offsetof(R, perpImpulse)];
        s.springImpulse = rows[offsetof(R, springImpulse)];
        s.motorImpulse = rows[offsetof(R, motorImpulse)];
    }
};

constexpr JointLaneStages wheelLanes = jointLaneStages<WheelRowSet>();

}  // namespace

Joint& makeJoint(World::Impl& w, const WheelJointDef& def) {
    requireFinite(isFinite(def.localAxisA), "WheelJointDef.localAxisA");
    requireFinite(std::isfinite(def.hertz) && std::isfinite(def.dampingRatio), "WheelJointDef spring");
    requireFinite(std::isfinite(def.motorSpeed) && std::isfinite(def.maxMotorTorque), "WheelJointDef motor");
    if (lengthSquared(def.localAxisA) == 0.0f) throw Error("WheelJointDef.localAxisA must not be zero");
    if (def.hertz < 0.0f || def.dampingRatio < 0.0f) throw Error("WheelJointDef: hertz and dampingRatio must be >= 0");
    if (def.maxMotorTorque < 0.0f) throw Error("WheelJointDef.maxMotorTorque must be >= 0");
    Joint& j = addJoint(w, JointType::Wheel, def.bodyA, def.bodyB, def.localAnchorA, def.localAnchorB, 0.0f,
                        def.collideConnected, def.userData);
    WheelJoint& s = j.data.emplace<WheelJoint>();
    s.localAxisA = normalize(def.localAxisA);
    s.hertz = def.hertz;
    s.dampingRatio = def.dampingRatio;
    s.enableMotor = def.enableMotor;
    s.motorSpeed = def.motorSpeed;
    s.maxMotorTorque = def.maxMotorTorque;
    return j;
}

void prepareWheel(PreparedJoint& j, const StepContext& ctx, const Body& a, const Body&) {
    const Rot qA = a.xf.q;
    WheelJoint& s = j.data.as<WheelJoint>();
    s.axisA = rotate(qA, s.localAxisA);
    s.axialMass = axialMass(j, s.axisA);
    s.motorMass = effectiveMass(j.mass, angularRow);
    s.spring = makeSoftness(s.hertz, s.dampingRatio, ctx.hs);
    if (!ctx.enableWarmStarting) s.perpImpulse = s.springImpulse = s.motorImpulse = 0.0f;
}

JointReaction reactionWheel(const JointData& data) {
    const WheelJoint& s = data.as<WheelJoint>();
    return {s.springImpulse * s.axisA + s.perpImpulse * perp(s.axisA), s.motorImpulse};
}

template JointId World::createJoint(const WheelJointDef&);
extern const JointKind wheelKind = jointKind<WheelJoint, &WheelJoint::motorSpeed>(
    {prepareWheel, warmStartJoint<WheelRowSet>, solveJoint<WheelRowSet>, reactionWheel, &wheelLanes});

}  // namespace perpdot
