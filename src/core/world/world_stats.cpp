// World::stats(): live counts, pool sizes and the frozen-body counter, for soak tests and tools.
#include "core/world/world_impl.hpp"

namespace perpdot {

WorldStats World::stats() const {
    const Impl& w = *impl_;
    WorldStats s;
    s.bodySlots = w.bodies.capacity();
    s.shapeSlots = w.shapes.capacity();
    s.contactSlots = w.contactCache.contacts.capacity();
    s.bodies = w.bodies.size();
    s.shapes = w.shapes.size();
    s.contacts = w.contactCache.contacts.size();
    s.frozenBodies = w.frozenBodies;
    return s;
}

}  // namespace perpdot
