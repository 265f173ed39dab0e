// The World's internals: the pools of bodies and shapes (pool.hpp), the contact cache
// (contact_cache.hpp), the joint store (joint_store.hpp), the collision system, events, and the
// step's working arrays (step_scratch.hpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "collide/collision.hpp"
#include "core/bodies/body_store.hpp"
#include "core/shapes/box_room.hpp"
#include "core/contacts/contact_cache.hpp"
#include "core/world/event_buffers.hpp"
#include "core/world/handle_check.hpp"
#include "core/joints/joint.hpp"
#include "core/shapes/shape_store.hpp"
#include "core/world/step_scratch.hpp"
#include "core/threads/workers.hpp"
#include "perpdot/error.hpp"
#include "perpdot/world.hpp"

namespace perpdot {

struct World::Impl {
    WorldDef def;
    // This World's identity, carried by the handles it issues (ids.hpp, handle_check.hpp).
    WorldIdentity identity;
    // The owned parts (docs/architecture.md): the stores, the broadphase with its move buffer,
    // and the step's working arrays.
    Pool<Body> bodies;
    ShapeStore shapes;
    ContactCache contactCache;
    std::vector<BoxRoom> boxRooms;  // by body index: where its boxes were last measured (refit_ahead.cpp)
    std::vector<int> movedProxies;  // proxies that left their fat AABB (or are new): updatePairs looks for their pairs
    collide::CollisionSystem collision;
    JointStorePtr joints;
    StepScratch scratch;
    Workers workers;  // the threads of the step's parallel stages
    bool locked = false;  // inside step()
    int frozenBodies = 0;  // bodies frozen because their state went non-finite (stats())

    EventBuffers events;  // of the last step (event_buffers.hpp, events.cpp)
    PreSolveFn preSolve;
    JointDestroyedFn jointDestroyed;  // World::setJointDestroyedCallback: called by destroyBody
    ShouldCollideFn shouldCollide;  // World::setShouldCollide, asked by addPair (contact_cache.cpp)
    // The state the last restore replaced (snapshot.cpp): the next restore reads into its pools' memory.
    std::unique_ptr<Impl> spare;

    Impl(const WorldDef& d);

    // Checked access: a null, stale or foreign id throws perpdot::Error naming `call`, by default
    // the World call this is called from (handle_check.hpp).
    Body& body(BodyId id, const char* call = __builtin_FUNCTION());
    const Body& body(BodyId id, const char* call = __builtin_FUNCTION()) const;
    ShapeData& shape(ShapeId id, const char* call = __builtin_FUNCTION());
    const ShapeData& shape(ShapeId id, const char* call = __builtin_FUNCTION()) const;
    void checkUnlocked(const char* what) const;

    BodyId bodyId(int index) const { return {index, bodies[index].generation, identity.issued}; }
    ShapeId shapeId(int index) const { return {index, shapes[index].generation, identity.issued}; }

    // Bodies (body.cpp)
    void updateMass(int body);
    void wake(int body);  // wakes the body and the island it slept with
    // A body whose motion went non-finite, frozen where it is instead of spreading NaN: stopped,
    // asleep until something wakes it, and counted in stats().frozenBodies.
    void freeze(int body);

    // Shapes and broadphase (shape.cpp)
    int addShape(BodyId body, const ShapeDef& def);
    void createProxies(int shape);
    void destroyProxies(int shape);
    // Re-fit every proxy of the body to transform xf (as b2DynamicTree::MoveProxy decides); its
    // box room is forgotten. Proxies that left their fat AABB are queried for pairs next step.
    void synchronizeProxies(int body, const Transform& xf, Vec2 displacement);
    // Re-fit one proxy to `aabb` if it left its fat AABB (collision.moveProxy), and queue it for
    // updatePairs once.
    void refitProxy(int proxy, const AABB& aabb, Vec2 displacement);
    // Moves an escaped proxy's leaf in place to `fat` (collision.inPlaceFat's), queued as refitProxy does.
    void moveInPlace(int proxy, const AABB& fat);
    // Its shapes, proxies or centre of mass changed: its box room (box_room.hpp) is not known.
    void forgetBoxRoom(int body);
    void reportTouch(const Contact& c, bool begin);  // begin/end event for a contact or sensor
    ContactData contactData(const Contact& c) const;
};

// The hit events of the step's contacts, from their rows after the solve (events.cpp).
void reportHitEvents(World::Impl& world);

}  // namespace perpdot
