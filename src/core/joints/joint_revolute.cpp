// Revolute joint: B's anchor held on A's by two point rows (the 2x2 K of joint_rows.hpp), plus on
// the angle θB − θA − θref an optional motor row and two one-sided limit rows, each with effective
// mass 1/(1/IA + 1/IB); all written once over a lane type F, for one joint and for blocks of four
// (joint_solver_wide.hpp).
#include <cmath>
#include <cstddef>

#include "core/bodies/body_store.hpp"
#include "core/joints/joint_revolute.hpp"
#include "core/joints/joint_solver_wide.hpp"
#include "core/joints/joint_type.hpp"

namespace perpdot {

namespace {

// The revolute joint's rows; a block whose lanes have neither motor nor limit gathers and solves
// the point rows alone (optionalRows false).
struct RevoluteRowSet {
    template <class F>
    struct Rows {
        Vec2T<F> anchorA, anchorB;  // rA, rB at step start
        Vec2T<F> deltaCenter;       // cB − cA at step start
        Vec2T<F> linearImpulse;     // λ of the point rows
        F motorImpulse{}, lowerImpulse{}, upperImpulse{};  // λ of the angle rows
        // The angle rows' constants, gathered where optionalRows: last, away from what every block reads.
        F deltaAngle{};  // θB − θA − θref at step start
        F axialMass{};   // 1 / (1/IA + 1/IB)
        MotorLimitsT<F> angle;  // motor torque, limit angles
    };

    static bool optionalRows(const PreparedJoint& j) { return !pointRowsOnly(j); }
    static bool usesRotation(bool optionalRows) { return optionalRows; }

    template <std::size_t lanes>
    static void gather(const PreparedJoint& j, RowLane<lanes> out, bool optionalRows) {
        using R = Rows<float>;
        const RevoluteJoint& r = j.data.as<RevoluteJoint>();
        gatherFrame<R>(j, out);
        out.set(offsetof(R, linearImpulse), r.linearImpulse);
        out.set(offsetof(R, motorImpulse), r.motorImpulse);
        out.set(offsetof(R, lowerImpulse), r.lowerImpulse);
        out.set(offsetof(R, upperImpulse), r.upperImpulse);
        if (!optionalRows) return;
        out.set(offsetof(R, deltaAngle), j.deltaAngle);
        out.set(offsetof(R, axialMass), r.axialMass);
        gatherMotorLimits(out, offsetof(R, angle),
                          {r.motorSpeed, r.maxMotorTorque, r.lowerAngle, r.upperAngle, r.enableMotor ? 1.0f : 0.0f,
                           r.enableLimit ? 1.0f : 0.0f});
    }

    // Re-apply last step's impulses: λ at the anchors, then motor + lower − upper on ωB − ωA.
    template <class F>
    static void warmStart(const Rows<F>& r, JointPairT<F>& p) {
        const JointFrameT<F> f = currentFrame(p, r.anchorA, r.anchorB, r.deltaCenter);
        applyPoint(p, f.rA, f.rB, r.linearImpulse);
        applyRow(p, angularRowOf<F>(), r.motorImpulse + r.lowerImpulse - r.upperImpulse);
    }

    // One pass: the motor and the limits on θ = (θB − θA − θref)₀ + p.rotation, row ωB − ωA; then
    // the point rows on C = pB − pA, solved last so that the stiffest part wins.
    template <class F>
    static void solve(Rows<F>& r, JointPairT<F>& p, const StepContext& ctx, bool useBias, bool optionalRows) {
        if (optionalRows)
            solveMotorAndLimits(p, angularRowOf<F>(), r.axialMass, r.deltaAngle + p.rotation, r.angle, ctx, useBias, r.motorImpulse,
                                r.lowerImpulse, r.upperImpulse);
        const JointFrameT<F> f = currentFrame(p, r.anchorA, r.anchorB, r.deltaCenter);
        solvePointRows(p, f.rA, f.rB, f.d, rigidSoftness(ctx, useBias), r.linearImpulse);
    }

    // The point rows' λ; where the rows had angle rows, theirs too, and for a joint with a motor
    // or a limit the axial mass prepareRevolute wrote, which snapshots carry and such a joint has
    // always kept (one with the point rows alone never has).
    template <std::size_t lanes>
    static void store(RowLane<lanes, const float> rows, JointData& data, bool optionalRows) {
        using R = Rows<float>;
        RevoluteJoint& r = data.as<RevoluteJoint>();
        r.linearImpulse = rows.vec(offsetof(R, linearImpulse));
        if (!optionalRows) return;  // the point rows alone leave the angle rows' λ as they were
        r.motorImpulse = rows[offsetof(R, motorImpulse)];
        r.lowerImpulse = rows[offsetof(R, lowerImpulse)];
        r.upperImpulse = rows[offsetof(R, upperImpulse)];
        if (r.enableMotor || r.enableLimit) r.axialMass = rows[offsetof(R, axialMass)];
    }
};

constexpr JointLaneStages revoluteLanes = jointLaneStages<RevoluteRowSet>();

}  // namespace

Joint& makeJoint(World::Impl& w, const RevoluteJointDef& def) {
    requireFinite(std::isfinite(def.lowerAngle) && std::isfinite(def.upperAngle), "RevoluteJointDef limits");
    requireFinite(std::isfinite(def.motorSpeed) && std::isfinite(def.maxMotorTorque), "RevoluteJointDef motor");
    if (def.lowerAngle > def.upperAngle) throw Error("RevoluteJointDef: lowerAngle must be <= upperAngle");
    if (def.maxMotorTorque < 0.0f) throw Error("RevoluteJointDef.maxMotorTorque must be >= 0");
    Joint& j = addJoint(w, JointType::Revolute, def.bodyA, def.bodyB, def.localAnchorA, def.localAnchorB,
                        def.referenceAngle, def.collideConnected, def.userData);
    RevoluteJoint& r = j.data.emplace<RevoluteJoint>();
    r.enableLimit = def.enableLimit;
    r.lowerAngle = def.lowerAngle;
    r.upperAngle = def.upperAngle;
    r.enableMotor = def.enableMotor;
    r.motorSpeed = def.motorSpeed;
    r.maxMotorTorque = def.maxMotorTorque;
    return j;
}

void prepareRevolute(PreparedJoint& j, const StepContext& ctx, const Body&, const Body&) {
    RevoluteJoint& r = j.data.as<RevoluteJoint>();
    r.axialMass = effectiveMass(j.mass, angularRow);
    if (!ctx.enableWarmStarting) {
        r.linearImpulse = {};
        r.motorImpulse = r.lowerImpulse = r.upperImpulse = 0.0f;
    }
}

void solveRevoluteMotor(PreparedJoint& j, JointPair& p, const StepContext& ctx) {
    RevoluteJoint& r = j.data.as<RevoluteJoint>();
    if (r.enableMotor) solveMotorRow(p, angularRow, r.axialMass, r.motorSpeed, r.maxMotorTorque * ctx.hs, r.motorImpulse);
}
JointReaction reactionRevolute(const JointData& data) {
    const RevoluteJoint& r = data.as<RevoluteJoint>();
    return {r.linearImpulse, r.motorImpulse + r.lowerImpulse - r.upperImpulse};
}

template JointId World::createJoint(const RevoluteJointDef&);
extern const JointKind revoluteKind = jointKind<RevoluteJoint, &RevoluteJoint::motorSpeed>(
    {prepareRevolute, warmStartJoint<RevoluteRowSet>, solveJoint<RevoluteRowSet>, reactionRevolute, &revoluteLanes});

}  // namespace perpdot
