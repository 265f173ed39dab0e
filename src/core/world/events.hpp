// Contact, sensor and hit events raised by the step into the world's EventBuffers
// (event_buffers.hpp), and a contact as the game sees it (events.cpp).
#pragma once

#include "perpdot/world.hpp"

namespace perpdot {

struct Contact;         // contact_cache.hpp
struct ContactCache;    // contact_cache.hpp
struct ContactScratch;  // step_scratch.hpp
struct EventBuffers;    // event_buffers.hpp
struct ShapeStore;      // shape_store.hpp
struct WorldIdentity;   // handle_check.hpp

// The contact's shapes, normal and points, with the shape ids of the World of `identity`.
ContactData contactData(const ShapeStore& shapes, const WorldIdentity& identity, const Contact& c);
// The begin (or end) event of a contact or sensor, where its shapes ask for one.
void reportTouch(EventBuffers& events, const ShapeStore& shapes, const WorldIdentity& identity, const Contact& c, bool begin);
// The hit events of the step's contacts (`rows`, after the solve), those approaching faster than
// `threshold` (WorldDef::hitEventThreshold).
void reportHitEvents(EventBuffers& events, ContactScratch& rows, const ContactCache& cache, const ShapeStore& shapes,
                     const WorldIdentity& identity, float threshold);

}  // namespace perpdot
