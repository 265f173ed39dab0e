// The joint store: a Pool<Joint> (pool.hpp: one contiguous vector, a free list, generations), and the
// per-type entry points that joint.cpp dispatches to by switch (no virtual calls in the solve).
//
// A Joint is plain data (trivially copyable): the user's definition, the per-step solver
// values written by prepare, and the accumulated impulses kept for warm starting.
#pragma once

#include <array>
#include <limits>
#include <memory>
#include <type_traits>
#include <vector>

#include "core/edge_list.hpp"
#include "core/graph_color.hpp"
#include "core/joint.hpp"
#include "core/joint_tree.hpp"
#include "core/pool.hpp"
#include "core/softness.hpp"
#include "core/step_context.hpp"

namespace perpdot {

// Inverse masses and inverse rotational inertias of the joint's two bodies, over a lane type F
// (lanes.hpp): float for one joint, simd::Float4 for four.
template <class F>
struct JointMassT {
    F mA{}, iA{}, mB{}, iB{};
};
using JointMass = JointMassT<float>;

// The two bodies of a joint inside one substep.
template <class F>
struct JointPairT {
    BodyLanes<F>& a;
    BodyLanes<F>& b;
    JointMassT<F> m;
    F rotation{};   // (θB − θA) turned since the step began
    F rotationA{};  // θA turned since the step began (gear joints; not set in SIMD lanes)
};
using JointPair = JointPairT<float>;

struct RevoluteJoint {
    bool enableLimit = false, enableMotor = false;
    float lowerAngle = 0, upperAngle = 0;
    float motorSpeed = 0, maxMotorTorque = 0;
    float axialMass = 0;  // 1 / (1/IA + 1/IB)
    Vec2 linearImpulse;   // point rows
    float motorImpulse = 0, lowerImpulse = 0, upperImpulse = 0;
};

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

struct DistanceJoint {
    float length = 1, minLength = 0, maxLength = 0;
    float hertz = 0, dampingRatio = 0;
    Softness spring;
    Vec2 axis;            // B's anchor from A's, unit, at step start
    float axialMass = 0;
    float impulse = 0, lowerImpulse = 0, upperImpulse = 0;
};

struct WeldJoint {
    float hertz = 0, dampingRatio = 0;  // soft in the angle only, like Box2D 2.4's weld
    Softness angularSoftness;
    float axialMass = 0;
    Vec2 linearImpulse;
    float angularImpulse = 0;
};

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

struct MotorJoint {
    float maxForce = 0, maxTorque = 0, correctionFactor = 0;
    float axialMass = 0;
    Vec2 linearImpulse;
    float angularImpulse = 0;
};

// The target is anchor A (fixed in the world during a step: A is meant to be static).
struct MouseJoint {
    float hertz = 0, dampingRatio = 0, maxForce = 0;
    Softness softness;
    Vec2 linearImpulse;
};

// One side of a gear: the coordinate of a revolute joint, θ − offset, or of a prismatic joint,
// axis·anchor − offset (= axis·(anchor − base)), whose body A is static, so axis and offset are fixed.
struct GearSide {
    JointType kind = JointType::Revolute;
    Vec2 axis;             // prismatic: world
    float offset = 0;      // revolute: θ of the static body + the joint's reference angle; prismatic: axis·base
    float coordinate = 0;  // at step start
};

// coordinateA + ratio·coordinateB = constant (joint_gear.cpp).
struct GearJoint {
    GearSide sideA, sideB;
    float ratio = 1, constant = 0;
    float mass = 0;
    float impulse = 0;
};

// lengthA + ratio·lengthB = constant, length = |anchor − ground anchor| (joint_pulley.cpp).
struct PulleyJoint {
    Vec2 groundA, groundB;   // world
    float ratio = 1, constant = 0;
    Vec2 fromGroundA, fromGroundB;  // centre of mass − ground anchor, at step start
    Vec2 uB;                 // B's rope direction (ground to anchor) at step start, for the reaction
    float mass = 0;
    float impulse = 0;
};

// Type-specific data; `type` in the Joint says which member is live (createJoint starts its
// lifetime with std::construct_at, value-initialised).
union JointData {
    RevoluteJoint revolute;
    PrismaticJoint prismatic;
    DistanceJoint distance;
    WeldJoint weld;
    WheelJoint wheel;
    MotorJoint motor;
    MouseJoint mouse;
    GearJoint gear;
    PulleyJoint pulley;
    JointData() : revolute{} {}
};

struct Joint {
    uint32_t generation = 0;
    bool alive = false;
    bool collideConnected = false;
    JointType type = JointType::Revolute;
    int bodyA = -1, bodyB = -1;
    Edge edges[2];             // in bodyA's list (side 0) and bodyB's (side 1): JointStore::bodyLists
    Vec2 localAnchorA, localAnchorB;  // in each body's origin frame
    float referenceAngle = 0;  // θB − θA at zero joint angle (motor joint: angularOffset)
    // Break limits (World::setJointBreakLimits): reaction force N and torque N·m; infinity never breaks.
    float breakForce = std::numeric_limits<float>::infinity(), breakTorque = std::numeric_limits<float>::infinity();
    bool destroyOnBreak = false;
    void* userData = nullptr;
    JointData data;
};
static_assert(std::is_trivially_copyable_v<Joint>, "the joint store is snapshotted bytewise");

// A joint as the substep passes see it, written by prepareJoints: the solver slots, the frame at
// step start and a working copy of the type data (its impulses go back to the Joint at the end
// of the step). Packed contiguously so that each pass streams only this, not the whole Joint.
struct PreparedJoint {
    JointType type = JointType::Revolute;
    int indexA = 0, indexB = 0;  // solver slots
    JointMass mass;
    Vec2 anchorA, anchorB;  // rA, rB: from each centre of mass to its anchor, at step start
    Vec2 deltaCenter;       // cB − cA at step start
    float deltaAngle = 0;   // θB − θA − referenceAngle at step start
    JointData data;
};

// The rows' view of a prepared joint: its bodies' solver states a and b, and their turn this step.
inline JointPair pairOf(BodyState& a, BodyState& b, const std::vector<float>& stepRotation, const PreparedJoint& j) {
    return {a, b, j.mass, stepRotation[j.indexB] - stepRotation[j.indexA], stepRotation[j.indexA]};
}
inline JointPair pairOf(std::vector<BodyState>& states, const std::vector<float>& stepRotation, const PreparedJoint& j) {
    return pairOf(states[j.indexA], states[j.indexB], stepRotation, j);
}

struct RevoluteBlock;  // four revolute joints in SIMD lanes (joint_solver_wide.hpp)

struct JointStore {
    Pool<Joint> joints;
    EdgeList bodyLists;                  // each body's joints
    // The step's awake joints, prepared in store order: prepared[k] is joints[awake[k]].
    std::vector<int> awake;
    std::vector<PreparedJoint> prepared;
    // The passes' order, colour by colour: colour c is revoluteBlocks[blockStart[c] .. blockStart[c + 1])
    // four at a time, then prepared[scalarOrder[k]] for k in [scalarStart[c], scalarStart[c + 1])
    // one at a time (the other joints, and every joint no colour could take).
    std::vector<RevoluteBlock> revoluteBlocks;
    std::vector<int> scalarOrder;
    ColorStarts blockStart{}, scalarStart{};
    // Revolute trees (joint_tree.hpp): solved directly after the colours, outside them.
    RevoluteTrees trees;
    // Scratch of prepareJoints, kept to reuse its memory.
    GraphColoring coloring;
    std::vector<int> colors;  // of prepared[k]
    std::vector<std::array<int, 4>> blockLanes;  // by revolute block: its lanes' k in prepared, -1 empty
    std::vector<int> breaking;  // breakJoints: the joints over their break limits, in store order
    float invHs = 0;                     // of the last step, for reaction forces
};

// Impulses on B per substep, turned into force and torque by the caller (× 1/hs).
struct JointReaction {
    Vec2 linear;
    float angular = 0;
};

// The common part of createJoint: checks the bodies, links the joint, wakes the bodies and,
// unless collideConnected, removes their contacts. Returns the new joint (type data unset).
Joint& addJoint(World::Impl& world, JointType type, BodyId bodyA, BodyId bodyB, Vec2 localAnchorA,
                Vec2 localAnchorB, float referenceAngle, bool collideConnected, void* userData);
JointId jointId(const World::Impl& world, const Joint& joint);
// The live joint of `id`; Error for a stale or invalid id.
Joint& checkedJoint(const World::Impl& world, JointId id);
void requireFinite(bool ok, const char* what);  // Error "<what> must be finite" unless ok

// A joint type's solver stages, defined at the end of its joint_<type>.cpp and listed in
// joint_registry.cpp. prepare runs after the common frame (anchors, masses, deltaCenter,
// deltaAngle) is set, with the two bodies as the step starts.
struct Body;
struct JointStages {
    void (*prepare)(PreparedJoint& joint, const StepContext& ctx, const Body& a, const Body& b);
    void (*warmStart)(PreparedJoint& joint, JointPair& pair);
    void (*solve)(PreparedJoint& joint, JointPair& pair, const StepContext& ctx, bool useBias);
    JointReaction (*reaction)(const Joint& joint);
};
const JointStages& stagesOf(JointType type);

// The revolute joint's rows one at a time, also for revolute trees that do not factor.
void warmStartRevolute(PreparedJoint& joint, JointPair& pair);
void solveRevolute(PreparedJoint& joint, JointPair& pair, const StepContext& ctx, bool useBias);

}  // namespace perpdot
