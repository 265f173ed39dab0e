// The World's internals: pools of bodies, shapes and contacts addressed by generational ids,
// the collision system, and the per-step solver arrays.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "collide/collision.hpp"
#include "collide/pair_set.hpp"
#include "core/contact_groups.hpp"
#include "core/contact_solver_wide.hpp"
#include "core/graph_color.hpp"
#include "core/joint.hpp"
#include "core/solver_stages.hpp"
#include "core/step_context.hpp"
#include "core/workers.hpp"
#include "perpdot/error.hpp"
#include "perpdot/world.hpp"

namespace perpdot {

struct Body {
    uint32_t generation = 0;
    bool alive = false;
    BodyType type = BodyType::Static;
    Transform xf;          // origin frame
    float angle = 0;       // accumulated θ; xf.q = Rot(θ)
    Vec2 localCenter;      // centre of mass, body frame
    Vec2 center;           // centre of mass, world
    Vec2 v;                // velocity of the centre of mass
    float w = 0;           // angular velocity ω
    Vec2 force;            // accumulated this step
    float torque = 0;
    float mass = 0, invMass = 0;
    float inertia = 0, invInertia = 0;  // scalar I about the centre of mass
    float linearDamping = 0, angularDamping = 0, gravityScale = 1;
    bool fixedRotation = false, bullet = false, allowSleep = true, awake = true;
    float sleepTime = 0;
    void* userData = nullptr;
    std::vector<int> shapes;
    int contactHead = -1;  // first edge (contact*2 + side) of this body's contact list
    int solverIndex = 0;   // slot in StepContext::states during a step; 0 = static
    int jointCount = 0;    // joints attached (maintained by the joint store)
    int islandNext = -1;   // next body of the island it fell asleep with

    // The origin frame of the pose (θ, c): q = Rot(θ), x = c − R(θ)·localCenter.
    Transform derivedTransform() const {
        const Rot q = Rot::fromAngle(angle);
        return {center - rotate(q, localCenter), q};
    }
};

struct ShapeData {
    uint32_t generation = 0;
    bool alive = false;
    int body = -1;
    ShapeType type = ShapeType::Circle;
    using Geometry = std::variant<Circle, Polygon, Segment, Chain, Capsule>;  // index = ShapeType
    Geometry geometry;
    float density = 1, friction = 0.6f, restitution = 0;
    float rollingResistance = 0, tangentSpeed = 0;
    bool sensor = false;
    bool enableContactEvents = true, enableHitEvents = false, enableSensorEvents = true, enablePreSolveEvents = false;
    float minExtent = 0, maxExtent = 0;  // about the body origin, for continuous collision
    Filter filter;
    void* userData = nullptr;
    std::vector<int> proxies;  // broadphase proxy of each child
};

// The radius a shape's surface is rounded by (a circle's, a capsule's, a rounded polygon's), 0 for
// flat surfaces: these meet other shapes at their vertices, which are points of the body.
inline float roundingRadius(const ShapeData& s) {
    if (auto* c = std::get_if<Circle>(&s.geometry)) return c->radius;
    if (auto* p = std::get_if<Polygon>(&s.geometry)) return p->radius;
    if (auto* c = std::get_if<Capsule>(&s.geometry)) return c->radius;
    return 0.0f;
}

struct ContactPointState {
    Vec2 point;             // world, at the last narrowphase
    Vec2 anchorA, anchorB;  // from each body's centre of mass to the point
    float separation = 0;
    float normalImpulse = 0, tangentImpulse = 0, maxNormalImpulse = 0;
    uint32_t id = 0;
    float baseSeparation = 0;  // at the last narrowphase, for a kept manifold (manifold_reuse.hpp)
};

struct ContactEdge {
    int prev = -1, next = -1;  // edge keys (contact*2 + side) in the body's list
};

struct Contact {
    bool alive = false;
    bool touching = false;     // has manifold points and takes part in the solve (never for sensors)
    bool sensor = false;       // a sensor and a visitor: overlap test only, no constraint
    bool overlapping = false;  // sensor contacts: the shapes overlap
    uint64_t pairKey = 0;
    int proxyA = -1, proxyB = -1;
    collide::ChildKey a, b;
    int bodyA = -1, bodyB = -1;
    float friction = 0, restitution = 0;
    float rollingResistance = 0, tangentSpeed = 0;
    float rollingImpulse = 0;  // warm start of the rolling-resistance row
    Vec2 normal;
    int pointCount = 0;
    ContactPointState points[2];
    // The pose at the last narrowphase (manifold_reuse.hpp): B's centre in A's frame, both angles.
    bool reuseValid = false;
    Vec2 reuseOffset;
    float reuseAngleA = 0, reuseAngleB = 0;
    ContactEdge edges[2];  // in bodyA's list (side 0) and bodyB's (side 1)
};

// A contact's rows for this step (ContactRows<float>, contact_solver_wide.hpp) and where they
// came from: the bodies' solver slots and the contact.
struct ContactConstraint : ContactRows<float> {
    int indexA = 0, indexB = 0;  // solver slots
    int contact = -1;
    int pointCount = 0;
};

// Identity of a broadphase pair in World::Impl::pairs (never 0: the two proxies differ).
inline uint64_t proxyPairKey(int proxyA, int proxyB) {
    const auto lo = static_cast<uint32_t>(std::min(proxyA, proxyB));
    const auto hi = static_cast<uint32_t>(std::max(proxyA, proxyB));
    return (static_cast<uint64_t>(lo) << 32) | hi;
}

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
    float staticTime = 1;   // time of impact with static shapes (valid when !sweepStatic)
};

