// The World's internals: the pools of bodies and shapes (pool.hpp), the contact cache
// (contact_cache.hpp), the joint store (joint_store.hpp), the collision system, events, and the
// step's working arrays (step_scratch.hpp).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "collide/collision.hpp"
#include "core/contact_cache.hpp"
#include "core/contact_solver_wide.hpp"
#include "core/graph_color.hpp"
#include "core/joint.hpp"
#include "core/pool.hpp"
#include "core/step_context.hpp"
#include "core/step_scratch.hpp"
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

// The geometry checks of createShape (shape.cpp), also run on restored snapshots: Error if invalid.
void validateGeometry(const Circle& circle);
void validateGeometry(const Polygon& polygon);
void validateGeometry(const Segment& segment);
void validateGeometry(const Chain& chain);
void validateGeometry(const Capsule& capsule);

struct World::Impl {
    WorldDef def;
    Pool<Body> bodies;
    Pool<ShapeData> shapes;
    ContactCache contactCache;
    std::vector<int> movedProxies;
    collide::CollisionSystem collision;
    JointStorePtr joints;
    Workers workers;  // the threads of the step's parallel stages
    bool locked = false;  // inside step()
    int frozenBodies = 0;  // bodies frozen because their state went non-finite (stats())

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

    StepScratch scratch;  // the step's working arrays

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

    // Shapes and broadphase (shape.cpp)
    int addShape(BodyId body, const ShapeDef& def);
    void createProxies(int shape);
    void destroyProxies(int shape);
    void synchronizeProxies(int body, Vec2 displacement);
    // Whether synchronizeProxies(body, displacement) would change no proxy (any thread, between tree updates).
    bool proxiesKeep(int body, Vec2 displacement) const;
    void noteFilter(const Filter& f) {
        shapeCategories |= f.category;
        shapeMasks |= f.mask;
    }
    // shouldCollide(f, g) is false for every shape's g: outside a positive group (which collides
    // whatever the masks), f's mask meets no category or f's category no mask.
    bool pairsWithNothing(const Filter& f) const {
        return f.group <= 0 && ((f.mask & shapeCategories) == 0 || (f.category & shapeMasks) == 0);
    }
    void beginEvents();                        // forget the events reported after the last step
    void reportTouch(const Contact& c, bool begin);  // begin/end event for a contact or sensor
    ContactData contactData(const Contact& c) const;

    // Stages of the step run by step.cpp (stages.hpp; sleep.cpp, continuous*.cpp)
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
