// Mouse joint: a soft spring (hertz, damping ratio) pulling B's grabbed point to the target,
// the point rows of joint_rows.hpp with only B movable and the impulse capped at maxForce·hs.
// The target is anchor A, so it stays put in A's frame (A is normally static).
#include <cmath>

#include "core/bodies/body_store.hpp"
#include "core/joints/joint_mouse.hpp"
#include "core/joints/joint_rows.hpp"
#include "core/joints/joint_type.hpp"

namespace perpdot {

Joint& makeJoint(World::Impl& w, const MouseJointDef& def) {
    requireFinite(isFinite(def.target), "MouseJointDef.target");
    requireFinite(std::isfinite(def.hertz) && std::isfinite(def.dampingRatio) && std::isfinite(def.maxForce),
                  "MouseJointDef spring");
    if (!(def.hertz > 0.0f) || def.dampingRatio < 0.0f || def.maxForce < 0.0f)
        throw Error("MouseJointDef: need hertz > 0, dampingRatio >= 0 and maxForce >= 0");
    const Transform xfA = checkedBody(w, def.bodyA, "createJoint").xf, xfB = checkedBody(w, def.bodyB, "createJoint").xf;
    Joint& j = addJoint(w, JointType::Mouse, def.bodyA, def.bodyB, invTransformPoint(xfA, def.target),
                        invTransformPoint(xfB, def.target), 0.0f, def.collideConnected, def.userData);
    MouseJoint& s = j.data.emplace<MouseJoint>();
    s.hertz = def.hertz;
    s.dampingRatio = def.dampingRatio;
    s.maxForce = def.maxForce;
    return j;
}

void prepareMouse(PreparedJoint& j, const StepContext& ctx, const Body&, const Body&) {
    MouseJoint& s = j.data.as<MouseJoint>();
    j.mass.mA = j.mass.iA = 0.0f;  // the mouse pulls B only
    s.softness = makeSoftness(s.hertz, s.dampingRatio, ctx.hs);
    if (!ctx.enableWarmStarting) s.linearImpulse = {};
}

void warmStartMouse(PreparedJoint& j, JointPair& p) {
    const JointFrame f = currentFrame(j, p);
    applyPoint(p, f.rA, f.rB, j.data.as<MouseJoint>().linearImpulse);
}

void solveMouse(PreparedJoint& j, JointPair& p, const StepContext& ctx, bool) {
    MouseJoint& s = j.data.as<MouseJoint>();
    const JointFrame f = currentFrame(j, p);
    solvePointRows(p, f.rA, f.rB, f.d, s.softness, s.linearImpulse, s.maxForce * ctx.hs);
}

JointReaction reactionMouse(const JointData& data) { return {data.as<MouseJoint>().linearImpulse, 0.0f}; }

template JointId World::createJoint(const MouseJointDef&);
extern const JointKind mouseKind = jointKind<MouseJoint>({prepareMouse, warmStartMouse, solveMouse, reactionMouse});

}  // namespace perpdot
