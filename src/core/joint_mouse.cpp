// Mouse joint: a soft spring (hertz, damping ratio) pulling B's grabbed point to the target,
// the point rows of joint_rows.hpp with only B movable and the impulse capped at maxForce·hs.
// The target is anchor A, so it stays put in A's frame (A is normally static).
#include <cmath>
#include <memory>

#include "core/joint_rows.hpp"
#include "core/world_impl.hpp"

namespace perpdot {

JointId World::createJoint(const MouseJointDef& def) {
    requireFinite(isFinite(def.target), "MouseJointDef.target");
    requireFinite(std::isfinite(def.hertz) && std::isfinite(def.dampingRatio) && std::isfinite(def.maxForce),
                  "MouseJointDef spring");
    if (!(def.hertz > 0.0f) || def.dampingRatio < 0.0f || def.maxForce < 0.0f)
        throw Error("MouseJointDef: need hertz > 0, dampingRatio >= 0 and maxForce >= 0");
    const Transform xfA = transform(def.bodyA), xfB = transform(def.bodyB);
    Joint& j = addJoint(*impl_, JointType::Mouse, def.bodyA, def.bodyB, invTransformPoint(xfA, def.target),
                        invTransformPoint(xfB, def.target), 0.0f, def.collideConnected, def.userData);
    MouseJoint& s = *std::construct_at(&j.data.mouse);
    s.hertz = def.hertz;
    s.dampingRatio = def.dampingRatio;
    s.maxForce = def.maxForce;
    return jointId(*impl_, j);
}

void prepareMouse(PreparedJoint& j, const StepContext& ctx, const Body&, const Body&) {
    MouseJoint& s = j.data.mouse;
    j.mass.mA = j.mass.iA = 0.0f;  // the mouse pulls B only
    s.softness = makeSoftness(s.hertz, s.dampingRatio, ctx.hs);
    if (!ctx.enableWarmStarting) s.linearImpulse = {};
}

void warmStartMouse(PreparedJoint& j, JointPair& p) {
    const JointFrame f = currentFrame(j, p);
    applyPoint(p, f.rA, f.rB, j.data.mouse.linearImpulse);
}

void solveMouse(PreparedJoint& j, JointPair& p, const StepContext& ctx, bool) {
    MouseJoint& s = j.data.mouse;
    const JointFrame f = currentFrame(j, p);
    solvePointRows(p, f.rA, f.rB, f.d, s.softness, s.linearImpulse, s.maxForce * ctx.hs);
}

JointReaction reactionMouse(const Joint& j) { return {j.data.mouse.linearImpulse, 0.0f}; }

extern const JointStages mouseStages{prepareMouse, warmStartMouse, solveMouse, reactionMouse};

}  // namespace perpdot
