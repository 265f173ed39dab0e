// Prismatic joint: B slides along an axis fixed in A. A block of two rows holds the anchor on
// the line (row along perp(axis)) and the relative angle; along the axis there is an optional
// motor row and two one-sided limit rows. The axis rows use A's arm to B's anchor, rA + d.
#include <cmath>

#include "core/joint_prismatic.hpp"
#include "core/joint_rows.hpp"
#include "core/joint_type.hpp"
#include "core/world_impl.hpp"

namespace perpdot {

namespace {

struct PrismaticJoint {
    Vec2 localAxisA;
    bool enableLimit = false, enableMotor = false;
    float lower = 0, upper = 0;
    float motorSpeed = 0, maxMotorForce = 0;
    Vec2 axisA;           // world axis at step start
    float axialMass = 0;  // of the row along the axis
    Vec2 impulse;         // (perpendicular, angular) rows
    float motorImpulse = 0, lowerImpulse = 0, upperImpulse = 0;
};

static_assert(reviewedLayout<PrismaticJoint, 60>);
constexpr auto fields(const PrismaticJoint*) {
    using J = PrismaticJoint;
    return std::tuple{field("localAxisA", &J::localAxisA).anyBits(),
                      field("enableLimit", &J::enableLimit),
                      field("enableMotor", &J::enableMotor),
                      field("lower", &J::lower).anyBits(),
                      field("upper", &J::upper).anyBits(),
                      field("motorSpeed", &J::motorSpeed).anyBits(),
                      field("maxMotorForce", &J::maxMotorForce).anyBits(),
                      field("axisA", &J::axisA).anyBits(),
                      field("axialMass", &J::axialMass).anyBits(),
                      field("impulse", &J::impulse).anyBits(),
                      field("motorImpulse", &J::motorImpulse).anyBits(),
                      field("lowerImpulse", &J::lowerImpulse).anyBits(),
                      field("upperImpulse", &J::upperImpulse).anyBits()};
}

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
    const Vec2 d = j.deltaCenter + j.anchorB - j.anchorA;
    s.axialMass = effectiveMass(j.mass, linearRow(j.anchorA + d, j.anchorB, s.axisA));
    if (!ctx.enableWarmStarting) {
        s.impulse = {};
        s.motorImpulse = s.lowerImpulse = s.upperImpulse = 0.0f;
    }
}

namespace {

struct SliderRows {
    Row axial, perpendicular;
    float translation, offset;  // along the axis, and off it
};

SliderRows sliderRows(const PreparedJoint& j, const JointPair& p) {
    const JointFrame f = currentFrame(j, p);
    const Vec2 axis = rotate(p.a.dq, j.data.as<PrismaticJoint>().axisA);
    return {linearRow(f.rA + f.d, f.rB, axis), linearRow(f.rA + f.d, f.rB, perp(axis)), dot(axis, f.d),
            dot(perp(axis), f.d)};
}

}  // namespace

void warmStartPrismatic(PreparedJoint& j, JointPair& p) {
    const PrismaticJoint& s = j.data.as<PrismaticJoint>();
    const SliderRows rows = sliderRows(j, p);
    applyRow(p, rows.axial, s.motorImpulse + s.lowerImpulse - s.upperImpulse);
    applyRow(p, rows.perpendicular, s.impulse.x);
    applyRow(p, angularRow, s.impulse.y);
}

void solvePrismatic(PreparedJoint& j, JointPair& p, const StepContext& ctx, bool useBias) {
    PrismaticJoint& s = j.data.as<PrismaticJoint>();
    const SliderRows rows = sliderRows(j, p);
    if (s.enableMotor) solveMotorRow(p, rows.axial, s.axialMass, s.motorSpeed, s.maxMotorForce * ctx.hs, s.motorImpulse);
    if (s.enableLimit) {
        solveLimitRow(p, rows.axial, s.axialMass, rows.translation - s.lower, ctx, useBias, s.lowerImpulse);
        solveLimitRow(p, negated(rows.axial), s.axialMass, s.upper - rows.translation, ctx, useBias, s.upperImpulse);
    }
    solveRowPair(p, rows.perpendicular, angularRow, {rows.offset, currentAngle(j, p)}, rigidSoftness(ctx, useBias),
                 s.impulse);
}

JointReaction reactionPrismatic(const Joint& j) {
    const PrismaticJoint& s = j.data.as<PrismaticJoint>();
    return {(s.motorImpulse + s.lowerImpulse - s.upperImpulse) * s.axisA + s.impulse.x * perp(s.axisA), s.impulse.y};
}

template JointId World::createJoint(const PrismaticJointDef&);
extern const JointKind prismaticKind = jointKind<PrismaticJoint, &PrismaticJoint::motorSpeed>({preparePrismatic, warmStartPrismatic, solvePrismatic, reactionPrismatic});

}  // namespace perpdot
