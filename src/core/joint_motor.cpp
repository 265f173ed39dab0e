// Motor joint: drives B's origin to the point `linearOffset` of A's frame and θB − θA to
// `angularOffset`, each at the speed correctionFactor·C/h (a share of the error per step, as in
// Box2D; per substep it overshot the target by 0.8 m in a cross-check), impulses capped by maxForce·hs
// and maxTorque·hs. Rows: the point rows and the angular row of the weld, used as motors.
#include <cmath>

#include "core/joint_rows.hpp"
#include "core/joint_type.hpp"
#include "core/world_impl.hpp"

namespace perpdot {

namespace {

struct MotorJoint {
    float maxForce = 0, maxTorque = 0, correctionFactor = 0;
    float axialMass = 0;
    Vec2 linearImpulse;
    float angularImpulse = 0;
};

static_assert(reviewedLayout<MotorJoint, 28>);
constexpr auto fields(const MotorJoint*) {
    using J = MotorJoint;
    return std::tuple{field("maxForce", &J::maxForce).anyBits(),
                      field("maxTorque", &J::maxTorque).anyBits(),
                      field("correctionFactor", &J::correctionFactor).anyBits(),
                      field("axialMass", &J::axialMass).anyBits(),
                      field("linearImpulse", &J::linearImpulse).anyBits(),
                      field("angularImpulse", &J::angularImpulse).anyBits()};
}

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

void warmStartMotor(PreparedJoint& j, JointPair& p) {
    const MotorJoint& s = j.data.as<MotorJoint>();
    const JointFrame f = currentFrame(j, p);
    applyPoint(p, f.rA, f.rB, s.linearImpulse);
    applyRow(p, angularRow, s.angularImpulse);
}

void solveMotor(PreparedJoint& j, JointPair& p, const StepContext& ctx, bool) {
    MotorJoint& s = j.data.as<MotorJoint>();
    const float rate = s.correctionFactor * ctx.invH;
    solveMotorRow(p, angularRow, s.axialMass, -rate * currentAngle(j, p), s.maxTorque * ctx.hs, s.angularImpulse);
    const JointFrame f = currentFrame(j, p);
    solvePointRows(p, f.rA, f.rB, f.d, Softness{.biasRate = rate}, s.linearImpulse, s.maxForce * ctx.hs);
}

JointReaction reactionMotor(const Joint& j) { return {j.data.as<MotorJoint>().linearImpulse, j.data.as<MotorJoint>().angularImpulse}; }

template JointId World::createJoint(const MotorJointDef&);
extern const JointKind motorKind = jointKind<MotorJoint>({prepareMotor, warmStartMotor, solveMotor, reactionMotor});

}  // namespace perpdot