// Two movers of which at least one is a bullet, with their next time of impact.
struct MoverPair {
    int a = -1, b = -1;  // movers, a < b
    bool dirty = true;   // a path changed: the time of impact is to be recomputed
    float time = 1;
    collide::ChildKey keyA, keyB;  // the children that meet first
};

// A pair found by the broadphase this step, child keys in order (a < b).
struct NewPair {
    collide::ChildKey a, b;
    int proxyA = -1, proxyB = -1;
};

// The geometry checks of createShape (shape.cpp), also run on restored snapshots: Error if invalid.
void validateGeometry(const Circle& circle);
void validateGeometry(const Polygon& polygon);
void validateGeometry(const Segment& segment);
void validateGeometry(const Chain& chain);
void validateGeometry(const Capsule& capsule);

struct World::Impl {
    WorldDef def;
    std::vector<Body> bodies;
    std::vector<int> freeBodies;
    std::vector<ShapeData> shapes;
    std::vector<int> freeShapes;
    std::vector<Contact> contacts;
    std::vector<int> freeContacts;
    collide::PairSet pairs;  // broadphase pairs that have a contact
    std::vector<int> movedProxies;
    collide::CollisionSystem collision;
    JointStorePtr joints;
    Workers workers;  // the threads of the step's parallel stages
    bool locked = false;  // inside step()
    int frozenBodies = 0;  // bodies frozen because their state went non-finite (stats())
    std::vector<NewPair> newPairs;  // updatePairs scratch: the pairs found,
    std::vector<std::vector<NewPair>> newPairsOf;  // by each worker

    // Events of the last step (events.cpp). End events raised between steps (a destroyed shape)
    // are kept for the next step: the first `endEventsReported` entries are the stale ones.
    std::vector<ContactBeginTouchEvent> contactBeginEvents;
    std::vector<ContactEndTouchEvent> contactEndEvents;
    std::vector<ContactHitEvent> contactHitEvents;
    std::vector<JointBreakEvent> jointBreakEvents;
    std::vector<SensorBeginTouchEvent> sensorBeginEvents;
    std::vector<SensorEndTouchEvent> sensorEndEvents;
    size_t contactEndReported = 0, sensorEndReported = 0;
    PreSolveFn preSolve;
    bool anyHitEvents = false;  // a shape with enableHitEvents was ever created: look for hits
    // Every category and every mask bit of the shapes ever created (never cleared).
    uint16_t shapeCategories = 0, shapeMasks = 0;
    std::vector<Mover> movers;          // continuous_impacts.cpp scratch: fast bodies and what they may hit,
    std::vector<MoverPair> moverPairs;  // the pairs among them that include a bullet,
    std::vector<int> moverOfBody;       // and each body's mover (-1: none)

    // Solver arrays, rebuilt each step without reallocating.
    std::vector<BodyState> states;
    std::vector<int> awakeBodies;       // body index of states[i + 1]
    std::vector<uint8_t> touchingBodies;  // by body index: has a touching contact (integrateVelocities)
    std::vector<float> stepRotation;    // Δθ of states[i], summed over substeps
    std::vector<uint8_t> bodyMotion;    // finalizeBodies scratch, by awake body: its Motion (integrate.cpp)
    std::vector<SubstepForces> substepForces;  // of states[i]
    std::vector<ContactConstraint> constraints;
    std::vector<int> bouncingConstraints;        // the constraints with restitution, for its pass
    std::vector<std::array<int, 2>> constraintSlots;  // by constraint: its bodies' solver slots, for colouring
    GraphColoring contactColoring;               // colours of `constraints` (graph_color.hpp)
    std::vector<ContactBlock> contactBlocks;     // four constraints of one colour each, in colour order
    ColorStarts contactBlockStart{};             // colour c is contactBlocks[start[c] .. start[c + 1])
    std::vector<int> contactColors;              // prepareContactBlocks scratch: colour of each constraint,
    std::vector<int> contactOrder;               // and the constraints sorted by colour
    std::vector<int> overflowConstraints;        // constraints no colour could take: solved one by one
    ContactGroups contactGroups;                 // constraints solved a group at a time (contact_groups.hpp)
    SolverStages solverStages;                   // the substeps' stages for the workers
    std::vector<int> islandParent;      // union-find scratch for sleeping, by body index
    std::vector<float> islandMinSleep;
    std::vector<int> islandHead;

