// How the joint store plugs into the World and its solver loop.
#pragma once

#include <memory>
#include <utility>
#include <vector>

#include "core/world/step_context.hpp"
#include "perpdot/world.hpp"

namespace perpdot {

template <class T>
class Pool;
struct Body;  // body_store.hpp
struct JointStore;
struct JointStoreDeleter {
    void operator()(JointStore* store) const;
};
using JointStorePtr = std::unique_ptr<JointStore, JointStoreDeleter>;
JointStorePtr makeJointStore();
// The joints' per-step arrays (joint_store.hpp), for the step scratch.
struct JointScratch;
struct SolverBodies;  // step_scratch.hpp
struct SolverWorld;   // solver_world.hpp
struct ShapeStore;    // shape_store.hpp
struct Broadphase;    // broadphase.hpp
struct EventBuffers;  // event_buffers.hpp
struct WorldIdentity; // handle_check.hpp
class Workers;        // workers.hpp
struct JointScratchDeleter {
    void operator()(JointScratch* scratch) const;
};
using JointScratchPtr = std::unique_ptr<JointScratch, JointScratchDeleter>;
JointScratchPtr makeJointScratch();

// Solver stages, run by World::step (step.cpp, solver_stages.cpp) like the contact stages; they read
// the world through the solver's view (solver_world.hpp).
// prepareJoints: the awake joints, each prepared (anchors, effective masses) on the workers;
// colorJoints: then coloured, the joint trees found (and stiffened), and laid out in blocks and slots.
void prepareJoints(const SolverWorld& world, const StepContext& ctx);
void colorJoints(const SolverWorld& world, const StepContext& ctx);
// The work of colour `color` (below GraphColoring::overflow) in a pass: units that share no
// moving body, to be run in any order or side by side.
int jointUnitCount(const JointScratch& joints, int color);
void jointRows(JointScratch& joints, SolverBodies& bodies, const StepContext& ctx, RowPass pass, int color, int begin, int end);
// The joints no colour could take, then the joint trees: one after another.
int serialJointCount(const JointScratch& joints);
void serialJointRows(JointScratch& joints, SolverBodies& bodies, const StepContext& ctx, RowPass pass);
void storeJointImpulses(const SolverWorld& world, const StepContext& ctx);
// After the substeps: a Newton step on the positions of each joint tree (joint_tree.hpp).
void projectJoints(JointScratch& joints, SolverBodies& bodies);

// A joint's rows in a contact group's direct solve (contact_groups.hpp): row i measures
// Ċ = n·(vB − vA) + sB ωB − sA ωA with the arms at step start; λ is free on an equality row and
// λ ≥ 0 on a one-sided row (a limit, speculative while its C > 0).
struct DirectJointRow {
    Vec2 n;
    float sA = 0, sB = 0;
    bool oneSided = false;
};
constexpr int maxDirectJointRows = 4;  // a revolute joint's point rows and limits; a prismatic's perpendicular, angle and limits
int awakeJointCount(const JointScratch& joints);
std::pair<int, int> jointSlots(const JointScratch& joints, int k);  // of the k-th awake joint
// The rows of the k-th awake joint a direct solve takes (revolute, rigid weld and prismatic joints
// without a motor or break limits): their count, 0 for a joint that stays sequential.
int directJointRows(const JointScratch& joints, int k, DirectJointRow* rows);
// Their position errors C now, in the same order.
void directJointErrors(const JointScratch& joints, SolverBodies& bodies, int k, float* C);
// The k-th awake joint solved by a contact group this step: no colour, no tree, its λ the group's.
void solveJointDirectly(JointScratch& joints, int k);
// The accumulated λ of its row `row` (the warm start), and the group's λ written back.
float directJointImpulse(const JointScratch& joints, int k, int row);
void setDirectJointImpulse(JointScratch& joints, int k, int row, float impulse);

// What removing a joint touches besides its store: the bodies it wakes, and the broadphase, which
// looks again for the pairs of shapes the joint kept apart.
struct JointRemoval {
    JointStore& joints;
    Pool<Body>& bodies;
    const ShapeStore& shapes;
    Broadphase& broadphase;
};
JointRemoval jointRemoval(World::Impl& world);  // joint.cpp
void removeJoint(const JointRemoval& world, int joint);

// Reports in `events` (and removes, where asked) the joints whose reaction, averaged over the step
// (the joint scratch's stepImpulse), passed their break limits; run after storeJointImpulses.
void breakJoints(const JointRemoval& world, JointScratch& joints, EventBuffers& events, const WorldIdentity& identity,
                 Workers& workers, const StepContext& ctx);

// False when a joint between the two bodies has collideConnected == false.
bool jointAllowsCollision(const Pool<Body>& bodies, const JointStore& joints, int bodyA, int bodyB);
// Destroys every joint attached to the body (called before the body goes). Returns the joints
// (stale ids) and their userData where the world has a joint-destroyed callback, for destroyBody
// to call it once the body is gone; otherwise nothing.
std::vector<std::pair<JointId, void*>> destroyJointsOf(World::Impl& world, int body);
// Calls visit(bodyA, bodyB) for every joint, for islands.
void forEachJointPair(const JointStore& joints, void (*visit)(void* context, int bodyA, int bodyB), void* context);

}  // namespace perpdot
