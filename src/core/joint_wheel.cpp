// Wheel joint: B's anchor (the axle) moves along a suspension axis fixed in A and B turns freely.
// One rigid row holds the axle on the line (along perp(axis)), a spring row acts along the axis
// (rigid when hertz = 0), and an optional motor row drives ωB − ωA.
#include <cmath>

#include "core/joint_rows.hpp"
#include "core/joint_type.hpp"
#include "core/world_impl.hpp"

namespace perpdot {

namespace {

struct WheelJoint {
    Vec2 localAxisA;
    float hertz = 0, dampingRatio = 0;  // 0 hertz: rigid suspension
    bool enableMotor = false;
    float motorSpeed = 0, maxMotorTorque = 0;
    Softness spring;
    Vec2 axisA;
    float axialMass = 0, motorMass = 0;
    float perpImpulse = 0, springImpulse = 0, motorImpulse = 0;
};

static_assert(reviewedLayout<WheelJoint, 68>);
constexpr auto fields(const WheelJoint*) {
    using J = WheelJoint;
    return std::tuple{field("localAxisA", &J::localAxisA).anyBits(),
                      field("hertz", &J::hertz).anyBits(),
                      field("dampingRatio", &J::dampingRatio).anyBits(),
                      field("enableMotor", &J::enableMotor),
                      field("motorSpeed", &J::motorSpeed).anyBits(),
                      field("maxMotorTorque", &J::maxMotorTorque).anyBits(),
                      field("spring", &J::spring).anyBits(),
                      field("axisA", &J::axisA).anyBits(),
                      field("axialMass", &J::axialMass).anyBits(),
                      field("motorMass", &J::motorMass).anyBits(),
                      field("perpImpulse", &J::perpImpulse).anyBits(),
                      field("springImpulse", &J::springImpulse).anyBits(),
                      field("motorImpulse", &J::motorImpulse).anyBits()};
}

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
    const Vec2 d = j.deltaCenter + j.anchorB - j.anchorA;
    s.axialMass = effectiveMass(j.mass, linearRow(j.anchorA + d, j.anchorB, s.axisA));
    s.motorMass = effectiveMass(j.mass, angularRow);
    s.spring = makeSoftness(s.hertz, s.dampingRatio, ctx.hs);
    if (!ctx.enableWarmStarting) s.perpImpulse = s.springImpulse = s.motorImpulse = 0.0f;
}

namespace {

struct WheelRows {
    Row axial, perpendicular;
    float translation, offset;
};

WheelRows wheelRows(const PreparedJoint& j, const JointPair& p) {
    const JointFrame f = currentFrame(j, p);
    const Vec2 axis = rotate(p.a.dq, j.data.as<WheelJoint>().axisA);
    return {linearRow(f.rA + f.d, f.rB, axis), linearRow(f.rA + f.d, f.rB, perp(axis)), dot(axis, f.d),
            dot(perp(axis), f.d)};
}

}  // namespace

void warmStartWheel(PreparedJoint& j, JointPair& p) {
    const WheelJoint& s = j.data.as<WheelJoint>();
    const WheelRows rows = wheelRows(j, p);
    applyRow(p, rows.axial, s.springImpulse);
    applyRow(p, rows.perpendicular, s.perpImpulse);
    applyRow(p, angularRow, s.motorImpulse);
}

void solveWheel(PreparedJoint& j, JointPair& p, const StepContext& ctx, bool useBias) {
    WheelJoint& s = j.data.as<WheelJoint>();
    if (s.enableMotor) solveMotorRow(p, angularRow, s.motorMass, s.motorSpeed, s.maxMotorTorque * ctx.hs, s.motorImpulse);
    WheelRows rows = wheelRows(j, p);
    const Softness suspension = s.hertz > 0.0f ? s.spring : rigidSoftness(ctx, useBias);
    solveRow(p, rows.axial, s.axialMass, rows.translation, suspension, s.springImpulse);
    rows = wheelRows(j, p);
    solveRow(p, rows.perpendicular, effectiveMass(p.m, rows.perpendicular), rows.offset, rigidSoftness(ctx, useBias),
             s.perpImpulse);
}

JointReaction reactionWheel(const Joint& j) {
    const WheelJoint& s = j.data.as<WheelJoint>();
    return {s.springImpulse * s.axisA + s.perpImpulse * perp(s.axisA), s.motorImpulse};
}

template JointId World::createJoint(const WheelJointDef&);
extern const JointKind wheelKind = jointKind<WheelJoint, &WheelJoint::motorSpeed>({prepareWheel, warmStartWheel, solveWheel, reactionWheel});

}  // namespace perpdot
