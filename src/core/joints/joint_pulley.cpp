// Pulley joint: lengthA + ratio·lengthB = constant, length = |anchor − ground anchor|
// (Box2D's b2PulleyJoint). With u the unit rope direction from the ground anchor to the body's
// anchor, d(length)/dt = u·(v + ω perp(r)) = u·v + perpDot(r, u) ω, so the row is
// nA = uA, sA = perpDot(rA, uA), nB = ratio·uB, sB = ratio·perpDot(rB, uB) (joint_coupled_row.hpp).
#include <cmath>

#include "core/bodies/body_store.hpp"
#include "core/joints/joint_coupled_row.hpp"
#include "core/joints/joint_type.hpp"

namespace perpdot {

namespace {

// lengthA + ratio·lengthB = constant, length = |anchor − ground anchor|.
struct PulleyJoint {
    Vec2 groundA, groundB;   // world
    float ratio = 1, constant = 0;
    Vec2 fromGroundA, fromGroundB;  // centre of mass − ground anchor, at step start
    Vec2 uB;                 // B's rope direction (ground to anchor) at step start, for the reaction
    float mass = 0;
    float impulse = 0;
};

static_assert(reviewedLayout<PulleyJoint, 56>);
constexpr auto fields(const PulleyJoint*) {
    using J = PulleyJoint;
    return std::tuple{field("groundA", &J::groundA).anyBits(),
                      field("groundB", &J::groundB).anyBits(),
                      field("ratio", &J::ratio).anyBits(),
                      field("constant", &J::constant).anyBits(),
                      field("fromGroundA", &J::fromGroundA).anyBits(),
                      field("fromGroundB", &J::fromGroundB).anyBits(),
                      field("uB", &J::uB).anyBits(),
                      field("mass", &J::mass).anyBits(),
                      field("impulse", &J::impulse).anyBits()};
}

// The rope on both sides now: lengths and the row.
struct Ropes {
    float lengthA, lengthB;
    CoupledRow row;
};

Ropes ropes(const PreparedJoint& j, const BodyState& a, const BodyState& b) {
    const PulleyJoint& s = j.data.as<PulleyJoint>();
    const Vec2 rA = rotate(a.dq, j.anchorA), rB = rotate(b.dq, j.anchorB);
    const Vec2 dA = s.fromGroundA + a.dp + rA, dB = s.fromGroundB + b.dp + rB;
    const Vec2 uA = normalize(dA), uB = normalize(dB);
    return {length(dA), length(dB), {uA, perpDot(rA, uA), s.ratio * uB, s.ratio * perpDot(rB, uB)}};
}

}  // namespace

Joint& makeJoint(World::Impl& w, const PulleyJointDef& def) {
    requireFinite(isFinite(def.groundAnchorA) && isFinite(def.groundAnchorB), "PulleyJointDef ground anchors");
    requireFinite(std::isfinite(def.lengthA) && std::isfinite(def.lengthB), "PulleyJointDef lengths");
    requireFinite(std::isfinite(def.ratio), "PulleyJointDef.ratio");
    if (!(def.lengthA > 0.0f) || !(def.lengthB > 0.0f)) throw Error("PulleyJointDef: lengthA and lengthB must be > 0");
    if (!(def.ratio > 0.0f)) throw Error("PulleyJointDef.ratio must be > 0");
    Joint& j = addJoint(w, JointType::Pulley, def.bodyA, def.bodyB, def.localAnchorA, def.localAnchorB, 0.0f,
                        def.collideConnected, def.userData);
    PulleyJoint& s = j.data.emplace<PulleyJoint>();
    s.groundA = def.groundAnchorA;
    s.groundB = def.groundAnchorB;
    s.ratio = def.ratio;
    s.constant = def.lengthA + def.ratio * def.lengthB;
    return j;
}

void preparePulley(PreparedJoint& j, const StepContext& ctx, const Body& a, const Body& b) {
    PulleyJoint& s = j.data.as<PulleyJoint>();
    s.fromGroundA = a.center - s.groundA;
    s.fromGroundB = b.center - s.groundB;
    const Ropes now = ropes(j, BodyState{}, BodyState{});
    s.uB = normalize(now.row.nB);
    s.mass = effectiveMass(j.mass, now.row);
    if (!ctx.enableWarmStarting) s.impulse = 0.0f;
}

void warmStartPulley(PreparedJoint& j, JointPair& p) { applyRow(p, ropes(j, p.a, p.b).row, j.data.as<PulleyJoint>().impulse); }

void solvePulley(PreparedJoint& j, JointPair& p, const StepContext& ctx, bool useBias) {
    PulleyJoint& s = j.data.as<PulleyJoint>();
    const Ropes now = ropes(j, p.a, p.b);
    solveRow(p, now.row, s.mass, now.lengthA + s.ratio * now.lengthB - s.constant, rigidSoftness(ctx, useBias), s.impulse);
}

// The rope's pull on B: ratio·λ along B's rope direction (λ < 0 while the rope is in tension).
JointReaction reactionPulley(const JointData& data) {
    const PulleyJoint& s = data.as<PulleyJoint>();
    return {(s.ratio * s.impulse) * s.uB, 0.0f};
}

std::pair<Vec2, Vec2> World::pulleyGroundAnchors(JointId id) const {
    const Joint& j = checkedJoint(*impl_, id);
    if (j.type != JointType::Pulley) throw Error("pulleyGroundAnchors: not a pulley joint");
    const PulleyJoint& s = j.data.as<PulleyJoint>();
    return {s.groundA, s.groundB};
}

void shiftPulleyGround(Joint& j, Vec2 newOrigin) {
    PulleyJoint& s = j.data.as<PulleyJoint>();
    s.groundA -= newOrigin;
    s.groundB -= newOrigin;
}

template JointId World::createJoint(const PulleyJointDef&);
extern const JointKind pulleyKind = jointKind<PulleyJoint>({preparePulley, warmStartPulley, solvePulley, reactionPulley});

}  // namespace perpdot
