// Gear joint: coordinateA + ratio·coordinateB = constant, between the moving bodies of two
// revolute or prismatic joints whose other body is static (Box2D's b2GearJoint with static C, D).
// A revolute side's coordinate is its angle, Ċ-term ω (n = 0, s = 1); a prismatic side's is
// axis·(anchor − base), Ċ-term axis·v + perpDot(r, axis) ω. One coupled row (joint_coupled_row.hpp),
// B's terms scaled by the ratio.
#include <cmath>
#include <string>

#include "core/bodies/body_store.hpp"
#include "core/joints/joint_coupled_row.hpp"
#include "core/joints/joint_prismatic.hpp"
#include "core/joints/joint_type.hpp"

namespace perpdot {

namespace {

// One side of a gear: the coordinate of a revolute joint, θ − offset, or of a prismatic joint,
// axis·anchor − offset (= axis·(anchor − base)), whose body A is static, so axis and offset are fixed.
struct GearSide {
    JointType kind = JointType::Revolute;
    Vec2 axis;             // prismatic: world
    float offset = 0;      // revolute: θ of the static body + the joint's reference angle; prismatic: axis·base
    float coordinate = 0;  // at step start
};

constexpr auto fields(const GearSide*) {
    using S = GearSide;
    return std::tuple{field("kind", &S::kind), field("axis", &S::axis).anyBits(), field("offset", &S::offset).anyBits(),
                      field("coordinate", &S::coordinate).anyBits()};
}

// coordinateA + ratio·coordinateB = constant.
struct GearJoint {
    GearSide sideA, sideB;
    float ratio = 1, constant = 0;
    float mass = 0;
    float impulse = 0;
};

static_assert(reviewedLayout<GearJoint, 56>);
constexpr auto fields(const GearJoint*) {
    using J = GearJoint;
    return std::tuple{field("sideA", &J::sideA),
                      field("sideB", &J::sideB),
                      field("ratio", &J::ratio).anyBits(),
                      field("constant", &J::constant).anyBits(),
                      field("mass", &J::mass).anyBits(),
                      field("impulse", &J::impulse).anyBits()};
}

// The side's coordinate with the body at rest at `body`, its anchor at arm r from the centre of mass.
float coordinateAt(const GearSide& side, const Body& body, Vec2 r) {
    if (side.kind == JointType::Revolute) return body.angle - side.offset;
    return dot(body.center + r, side.axis) - side.offset;
}

// A revolute or prismatic joint seen from its moving body B: what the gear needs to measure it.
GearSide gearSide(const World::Impl& w, const Joint& joint, const char* which) {
    const std::string name = std::string("GearJointDef.") + which;
    if (joint.type != JointType::Revolute && joint.type != JointType::Prismatic)
        throw Error(name + " must be a revolute or prismatic joint");
    const Body& base = bodyAt(w, joint.bodyA);
    const Body& moving = bodyAt(w, joint.bodyB);
    if (base.type != BodyType::Static)
        throw Error(name + "'s body A must be static (perpdot's gear couples the two joints' bodies B)");
    GearSide side{.kind = joint.type};
    if (joint.type == JointType::Revolute) {
        side.offset = base.angle + joint.referenceAngle;
    } else {
        side.axis = rotate(base.xf.q, prismaticLocalAxis(joint));
        side.offset = dot(transformPoint(base.xf, joint.localAnchorA), side.axis);
    }
    side.coordinate = coordinateAt(side, moving, rotate(moving.xf.q, joint.localAnchorB - moving.localCenter));
    return side;
}

// The side's coordinate now, and its Ċ-terms, from the body's step-start state plus Δp, Δq.
struct SideNow {
    float coordinate;
    Vec2 n;
    float s;
};

// `turned`: the body's Δθ summed over the substeps so far (as the body's angle will add it).
SideNow sideNow(const GearSide& side, const BodyState& body, float turned, Vec2 anchor) {
    if (side.kind == JointType::Revolute) return {side.coordinate + turned, {}, 1.0f};
    const Vec2 r = rotate(body.dq, anchor);
    return {side.coordinate + dot(body.dp + r - anchor, side.axis), side.axis, perpDot(r, side.axis)};
}

CoupledRow gearRow(const GearJoint& g, const SideNow& a, const SideNow& b) {
    return {a.n, a.s, g.ratio * b.n, g.ratio * b.s};
}

}  // namespace

Joint& makeJoint(World::Impl& w, const GearJointDef& def) {
    requireFinite(std::isfinite(def.ratio), "GearJointDef.ratio");
    if (def.ratio == 0.0f) throw Error("GearJointDef.ratio must not be 0");
    const Joint& jointA = checkedJoint(w, def.jointA, "createJoint");
    const Joint& jointB = checkedJoint(w, def.jointB, "createJoint");
    const GearSide sideA = gearSide(w, jointA, "jointA");
    const GearSide sideB = gearSide(w, jointB, "jointB");
    const int bodyA = jointA.bodyB, bodyB = jointB.bodyB;
    const Vec2 anchorA = jointA.localAnchorB, anchorB = jointB.localAnchorB;
    if (bodyA == bodyB) throw Error("GearJointDef: the two joints move the same body");
    Joint& j = addJoint(w, JointType::Gear, bodyIdAt(w, bodyA), bodyIdAt(w, bodyB), anchorA, anchorB, 0.0f,
                        def.collideConnected, def.userData);
    GearJoint& g = j.data.emplace<GearJoint>();
    g.sideA = sideA;
    g.sideB = sideB;
    g.ratio = def.ratio;
    g.constant = sideA.coordinate + def.ratio * sideB.coordinate;
    return j;
}

void prepareGear(PreparedJoint& j, const StepContext& ctx, const Body& a, const Body& b) {
    GearJoint& g = j.data.as<GearJoint>();
    g.sideA.coordinate = coordinateAt(g.sideA, a, j.anchorA);
    g.sideB.coordinate = coordinateAt(g.sideB, b, j.anchorB);
    const BodyState still{};
    g.mass = effectiveMass(j.mass, gearRow(g, sideNow(g.sideA, still, 0.0f, j.anchorA), sideNow(g.sideB, still, 0.0f, j.anchorB)));
    if (!ctx.enableWarmStarting) g.impulse = 0.0f;
}

void warmStartGear(PreparedJoint& j, JointPair& p) {
    const GearJoint& g = j.data.as<GearJoint>();
    applyRow(p, gearRow(g, sideNow(g.sideA, p.a, p.rotationA, j.anchorA), sideNow(g.sideB, p.b, p.rotationA + p.rotation, j.anchorB)),
             g.impulse);
}

void solveGear(PreparedJoint& j, JointPair& p, const StepContext& ctx, bool useBias) {
    GearJoint& g = j.data.as<GearJoint>();
    const SideNow a = sideNow(g.sideA, p.a, p.rotationA, j.anchorA), b = sideNow(g.sideB, p.b, p.rotationA + p.rotation, j.anchorB);
    const float C = a.coordinate + g.ratio * b.coordinate - g.constant;
    solveRow(p, gearRow(g, a, b), g.mass, C, rigidSoftness(ctx, useBias), g.impulse);
}

// On B: a torque for a revolute side, a force along the axis for a prismatic one.
JointReaction reactionGear(const JointData& data) {
    const GearJoint& g = data.as<GearJoint>();
    const float impulse = g.ratio * g.impulse;
    if (g.sideB.kind == JointType::Revolute) return {{}, impulse};
    return {impulse * g.sideB.axis, 0.0f};
}

template JointId World::createJoint(const GearJointDef&);
extern const JointKind gearKind = jointKind<GearJoint>({prepareGear, warmStartGear, solveGear, reactionGear});

}  // namespace perpdot
