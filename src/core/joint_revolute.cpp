// Revolute joint: B's anchor held on A's by two point rows (the 2x2 K of joint_rows.hpp), plus on
// the angle θB − θA − θref an optional motor row and two one-sided limit rows, each with effective
// mass 1/(1/IA + 1/IB); all written once, for one joint and for the 4-wide blocks, in
// joint_solver_wide.hpp.
#include <cmath>

#include "core/joint_revolute.hpp"
#include "core/joint_solver_wide.hpp"
#include "core/joint_type.hpp"
#include "core/world_impl.hpp"

namespace perpdot {

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

void warmStartRevolute(PreparedJoint& j, JointPair& p) { warmStartRevoluteRows(revoluteRows(j), p); }

void solveRevolute(PreparedJoint& j, JointPair& p, const StepContext& ctx, bool useBias) {
    RevoluteRows<float> rows = revoluteRows(j);
    solveRevoluteRows(rows, revoluteAngleRows(j), p, ctx, useBias);
    storeImpulses(rows, j.data.as<RevoluteJoint>());
}

JointReaction reactionRevolute(const Joint& j) {
    const RevoluteJoint& r = j.data.as<RevoluteJoint>();
    return {r.linearImpulse, r.motorImpulse + r.lowerImpulse - r.upperImpulse};
}

template JointId World::createJoint(const RevoluteJointDef&);
extern const JointKind revoluteKind = jointKind<RevoluteJoint, &RevoluteJoint::motorSpeed>({prepareRevolute, warmStartRevolute, solveRevolute, reactionRevolute});

}  // namespace perpdot
