// World::stats(): live counts, pool sizes and the frozen-body counter, for soak tests and tools.
#include "core/world_impl.hpp"

namespace perpdot {

WorldStats World::stats() const {
    const Impl& w = *impl_;
    WorldStats s;
    s.bodySlots = static_cast<int>(w.bodies.size());
    s.shapeSlots = static_cast<int>(w.shapes.size());
    s.contactSlots = static_cast<int>(w.contacts.size());
    s.bodies = s.bodySlots - static_cast<int>(w.freeBodies.size());
    s.shapes = s.shapeSlots - static_cast<int>(w.freeShapes.size());
    s.contacts = s.contactSlots - static_cast<int>(w.freeContacts.size());
    s.frozenBodies = w.frozenBodies;
    return s;
}

}  // namespace perpdot
