// The step's working arrays (step scratch): filled by the stages of World::step (stages.hpp) and
// read only within a step, kept from one step to the next so that they are rebuilt without
// reallocating. A snapshot holds none of them.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "collide/collision.hpp"
#include "core/solver/contact_groups.hpp"
#include "core/solver/contact_solver_wide.hpp"
#include "core/solver/graph_color.hpp"
#include "core/solver/impact_propagation.hpp"
#include "core/joints/joint.hpp"
#include "core/solver/solver_stages.hpp"
#include "core/world/step_context.hpp"

namespace perpdot {

// A contact's constraint for this step: where it came from (the contact, the bodies' solver
// slots) and where its rows are (ContactRows<float>, contact_solver_wide.hpp): a lane of a block
// (ContactScratch::blocks or blocks8), or its own rows in ContactScratch::constraintRows when it has no
// colour (overflow, contact groups). Kept small: the blocks' preparation reads these in colour order.
struct ContactConstraint {
    int indexA = 0, indexB = 0;  // solver slots
    int contact = -1;
    int pointCount = 0;
};

// A body's path over the rest of a step, for continuous collision between moving bodies
// (continuous_impacts.cpp): centre of mass and angle go linearly from (c0, a0) at time t0 to
// (c1, a1) at the step's end; times are fractions of the step.
struct Mover {
    int body = -1;
    float t0 = 0;
    Vec2 c0, c1;
    float a0 = 0, a1 = 0;
    Vec2 v;      // velocity along the path
    float w = 0;
    Vec2 stepStart;  // centre at the step's start: the broadphase displacement
    AABB swept;      // of its shapes over the whole step (fast movers)
    bool fast = false;      // found fast by isFast (else: met by a fast mover)
    bool sweepStatic = false;  // its path still has to be swept against static shapes
    bool moved = false;     // its path differs from what finalizeBodies wrote to the body
    bool frozen = false;    // an impact's impulse overflowed: it stopped there and is frozen at the end
    float staticTime = 1;   // time of impact with static shapes (valid when !sweepStatic)
};

// Two movers of which at least one is a bullet, with their next time of impact.
struct MoverPair {
    int a = -1, b = -1;  // movers, a < b
    bool dirty = true;   // a path changed: the time of impact is to be recomputed
    float time = 1;
    collide::ChildKey keyA, keyB;  // the children that meet first
};

// A body's centre of mass and angle.
struct BodyPose {
    Vec2 center;
    float angle = 0;
};

// A proxy's leaf to move in place, and the fat AABB it moves to (proxy -1: none).
struct InPlaceMove {
    int proxy = -1;
    AABB fat;
};

// A body's pose predicted for the step's end from its velocity, and whether its proxies re-fit to
// it while the step is solved (refit_ahead.cpp).
struct PredictedPose {
    Transform xf;
    Vec2 center, displacement;
    bool refit = false;
    InPlaceMove inPlace;  // where refit and the body has one proxy, which moves in place
};

// The solver's view of the awake bodies, by solver slot (slot 0: every body that cannot move).
struct SolverBodies {
    std::vector<BodyState> states;
    std::vector<int> awakeBodies;       // body index of states[i + 1]
    // By body index: its slot in states, 0 for a body outside the solver (static or asleep).
    // Dense, so that selecting the step's constraints reads 4 bytes per body, not a Body's line.
    std::vector<int> bodySlots;
    std::vector<uint8_t> touchingBodies;  // by body index: has a touching contact (integrateVelocities)
    std::vector<float> stepRotation;    // Δθ of states[i], summed over substeps
    std::vector<uint8_t> bodyMotion;    // finalizeBodies scratch, by awake body: its Motion (integrate.cpp)
    std::vector<PredictedPose> predictedPoses;  // by awake body
    std::vector<BodyPose> stepStarts;           // finalizeBodies scratch, by awake body: a fast body's pose before the step
    std::vector<SubstepForces> substepForces;  // of states[i]
    std::vector<float> inverseInertias;        // 1/I of states[i] (slot 0: 0), dense for gathering rows (1/m is in the states)
    std::vector<BodyState> freeVelocities;     // of states[i]: v and ω at the step's end without contacts (contact_solver.cpp)
};

// seedSupportLoads scratch (support_sinks.hpp).
struct SupportScratch {
    enum : uint8_t { None, AllNew, Carrying };
    std::vector<uint8_t> seeded;      // by constraint: 1 where its rows were seeded this step
    std::vector<int> supported;       // by constraint: the solver slot of the body it supports, 0 for none
    std::vector<uint8_t> supports;    // by solver slot: None, AllNew (seeded this step) or Carrying
    std::vector<int> start, fill, rows;  // the seeded bodies' support constraints, slot by slot
    std::vector<int> order;           // the seeded bodies, from the top down
    std::vector<float> load, moment;  // by slot: what a seeded body carries, and its moment about the centre
    // Room for a step of `constraints` and `slots`, taken every step: storage grows only as the
    // world does, not in the first step that seeds a body (a step then allocates nothing).
    void reserve(size_t constraints, size_t slots) {
        for (auto* v : {&supported, &rows}) v->reserve(constraints);
        for (auto* v : {&start, &fill}) v->reserve(slots + 1);
        order.reserve(slots);
        supports.reserve(slots);
        for (auto* v : {&load, &moment}) v->reserve(slots);
    }
};

// The step's contact constraints and where their rows live: blocks by colour, or one by one.
struct ContactScratch {
    std::vector<ContactConstraint> constraints;
    Impacts impacts;                           // propagateImpacts scratch: the elastic points between moving bodies
    std::vector<ContactRows<float>> constraintRows;  // by constraint: the rows of those outside the blocks
    std::vector<std::array<int, 2>> constraintSlots;  // by constraint: its bodies' solver slots, for colouring
    int lanes = chooseContactLanes();        // constraints per block: 4, or 8 with AVX2
    std::vector<ContactBlock<4>> blocks;     // four constraints of one colour each, in colour order,
    std::vector<ContactBlock<8>> blocks8;    // or eight (lanes = 8)
    ColorStarts blockStart{};                // colour c is blocks[start[c] .. start[c + 1])
    std::vector<int> colors;                 // prepareContactBlocks scratch: colour and slot bucket of each constraint,
    std::vector<int> order;                  // and the constraints sorted by them (graph_color.hpp),
    ColorStarts colorStart{};                // colour c at order[start[c] .. start[c + 1])
    std::vector<int> rowSlot;                // by constraint, for hit events (locateContactRows)
    std::vector<int> overflow;               // constraints no colour could take: solved one by one
    ContactGroups groups;                    // constraints solved a group at a time (contact_groups.hpp)
    SupportScratch support;
};

// Union-find scratch for sleeping, by body index (sleep.cpp).
struct IslandScratch {
    std::vector<int> parent;
    std::vector<float> minSleep;
    std::vector<int> head;
};

// Continuous collision between moving bodies (continuous_impacts.cpp).
struct MoverScratch {
    std::vector<Mover> movers;          // fast bodies and what they may hit,
    std::vector<MoverPair> pairs;       // the pairs among them that include a bullet,
    std::vector<int> moverOfBody;       // and each body's mover (-1: none)
};

// The step's working arrays by owner. Contacts and joints share one colouring (one constraint graph).
struct StepScratch {
    SolverBodies bodies;
    ContactScratch contacts;
    JointScratchPtr joints = makeJointScratch();  // the joints' prepared rows, blocks and colours (joint_store.hpp)
    GraphColoring coloring;  // the colours of joints, then of contacts.constraints (graph_color.hpp)
    SolverStages solverStages;  // the substeps' stages for the workers
    IslandScratch islands;
    MoverScratch continuous;
};

}  // namespace perpdot