    Impl(const WorldDef& d);

    // Checked access: a stale or foreign id throws perpdot::Error.
    Body& body(BodyId id);
    const Body& body(BodyId id) const;
    ShapeData& shape(ShapeId id);
    const ShapeData& shape(ShapeId id) const;
    void checkUnlocked(const char* what) const;

    BodyId bodyId(int index) const { return {index, bodies[index].generation}; }
    ShapeId shapeId(int index) const { return {index, shapes[index].generation}; }

    // Bodies (body.cpp)
    void updateMass(int body);
    void wake(int body);  // wakes the body and the island it slept with

    // Shapes and broadphase (shape.cpp, contact_cache.cpp)
    int addShape(BodyId body, const ShapeDef& def);
    void createProxies(int shape);
    void destroyProxies(int shape);
    void synchronizeProxies(int body, Vec2 displacement);
    // Whether synchronizeProxies(body, displacement) would change no proxy (any thread, between tree updates).
    bool proxiesKeep(int body, Vec2 displacement) const;
    void updatePairs();
    void noteFilter(const Filter& f) {
        shapeCategories |= f.category;
        shapeMasks |= f.mask;
    }
    // shouldCollide(f, g) is false for every shape's g: outside a positive group (which collides
    // whatever the masks), f's mask meets no category or f's category no mask.
    bool pairsWithNothing(const Filter& f) const {
        return f.group <= 0 && ((f.mask & shapeCategories) == 0 || (f.category & shapeMasks) == 0);
    }
    // Whether two overlapping proxies may have a contact (bodies, sensors, shape types, filters,
    // joints); reads only, so the pair-finding workers ask it.
    bool pairWanted(int proxyA, int proxyB) const;
    void addPair(int proxyA, int proxyB);  // a contact for a wanted pair, unless it has one
    void updateContacts();
    // What collideContact found: not run (both bodies asleep), the fat AABBs apart, a sensor's
    // overlap, or a contact's manifold updated and whether it touched before.
    // Quiet: collided by the workers, and nothing is left for updateContacts' one-by-one pass.
    enum class Narrowphase : uint8_t { Skipped, Apart, Overlapping, Separate, WasTouching, WasNotTouching, Quiet };
    Narrowphase collideContact(int contact);
    bool isQuiet(const Contact& c, Narrowphase result) const;
    std::vector<Narrowphase> narrowphase;  // updateContacts scratch, by contact
    void destroyContact(int contact);
    void beginEvents();                        // forget the events reported after the last step
    void reportTouch(const Contact& c, bool begin);  // begin/end event for a contact or sensor
    ContactData contactData(const Contact& c) const;
    void destroyContactsOf(int body, int shape);  // shape = -1: all of the body's contacts

    // Stages of the step run by step.cpp (stages.hpp; contact_cache.cpp, sleep.cpp, continuous*.cpp)
    void updateSleep(float h);
    // Continuous collision (continuous.cpp): a body is fast when its move from (centre c0, angle
    // a0) to (c1, a1) may tunnel; solveContinuous sweeps it from its step-start pose (c0, a0) to
    // its current one and moves it back to the earliest time of impact.
    bool isFast(int body, Vec2 c0, float a0, Vec2 c1, float a1) const;
    void solveContinuous(int body, Vec2 c0, float a0);
    // The earliest time of impact in [0, 1] of the body's shapes along `sweep` with static shapes.
    float staticImpact(int body, const collide::Sweep& sweep) const;
    // Bullets against moving bodies (continuous_impacts.cpp): `movers` holds the fast bodies of
    // this step (bullets not yet synchronised); finds their impacts in time order, resolves each
    // with Hecker's collision impulse and moves the pair on for the rest of the step.
    void solveMovingImpacts(float h);
    void collectMoverPairs();
    void pairImpact(MoverPair& pair, float t) const;
    void resolveImpact(const MoverPair& pair, float t, float h);
};

// Contact solver stages (contact_solver.cpp, and contact_solver_wide.cpp for the rows solved in
// graph-coloured blocks of four).
void prepareContacts(World::Impl& world, const StepContext& ctx);
void prepareContactBlocks(World::Impl& world);
// The blocks of colour `color` (below GraphColoring::overflow) in a pass: they share no moving
// body, so they run in any order or side by side; then the overflow constraints, one by one.
int contactBlockCount(const World::Impl& world, int color);
void contactRows(World::Impl& world, const StepContext& ctx, RowPass pass, int color, int begin, int end);
void serialContactRows(World::Impl& world, const StepContext& ctx, RowPass pass);
void unpackContactBlocks(World::Impl& world);  // the blocks' accumulated impulses back into `constraints`
void applyRestitution(World::Impl& world, const StepContext& ctx);
void storeContactImpulses(World::Impl& world);
void reportHitEvents(World::Impl& world);

}  // namespace perpdot
