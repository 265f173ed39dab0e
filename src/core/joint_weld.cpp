// Weld joint: the point rows of the revolute joint plus one angular row (effective mass
// 1/(1/IA + 1/IB)) holding θB − θA at the reference angle. With hertz > 0 the angular row is a
// spring (Box2D 2.4's soft weld bends; it does not stretch).
#include <cmath>
#include <memory>

#include "core/joint_rows.hpp"
#include "core/world_impl.hpp"

namespace perpdot {

JointId World::createJoint(const WeldJointDef& def) {
    requireFinite(std::isfinite(def.hertz) && std::isfinite(def.dampingRatio), "WeldJointDef spring");
    if (def.hertz < 0.0f || def.dampingRatio < 0.0f) throw Error("WeldJointDef: hertz and dampingRatio must be >= 0");
    Joint& j = addJoint(*impl_, JointType::Weld, def.bodyA, def.bodyB, def.localAnchorA, def.localAnchorB,
                        def.referenceAngle, def.collideConnected, def.userData);
    WeldJoint& s = *std::construct_at(&j.data.weld);
    s.hertz = def.hertz;
    s.dampingRatio = def.dampingRatio;
    return jointId(*impl_, j);
}

void prepareWeld(PreparedJoint& j, const StepContext& ctx, const Body&, const Body&) {
    WeldJoint& s = j.data.weld;
    s.axialMass = effectiveMass(j.mass, angularRow);
    s.angularSoftness = makeSoftness(s.hertz, s.dampingRatio, ctx.hs);
    if (!ctx.enableWarmStarting) {
        s.linearImpulse = {};
        s.angularImpulse = 0.0f;
    }
}

void warmStartWeld(PreparedJoint& j, JointPair& p) {
    const WeldJoint& s = j.data.weld;
    const JointFrame f = currentFrame(j, p);
    applyPoint(p, f.rA, f.rB, s.linearImpulse);
    applyRow(p, angularRow, s.angularImpulse);
}

void solveWeld(PreparedJoint& j, JointPair& p, const StepContext& ctx, bool useBias) {
    WeldJoint& s = j.data.weld;
    const Softness angular = s.hertz > 0.0f ? s.angularSoftness : rigidSoftness(ctx, useBias);
    solveRow(p, angularRow, s.axialMass, currentAngle(j, p), angular, s.angularImpulse);
    const JointFrame f = currentFrame(j, p);
    solvePointRows(p, f.rA, f.rB, f.d, rigidSoftness(ctx, useBias), s.linearImpulse);
}

JointReaction reactionWeld(const Joint& j) { return {j.data.weld.linearImpulse, j.data.weld.angularImpulse}; }

extern const JointStages weldStages{prepareWeld, warmStartWeld, solveWeld, reactionWeld};

}  // namespace perpdot
