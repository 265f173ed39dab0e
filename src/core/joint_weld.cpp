// Weld joint: the point rows of the revolute joint plus one angular row (effective mass
// 1/(1/IA + 1/IB)) holding θB − θA at the reference angle. With hertz > 0 the angular row is a
// spring (Box2D 2.4's soft weld bends; it does not stretch).
#include <cmath>

#include "core/joint_rows.hpp"
#include "core/joint_type.hpp"
#include "core/world_impl.hpp"

namespace perpdot {

namespace {

struct WeldJoint {
    float hertz = 0, dampingRatio = 0;  // soft in the angle only, like Box2D 2.4's weld
    Softness angularSoftness;
    float axialMass = 0;
    Vec2 linearImpulse;
    float angularImpulse = 0;
};

static_assert(reviewedLayout<WeldJoint, 36>);
constexpr auto fields(const WeldJoint*) {
    using J = WeldJoint;
    return std::tuple{field("hertz", &J::hertz).anyBits(),
                      field("dampingRatio", &J::dampingRatio).anyBits(),
                      field("angularSoftness", &J::angularSoftness).anyBits(),
                      field("axialMass", &J::axialMass).anyBits(),
                      field("linearImpulse", &J::linearImpulse).anyBits(),
                      field("angularImpulse", &J::angularImpulse).anyBits()};
}

}  // namespace

Joint& makeJoint(World::Impl& w, const WeldJointDef& def) {
    requireFinite(std::isfinite(def.hertz) && std::isfinite(def.dampingRatio), "WeldJointDef spring");
    if (def.hertz < 0.0f || def.dampingRatio < 0.0f) throw Error("WeldJointDef: hertz and dampingRatio must be >= 0");
    Joint& j = addJoint(w, JointType::Weld, def.bodyA, def.bodyB, def.localAnchorA, def.localAnchorB,
                        def.referenceAngle, def.collideConnected, def.userData);
    WeldJoint& s = j.data.emplace<WeldJoint>();
    s.hertz = def.hertz;
    s.dampingRatio = def.dampingRatio;
    return j;
}

void prepareWeld(PreparedJoint& j, const StepContext& ctx, const Body&, const Body&) {
    WeldJoint& s = j.data.as<WeldJoint>();
    s.axialMass = effectiveMass(j.mass, angularRow);
    s.angularSoftness = makeSoftness(s.hertz, s.dampingRatio, ctx.hs);
    if (!ctx.enableWarmStarting) {
        s.linearImpulse = {};
        s.angularImpulse = 0.0f;
    }
}

void warmStartWeld(PreparedJoint& j, JointPair& p) {
    const WeldJoint& s = j.data.as<WeldJoint>();
    const JointFrame f = currentFrame(j, p);
    applyPoint(p, f.rA, f.rB, s.linearImpulse);
    applyRow(p, angularRow, s.angularImpulse);
}

void solveWeld(PreparedJoint& j, JointPair& p, const StepContext& ctx, bool useBias) {
    WeldJoint& s = j.data.as<WeldJoint>();
    const Softness angular = s.hertz > 0.0f ? s.angularSoftness : rigidSoftness(ctx, useBias);
    solveRow(p, angularRow, s.axialMass, currentAngle(j, p), angular, s.angularImpulse);
    const JointFrame f = currentFrame(j, p);
    solvePointRows(p, f.rA, f.rB, f.d, rigidSoftness(ctx, useBias), s.linearImpulse);
}

JointReaction reactionWeld(const Joint& j) { return {j.data.as<WeldJoint>().linearImpulse, j.data.as<WeldJoint>().angularImpulse}; }

template JointId World::createJoint(const WeldJointDef&);
extern const JointKind weldKind = jointKind<WeldJoint>({prepareWeld, warmStartWeld, solveWeld, reactionWeld});

}  // namespace perpdot
