// How the joint store plugs into the World and its solver loop.
#pragma once

#include <memory>
#include <utility>
#include <vector>

#include "core/world/step_context.hpp"
#include "perpdot/world.hpp"

namespace perpdot {

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
struct JointScratchDeleter {
    void operator()(JointScratch* scratch) const;
};
using JointScratchPtr = std::unique_ptr<JointScratch, JointScratchDeleter>;
JointScratchPtr makeJointScratch();

// Solver stages, run by World::step (step.cpp, solver_stages.cpp) like the contact stages; they read
// the world through the solver's view (solver_world.hpp).
// prepareJoints: the awake joints, each prepared (anchors, effective masses) on the workers;
// colorJoints: then coloured, the revolute trees found (and stiffened), and laid out in blocks and slots.
void prepareJoints(const SolverWorld& world, const StepContext& ctx);
void colorJoints(const SolverWorld& world, const StepContext& ctx);
// The work of colour `color` (below GraphColoring::overflow) in a pass: units that share no
// moving body, to be run in any order or side by side.
int jointUnitCount(const JointScratch& joints, int color);
void jointRows(JointScratch& joints, SolverBodies& bodies, const StepContext& ctx, RowPass pass, int color, int begin, int end);
// The joints no colour could take, then the revolute trees: one after another.
int serialJointCount(const JointScratch& joints);
void serialJointRows(JointScratch& joints, SolverBodies& bodies, const StepContext& ctx, RowPass pass);
void storeJointImpulses(const SolverWorld& world, const StepContext& ctx);
// After the substeps: a Newton step on the positions of each revolute tree (joint_tree.hpp).
void projectJoints(JointScratch& joints, SolverBodies& bodies);

// Reports (and destroys, where asked) the joints whose reaction, averaged over the step, passed
// their break limits; run after storeJointImpulses. A world stage: it removes joints, records
// events and wakes bodies, so it takes the hub.
void breakJoints(World::Impl& world, const StepContext& ctx);

// False when a joint between the two bodies has collideConnected == false.
bool jointAllowsCollision(const World::Impl& world, int bodyA, int bodyB);
// Destroys every joint attached to the body (called before the body goes). Returns the joints
// (stale ids) and their userData where the world has a joint-destroyed callback, for destroyBody
// to call it once the body is gone; otherwise nothing.
std::vector<std::pair<JointId, void*>> destroyJointsOf(World::Impl& world, int body);
// Calls visit(bodyA, bodyB) for every joint, for islands.
void forEachJointPair(const World::Impl& world, void (*visit)(void* context, int bodyA, int bodyB), void* context);

}  // namespace perpdot
