// The joint store: a Pool<Joint> (pool.hpp: one contiguous vector, a free list, generations), and the
// joint types as the store sees them (JointKind, one per type in joint_registry.cpp): their solver
// stages, called through one table of function pointers (no virtual calls in the solve), and the
// type-erased handling of their data.
//
// A Joint is plain data (trivially copyable): the user's definition, the per-step solver
// values written by prepare, and the accumulated impulses kept for warm starting.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <type_traits>
#include <vector>

#include "core/bodies/edge_list.hpp"
#include "core/solver/graph_color.hpp"
#include "core/solver/lane_block.hpp"
#include "core/joints/joint.hpp"
#include "core/joints/joint_tree.hpp"
#include "core/base/pool.hpp"
#include "core/world/step_context.hpp"

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
    F rotation{};   // (θB − θA) turned since the step began (in SIMD lanes: set where the row set usesRotation)
    F rotationA{};  // θA turned since the step began (gear joints; not set in SIMD lanes)
};
using JointPair = JointPairT<float>;

// A joint type's data, a struct only its file names (joint_type.hpp; the revolute, weld,
// prismatic, wheel, distance and motor joints' joint_<type>.hpp share theirs with the tests, the
// trees and the gear joint): `type` in the Joint says which one lives here. The bytes start at zero; emplace<T>()
// starts a value-initialised T (createJoint, the snapshot reader), as<T>() is the live T. Both
// check that T fits and is trivially copyable, since the store copies joints bytewise (which
// carries the T along: C++20's implicit object creation).
// Strictly, as<T>() would std::launder its pointer; GCC then stops merging the loads of the
// gathers into joint lanes, and no compiler we build with needs it.
class JointData {
public:
    static constexpr size_t capacity = 68;  // bytes: the largest type's (the wheel joint's)

    template <class T>
    T& emplace() {
        check<T>();
        return *std::construct_at(reinterpret_cast<T*>(bytes_));
    }
    template <class T>
    T& as() {
        check<T>();
        return *reinterpret_cast<T*>(bytes_);
    }
    template <class T>
    const T& as() const {
        return const_cast<JointData&>(*this).as<T>();
    }

private:
    static constexpr size_t alignment = alignof(float);
    template <class T>
    static constexpr void check() {
        static_assert(sizeof(T) <= capacity, "a joint type's data must fit: raise JointData::capacity");
        static_assert(alignof(T) <= alignment, "a joint type's data must not need more than float alignment");
        static_assert(std::is_trivially_copyable_v<T>, "a joint type's data must be trivially copyable");
    }
    alignas(alignment) std::byte bytes_[capacity]{};
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
    bool breakable = false;  // it has break limits: solved alone, its substeps' impulses summed (breakJoints)
    int indexA = 0, indexB = 0;  // solver slots
    JointMass mass;
    Vec2 anchorA, anchorB;  // rA, rB: from each centre of mass to its anchor, at step start
    Vec2 deltaCenter;       // cB − cA at step start
    float deltaAngle = 0;   // θB − θA − referenceAngle at step start
    JointData data;
};

// A prepared joint as the serial passes of colorJoints read it (tree finding, colouring, lane
// assignment): 16 bytes a joint for them to stream, where a PreparedJoint is 124.
struct JointKey {
    int indexA = 0, indexB = 0;  // solver slots
    JointType type = JointType::Revolute;
    bool movesA = false, movesB = false;  // the side has mass or inertia (static, asleep or kinematic: not)
    bool treeJoint = false;  // an unbreakable revolute, prismatic or rigid weld joint: a tree may take it (joint_tree.hpp)
    bool limited = false;    // a revolute or prismatic joint with limits
    bool optionalRows = false;            // in lanes, rows others of its type lack (JointLaneStages)
};

// The rows' view of a prepared joint: its bodies' solver states a and b, and their turn this step.
inline JointPair pairOf(BodyState& a, BodyState& b, const std::vector<float>& stepRotation, const PreparedJoint& j) {
    return {a, b, j.mass, stepRotation[j.indexB] - stepRotation[j.indexA], stepRotation[j.indexA]};
}
inline JointPair pairOf(std::vector<BodyState>& states, const std::vector<float>& stepRotation, const PreparedJoint& j) {
    return pairOf(states[j.indexA], states[j.indexB], stepRotation, j);
}

// Impulses on B per substep, turned into force and torque by the caller (× 1/hs).
struct JointReaction {
    Vec2 linear;
    float angular = 0;
};

// Four joints of one type and one graph colour as the lanes of the type's row set (LaneBlock,
// lane_block.hpp; solved in joint_solver_wide.hpp), the head holding what the passes read besides
// the rows; item[l] is lane l's joint, -1 for an empty lane. Only item (read by store) comes after
// the rows, so that a pass reads only the fields its type gathered.
struct JointHead {
    JointMassT<simd::Float4> mass;
    int typeEnd = 0;  // where the colour's blocks of this type end (index in JointScratch::blocks)
    JointType type = JointType::Revolute;
    bool optionalRows = false;  // whether a lane's joint has rows others of its type lack
};
inline constexpr std::size_t jointRowCapacity = 21;  // floats of the largest row set (the prismatic joint's)
using JointBlock = LaneBlock<4, jointRowCapacity, JointHead>;

struct JointStore {
    Pool<Joint> joints;
    EdgeList bodyLists;  // each body's joints
    float invHs = 0;     // of the last step, for reaction forces
};

