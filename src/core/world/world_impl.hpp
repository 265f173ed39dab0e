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
#include "core/shapes/broadphase.hpp"
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
    Broadphase broadphase;
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

    BodyId bodyId(int index) const { return handleAt<BodyId>(bodies, index, identity); }
    ShapeId shapeId(int index) const { return handleAt<ShapeId>(shapes, index, identity); }

    // Bodies (body.cpp)
    void updateMass(int body);

    // Shapes (shape.cpp)
    int addShape(BodyId body, const ShapeDef& def);
};

}  // namespace perpdot
