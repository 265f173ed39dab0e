// Pulley joint: lengthA + ratio·lengthB = constant, length = |anchor − ground anchor|
// (Box2D's b2PulleyJoint). With u the unit rope direction from the ground anchor to the body's
// anchor, d(length)/dt = u·(v + ω perp(r)) = u·v + perpDot(r, u) ω, so the row is
// nA = uA, sA = perpDot(rA, uA), nB = ratio·uB, sB = ratio·perpDot(rB, uB) (joint_coupled_row.hpp).
#include <cmath>
#include <memory>

#include "core/joint_coupled_row.hpp"
#include "core/world_impl.hpp"

namespace perpdot {

namespace {

// The rope on both sides now: lengths and the row.
struct Ropes {
    float lengthA, lengthB;
    CoupledRow row;
};

Ropes ropes(const PreparedJoint& j, const BodyState& a, const BodyState& b) {
    const PulleyJoint& s = j.data.pulley;
    const Vec2 rA = rotate(a.dq, j.anchorA), rB = rotate(b.dq, j.anchorB);
    const Vec2 dA = s.fromGroundA + a.dp + rA, dB = s.fromGroundB + b.dp + rB;
    const Vec2 uA = normalize(dA), uB = normalize(dB);
    return {length(dA), length(dB), {uA, perpDot(rA, uA), s.ratio * uB, s.ratio * perpDot(rB, uB)}};
}

}  // namespace

JointId World::createJoint(const PulleyJointDef& def) {
    requireFinite(isFinite(def.groundAnchorA) && isFinite(def.groundAnchorB), "PulleyJointDef ground anchors");
    requireFinite(std::isfinite(def.lengthA) && std::isfinite(def.lengthB), "PulleyJointDef lengths");
    requireFinite(std::isfinite(def.ratio), "PulleyJointDef.ratio");
    if (!(def.lengthA > 0.0f) || !(def.lengthB > 0.0f)) throw Error("PulleyJointDef: lengthA and lengthB must be > 0");
    if (!(def.ratio > 0.0f)) throw Error("PulleyJointDef.ratio must be > 0");
    Joint& j = addJoint(*impl_, JointType::Pulley, def.bodyA, def.bodyB, def.localAnchorA, def.localAnchorB, 0.0f,
                        def.collideConnected, def.userData);
    PulleyJoint& s = *std::construct_at(&j.data.pulley);
    s.groundA = def.groundAnchorA;
    s.groundB = def.groundAnchorB;
    s.ratio = def.ratio;
    s.constant = def.lengthA + def.ratio * def.lengthB;
    return jointId(*impl_, j);
}

void preparePulley(PreparedJoint& j, const StepContext& ctx, const Body& a, const Body& b) {
    PulleyJoint& s = j.data.pulley;
    s.fromGroundA = a.center - s.groundA;
    s.fromGroundB = b.center - s.groundB;
    const Ropes now = ropes(j, BodyState{}, BodyState{});
    s.uB = normalize(now.row.nB);
    s.mass = effectiveMass(j.mass, now.row);
    if (!ctx.enableWarmStarting) s.impulse = 0.0f;
}

void warmStartPulley(PreparedJoint& j, JointPair& p) { applyRow(p, ropes(j, p.a, p.b).row, j.data.pulley.impulse); }

void solvePulley(PreparedJoint& j, JointPair& p, const StepContext& ctx, bool useBias) {
    PulleyJoint& s = j.data.pulley;
    const Ropes now = ropes(j, p.a, p.b);
    solveRow(p, now.row, s.mass, now.lengthA + s.ratio * now.lengthB - s.constant, rigidSoftness(ctx, useBias), s.impulse);
}

// The rope's pull on B: ratio·λ along B's rope direction (λ < 0 while the rope is in tension).
JointReaction reactionPulley(const Joint& j) {
    const PulleyJoint& s = j.data.pulley;
    return {(s.ratio * s.impulse) * s.uB, 0.0f};
}

extern const JointStages pulleyStages{preparePulley, warmStartPulley, solvePulley, reactionPulley};

}  // namespace perpdot