// The joints' per-step arrays, held by the step scratch (step_scratch.hpp) with the contacts' and
// kept, like them, when a snapshot is restored.
struct JointScratch {
    // The step's awake joints, prepared in store order: prepared[k] is joints[awake[k]].
    std::vector<int> awake;
    std::vector<PreparedJoint> prepared;
    std::vector<JointKey> keys;  // keys[k] of prepared[k]
    // The passes' order, colour by colour: colour c is blocks[blockStart[c] .. blockStart[c + 1])
    // four at a time (by type, in JointType's order), then prepared[scalarOrder[k]] for k in
    // [scalarStart[c], scalarStart[c + 1]) one at a time (the types that have no lanes, and every
    // joint no colour could take).
    std::vector<JointBlock> blocks;
    std::vector<int> scalarOrder;
    ColorStarts blockStart{}, scalarStart{};
    // Joint trees (joint_tree.hpp): solved directly after the colours, outside them.
    JointTrees trees;
    // Scratch of colorJoints, kept to reuse its memory.
    std::vector<int> colors;  // of prepared[k], from the step scratch's one colouring
    // Of prepared[k]: -1 solved alone, 0 in lanes with its type's rows alone, 1 in lanes with
    // optional rows (a motor, a limit).
    std::vector<int8_t> laneRows;
    std::vector<std::array<int, 4>> blockLanes;  // by block: its lanes' k in prepared, -1 empty
    std::vector<int> breaking;  // breakJoints: the joints over their break limits, in store order
    // Of prepared[k] where breakable: the impulses on B summed over the step's substeps (each
    // substep's accumulated λ after its relax pass), zero elsewhere.
    std::vector<JointReaction> stepImpulse;
    std::vector<uint8_t> direct;  // of prepared[k]: 1 where a contact group solves it (solveJointDirectly)
};

struct Body;  // body_store.hpp

// The common part of createJoint: checks the bodies, links the joint, wakes the bodies and,
// unless collideConnected, removes their contacts. Returns the new joint (type data unset).
Joint& addJoint(World::Impl& world, JointType type, BodyId bodyA, BodyId bodyB, Vec2 localAnchorA,
                Vec2 localAnchorB, float referenceAngle, bool collideConnected, void* userData);
JointId jointId(const World::Impl& world, const Joint& joint);
// A pulley's world ground anchors move by −newOrigin (World::shiftOrigin; joint_pulley.cpp).
void shiftPulleyGround(Joint& pulley, Vec2 newOrigin);
// The live joint of `id`; Error naming `call` (by default the caller) for a null, stale or foreign id.
Joint& checkedJoint(const World::Impl& world, JointId id, const char* call = __builtin_FUNCTION());
// The bodies as a joint type reads them when it creates a joint (the gear and mouse joints): the
// live body of `id` (Error naming `call` as checkedJoint does), the body at pool index `index` and
// its id.
const Body& checkedBody(const World::Impl& world, BodyId id, const char* call = __builtin_FUNCTION());
const Body& bodyAt(const World::Impl& world, int index);
BodyId bodyIdAt(const World::Impl& world, int index);
void requireFinite(bool ok, const char* what);  // Error "<what> must be finite" unless ok

// What the World's joint calls at run time (joint_settings.cpp) reach besides the joint itself
// (checkedJoint): the joint store, the bodies (their motion gives the joint coordinates; a changed
// joint wakes them) and whether the world is stepping.
struct JointWorld {
    JointStore& joints;
    Pool<Body>& bodies;
    bool locked;
};
JointWorld jointWorld(World::Impl& world);  // joint.cpp

// A joint type's solver stages. prepare runs after the common frame (anchors, masses, deltaCenter,
// deltaAngle) is set, with the two bodies as the step starts.
// lanes: the stages of the type's blocks of four (joint_solver_wide.hpp), null for a type solved
// one joint at a time.
struct JointLaneStages;
struct JointStages {
    void (*prepare)(PreparedJoint& joint, const StepContext& ctx, const Body& a, const Body& b);
    void (*warmStart)(PreparedJoint& joint, JointPair& pair);
    void (*solve)(PreparedJoint& joint, JointPair& pair, const StepContext& ctx, bool useBias);
    JointReaction (*reaction)(const JointData& data);  // the accumulated impulses on B of one substep
    const JointLaneStages* lanes = nullptr;
};

// A joint type as the store sees it: its stages and what the store and the snapshot do with its
// data. Built at the end of the type's joint_<type>.cpp by jointKind (joint_type.hpp) and listed
// in joint_registry.cpp.
class ByteWriter;
class ByteReader;
struct JointKind {
    JointStages stages;
    void (*write)(ByteWriter& out, const JointData& data);  // through its field list
    // Emplaces the type's data and reads the fields of a snapshot of in.version (format 1: the raw layout).
    void (*read)(ByteReader& in, JointData& data);
    float* (*motorSpeed)(JointData& data);  // for setMotorSpeed; null: the type has no motor
};
// How many joint types there are: JointType's last enumerator names it (a new type moves it there).
constexpr int jointTypeCount = static_cast<int>(JointType::Friction) + 1;

// The kind of `type`; null for a number that names no type (read from a snapshot).
const JointKind* kindOf(JointType type);
const JointStages& stagesOf(JointType type);  // of a type that exists

// For joint trees (joint_tree.cpp), which solve a joint's motor row before their block: that row of
// a revolute or prismatic joint, where it has a motor.
void solveRevoluteMotor(PreparedJoint& joint, JointPair& pair, const StepContext& ctx);
void solvePrismaticMotor(PreparedJoint& joint, JointPair& pair, const StepContext& ctx);

}  // namespace perpdot
