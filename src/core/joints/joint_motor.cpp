// Motor joint: drives B's origin to the point `linearOffset` of A's frame and θB − θA to
// `angularOffset`, each at the speed correctionFactor·C/h (a share of the error per step, as in
// Box2D; per substep it overshot the target by 0.8 m in a cross-check), impulses capped by maxForce·hs
// and maxTorque·hs. Rows: the point rows and the angular row of the weld, used as motors, written
// once over a lane type F, for one joint and for blocks of four (joint_solver_wide.hpp).
#include <cmath>
#include <cstddef>

#include "core/bodies/body_store.hpp"
#include "core/joints/joint_motor.hpp"
#include "core/joints/joint_solver_wide.hpp"
#include "core/joints/joint_type.hpp"

namespace perpdot {

namespace {

// The motor joint's rows: the angle row, then the point rows, each a motor with a capped impulse.
struct MotorRowSet {
    template <class F>
    struct Rows {
        Vec2T<F> anchorA, anchorB;  // rA (to the target point), rB (to B's origin) at step start
        Vec2T<F> deltaCenter;       // cB − cA at step start
        Vec2T<F> linearImpulse;     // λ of the point rows
        F angularImpulse{};         // λ of the angle row
        F deltaAngle{};             // θB − θA − angularOffset at step start
        F axialMass{};              // 1 / (1/IA + 1/IB)
        F correctionFactor{}, maxForce{}, maxTorque{};
    };

    static bool optionalRows(const PreparedJoint&) { return false; }
    static bool usesRotation(bool) { return true; }

    template <std::size_t lanes>
    static void gather(const PreparedJoint& j, RowLane<lanes> out, bool) {
        using R = Rows<float>;
        const MotorJoint& s = j.data.as<MotorJoint>();
        gatherPointAndAngle<R>(j, s, out);
        out.set(offsetof(R, correctionFactor), s.correctionFactor);
        out.set(offsetof(R, maxForce), s.maxForce);
        out.set(offsetof(R, maxTorque), s.maxTorque);
    }

    // Re-apply last step's impulses: λ at the anchors, then the angle's on ωB − ωA.
    template <class F>
    static void warmStart(const Rows<F>& r, JointPairT<F>& p) {
        warmStartPointAndAngle(r, p);
    }

    // One pass: the angle row drives θ = (θB − θA − angularOffset)₀ + p.rotation at −rate·θ
    // (|λ| ≤ maxTorque·hs), then the point rows C = pB − pA at bias rate `rate` (|λ| ≤ maxForce·hs);
    // rate = correctionFactor/h.
    template <class F>
    static void solve(Rows<F>& r, JointPairT<F>& p, const StepContext& ctx, bool, bool) {
        const F rate = r.correctionFactor * F(ctx.invH);
        solveMotorRow(p, angularRowOf<F>(), r.axialMass, -rate * (r.deltaAngle + p.rotation), r.maxTorque * F(ctx.hs),
                      r.angularImpulse);
        const JointFrameT<F> f = currentFrame(p, r.anchorA, r.anchorB, r.deltaCenter);
        solvePointRows(p, f.rA, f.rB, f.d, SoftnessT<F>{rate, F(1.0f), F(0.0f)}, r.linearImpulse, r.maxForce * F(ctx.hs));
    }

    // The impulses, and what prepareMotor wrote (snapshots carry it).
    template <std::size_t lanes>
    static void store(RowLane<lanes, const float> rows, JointData& data, bool) {
        using R = Rows<float>;
        storePointAndAngle<R>(rows, data.as<MotorJoint>());
    }
};

constexpr JointLaneStages motorLanes = jointLaneStages<MotorRowSet>();

}  // namespace

Joint& makeJoint(World::Impl& w, const MotorJointDef& def) {
    requireFinite(isFinite(def.linearOffset) && std::isfinite(def.angularOffset), "MotorJointDef offsets");
    requireFinite(std::isfinite(def.maxForce) && std::isfinite(def.maxTorque) && std::isfinite(def.correctionFactor),
                  "MotorJointDef limits");
    if (def.maxForce < 0.0f || def.maxTorque < 0.0f) throw Error("MotorJointDef: maxForce and maxTorque must be >= 0");
    if (def.correctionFactor < 0.0f || def.correctionFactor > 1.0f) throw Error("MotorJointDef.correctionFactor must be in [0, 1]");
    // Anchor A is the target point in A's frame, anchor B is B's origin.
    Joint& j = addJoint(w, JointType::Motor, def.bodyA, def.bodyB, def.linearOffset, {}, def.angularOffset,
                        def.collideConnected, def.userData);
    MotorJoint& s = j.data.emplace<MotorJoint>();
    s.maxForce = def.maxForce;
    s.maxTorque = def.maxTorque;
    s.correctionFactor = def.correctionFactor;
    return j;
}

void prepareMotor(PreparedJoint& j, const StepContext& ctx, const Body&, const Body&) {
    MotorJoint& s = j.data.as<MotorJoint>();
    s.axialMass = effectiveMass(j.mass, angularRow);
    if (!ctx.enableWarmStarting) {
        s.linearImpulse = {};
        s.angularImpulse = 0.0f;
    }
}

// The friction joint is the motor joint's rows at the anchors with no correction (rate 0): the
// point rows drive vB + ωB perp(rB) − vA − ωA perp(rA) to zero, |λ| ≤ maxForce·hs, the angle row
// ωB − ωA to zero, |λ| ≤ maxTorque·hs (Box2D 2.4's b2FrictionJoint).
Joint& makeJoint(World::Impl& w, const FrictionJointDef& def) {
    requireFinite(std::isfinite(def.maxForce) && std::isfinite(def.maxTorque), "FrictionJointDef limits");
    if (def.maxForce < 0.0f || def.maxTorque < 0.0f) throw Error("FrictionJointDef: maxForce and maxTorque must be >= 0");
    Joint& j = addJoint(w, JointType::Friction, def.bodyA, def.bodyB, def.localAnchorA, def.localAnchorB, 0.0f,
                        def.collideConnected, def.userData);
    MotorJoint& s = j.data.emplace<MotorJoint>();
    s.maxForce = def.maxForce;
    s.maxTorque = def.maxTorque;
    return j;
}

JointReaction reactionMotor(const JointData& data) { return {data.as<MotorJoint>().linearImpulse, data.as<MotorJoint>().angularImpulse}; }

template JointId World::createJoint(const MotorJointDef&);
template JointId World::createJoint(const FrictionJointDef&);
constexpr JointStages motorStages{prepareMotor, warmStartJoint<MotorRowSet>, solveJoint<MotorRowSet>, reactionMotor, &motorLanes};
extern const JointKind motorKind = jointKind<MotorJoint>(motorStages);
extern const JointKind frictionKind = jointKind<MotorJoint>(motorStages);

}  // namespace perpdot
