// Distance joint: one row along the line between the anchors, n = d/|d|, with Hecker's
// effective mass 1/mA + 1/mB + perpDot(rA,n)²/IA + perpDot(rB,n)²/IB. Rigid (a rod of `length`)
// when hertz = 0; otherwise a spring, kept between minLength and maxLength by one-sided rows.
#include <cmath>

#include "core/joint_rows.hpp"
#include "core/joint_type.hpp"
#include "core/world_impl.hpp"

namespace perpdot {

namespace {

struct DistanceJoint {
    float length = 1, minLength = 0, maxLength = 0;
    float hertz = 0, dampingRatio = 0;
    Softness spring;
    Vec2 axis;            // B's anchor from A's, unit, at step start
    float axialMass = 0;
    float impulse = 0, lowerImpulse = 0, upperImpulse = 0;
};

static_assert(reviewedLayout<DistanceJoint, 56>);
constexpr auto fields(const DistanceJoint*) {
    using J = DistanceJoint;
    return std::tuple{field("length", &J::length).anyBits(),
                      field("minLength", &J::minLength).anyBits(),
                      field("maxLength", &J::maxLength).anyBits(),
                      field("hertz", &J::hertz).anyBits(),
                      field("dampingRatio", &J::dampingRatio).anyBits(),
                      field("spring", &J::spring).anyBits(),
                      field("axis", &J::axis).anyBits(),
                      field("axialMass", &J::axialMass).anyBits(),
                      field("impulse", &J::impulse).anyBits(),
                      field("lowerImpulse", &J::lowerImpulse).anyBits(),
                      field("upperImpulse", &J::upperImpulse).anyBits()};
}

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

void warmStartDistance(PreparedJoint& j, JointPair& p) {
    const DistanceJoint& s = j.data.as<DistanceJoint>();
    const JointFrame f = currentFrame(j, p);
    applyRow(p, linearRow(f.rA, f.rB, normalize(f.d)), s.impulse + s.lowerImpulse - s.upperImpulse);
}

void solveDistance(PreparedJoint& j, JointPair& p, const StepContext& ctx, bool useBias) {
    DistanceJoint& s = j.data.as<DistanceJoint>();
    const JointFrame f = currentFrame(j, p);
    const float length = std::sqrt(lengthSquared(f.d));
    const Row row = linearRow(f.rA, f.rB, normalize(f.d));
    if (s.hertz == 0.0f) {
        solveRow(p, row, s.axialMass, length - s.length, rigidSoftness(ctx, useBias), s.impulse);
        return;
    }
    solveRow(p, row, s.axialMass, length - s.length, s.spring, s.impulse);
    solveLimitRow(p, row, s.axialMass, length - s.minLength, ctx, useBias, s.lowerImpulse);
    solveLimitRow(p, negated(row), s.axialMass, s.maxLength - length, ctx, useBias, s.upperImpulse);
}

JointReaction reactionDistance(const Joint& j) {
    const DistanceJoint& s = j.data.as<DistanceJoint>();
    return {(s.impulse + s.lowerImpulse - s.upperImpulse) * s.axis, 0.0f};
}

template JointId World::createJoint(const DistanceJointDef&);
extern const JointKind distanceKind = jointKind<DistanceJoint>({prepareDistance, warmStartDistance, solveDistance, reactionDistance});

}  // namespace perpdot
