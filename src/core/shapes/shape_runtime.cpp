// Shapes changed at run time, as Box2D's b2Fixture setters change them: the filter, the sensor
// flag and user data; and the game's own collision rule (World::setShouldCollide).
#include <utility>

#include "core/contacts/contact_world.hpp"
#include "core/world/world_impl.hpp"

namespace perpdot {

namespace {

// The shape's proxies look for partners in the next step's pair update as new ones do: pairs
// whose boxes overlapped all along are found too.
void requeryShape(World::Impl& w, int shape) {
    for (int proxy : w.shapes[shape].proxies) {
        w.broadphase.collision.requery(proxy);
        w.broadphase.movedProxies.push_back(proxy);
    }
}

// Ends the shape's contacts for which `ends(contact)` (end events; the other bodies wake).
template <class Ends>
void endContactsOf(World::Impl& w, int shape, const Ends& ends) {
    const ContactCache& cache = w.contactCache;
    cache.bodyLists.forEach(cache.contacts, w.shapes[shape].body, [&](int index, int) {
        const Contact& c = cache.contacts[index];
        if ((c.a.shape != shape && c.b.shape != shape) || !ends(c)) return;
        if (c.touching) wakeIsland(w.bodies, c.bodyA == w.shapes[shape].body ? c.bodyB : c.bodyA);
        destroyContact(contactWorld(w), index);
    });
}

}  // namespace

void World::setFilter(ShapeId id, const Filter& filter) {
    Impl& w = *impl_;
    checkUnlocked(w.locked, "World::setFilter");
    ShapeData& s = w.shape(id);
    s.filter = filter;
    w.shapes.noteFilter(filter);
    endContactsOf(w, id.index, [&](const Contact& c) { return !shouldCollide(w.shapes[c.a.shape].filter, w.shapes[c.b.shape].filter); });
    requeryShape(w, id.index);
    wakeIsland(w.bodies, s.body);
}

void World::setSensor(ShapeId id, bool sensor) {
    Impl& w = *impl_;
    checkUnlocked(w.locked, "World::setSensor");
    ShapeData& s = w.shape(id);
    if (s.sensor == sensor) return;
    s.sensor = sensor;
    endContactsOf(w, id.index, [](const Contact&) { return true; });
    requeryShape(w, id.index);
    wakeIsland(w.bodies, s.body);
}

void World::setEnabled(ShapeId id, bool enabled) {
    Impl& w = *impl_;
    checkUnlocked(w.locked, "World::setEnabled");
    ShapeData& s = w.shape(id);
    if (s.enabled == enabled) return;
    s.enabled = enabled;
    if (enabled) {
        w.broadphase.createProxies(w.shapes, w.bodies, id.index);
    } else {
        endContactsOf(w, id.index, [](const Contact&) { return true; });
        w.broadphase.destroyProxies(w.shapes, id.index);
    }
    wakeIsland(w.bodies, s.body);
}

bool World::isEnabled(ShapeId id) const { return impl_->shape(id).enabled; }

void* World::userData(ShapeId id) const { return impl_->shape(id).userData; }
void World::setUserData(ShapeId id, void* userData) { impl_->shape(id).userData = userData; }

void World::setShouldCollide(ShouldCollideFn callback) {
    checkUnlocked(impl_->locked, "World::setShouldCollide");
    impl_->shouldCollide = std::move(callback);
}

}  // namespace perpdot
