// The contact stages' view of the world: the parts updatePairs, updateContacts and the contact
// destroyers (contact_cache.cpp) read and write, and nothing else, built from a World by
// contactWorld (world.cpp). Its parts keep World::Impl's names; passed as `const ContactWorld&`,
// its parts are as writable as their references.
#pragma once

#include "core/base/pool.hpp"
#include "core/bodies/body_store.hpp"
#include "core/contacts/contact_cache.hpp"
#include "core/joints/joint.hpp"
#include "core/shapes/broadphase.hpp"
#include "core/shapes/shape_store.hpp"
#include "core/threads/workers.hpp"
#include "core/world/event_buffers.hpp"
#include "core/world/handle_check.hpp"
#include "perpdot/world.hpp"

namespace perpdot {

struct ContactWorld {
    Pool<Body>& bodies;  // their types and poses; sleepers a contact touches or leaves are woken
    const ShapeStore& shapes;
    ContactCache& contactCache;
    Broadphase& broadphase;  // the tree's pairs; its move buffer is emptied by updatePairs
    const JointStore& joints;  // joints whose bodies do not collide (jointAllowsCollision)
    EventBuffers& events;      // begin and end events
    const WorldDef& def;
    const WorldIdentity& identity;  // of the shape ids in events and callbacks
    Workers& workers;
    const PreSolveFn& preSolve;
    const ShouldCollideFn& shouldCollide;
};

// Stages of the step (step.cpp): new contacts for the pairs of proxies that moved (in the order
// of their child keys), then the narrowphase of every contact with an awake body, with begin and
// end events, the pre-solve callback and waking.
void updatePairs(const ContactWorld& world);
void updateContacts(const ContactWorld& world);

void destroyContact(const ContactWorld& world, int contact);  // with its end event
void destroyContactsOf(const ContactWorld& world, int body, int shape);  // shape = -1: all of the body's contacts

// The view of a World's parts (world.cpp), for step.cpp and the World calls that destroy contacts.
ContactWorld contactWorld(World::Impl& world);

}  // namespace perpdot
