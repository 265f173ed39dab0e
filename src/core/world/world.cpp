// World construction, settings, its counts, read-only views of the contact cache and the events,
// the origin shift, and the views of the world its other files read (QueryWorld, ContactWorld).
#include "core/contacts/contact_world.hpp"
#include "core/queries/query_world.hpp"
#include "core/world/events.hpp"
#include "core/world/shift_origin.hpp"
#include "core/world/world_impl.hpp"

namespace perpdot {

World::World(const WorldDef& def) : impl_(std::make_unique<Impl>(def)) {}
World::~World() = default;
World::World(World&&) noexcept = default;
World& World::operator=(World&&) noexcept = default;

const WorldDef& World::settings() const { return impl_->def; }

bool World::isLocked() const { return impl_->locked; }

void World::setJointDestroyedCallback(JointDestroyedFn callback) { impl_->jointDestroyed = std::move(callback); }

void World::setGravity(Vec2 gravity) {
    checkUnlocked(impl_->locked, "setGravity");
    if (!isFinite(gravity)) throw Error("setGravity: gravity must be finite");
    impl_->def.gravity = gravity;
}

void World::setSubsteps(int substeps) {
    checkUnlocked(impl_->locked, "setSubsteps");
    if (substeps < 1 || substeps > 64) throw Error("setSubsteps: substeps must be 1..64");
    impl_->def.substeps = substeps;
}

int World::contactCount() const {
    int count = 0;
    impl_->contactCache.contacts.forEachLive([&](int, const Contact& c) { count += c.touching; });
    return count;
}

std::vector<ContactData> World::contacts() const {
    std::vector<ContactData> out;
    impl_->contactCache.contacts.forEachLive([&](int, const Contact& c) {
        if (c.touching) out.push_back(contactData(impl_->shapes, impl_->identity, c));
    });
    return out;
}

void World::shiftOrigin(Vec2 newOrigin) {
    Impl& w = *impl_;
    checkUnlocked(w.locked, "World::shiftOrigin");
    if (!isFinite(newOrigin)) throw Error("World::shiftOrigin: the new origin must be finite");
    perpdot::shiftOrigin(w.bodies, w.contactCache, *w.joints, w.broadphase, newOrigin);
}

// Live counts, pool sizes and the frozen-body counter, for soak tests and tools.
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

QueryWorld queryWorld(const World::Impl& w) {
    return {.collision = w.broadphase.collision,
            .shapes = w.shapes,
            .bodies = w.bodies,
            .contactCache = w.contactCache,
            .identity = w.identity,
            .locked = w.locked};
}

ContactEvents World::contactEvents() const {
    return {impl_->events.contactBegin, impl_->events.contactEnd, impl_->events.contactHit};
}

SensorEvents World::sensorEvents() const { return {impl_->events.sensorBegin, impl_->events.sensorEnd}; }

JointEvents World::jointEvents() const { return {impl_->events.jointBreak}; }

void World::setPreSolve(PreSolveFn callback) {
    checkUnlocked(impl_->locked, "setPreSolve");
    impl_->preSolve = std::move(callback);
}

ContactWorld contactWorld(World::Impl& w) {
    return {.bodies = w.bodies,
            .shapes = w.shapes,
            .contactCache = w.contactCache,
            .broadphase = w.broadphase,
            .joints = *w.joints,
            .events = w.events,
            .def = w.def,
            .identity = w.identity,
            .workers = w.workers,
            .preSolve = w.preSolve,
            .shouldCollide = w.shouldCollide};
}

}  // namespace perpdot
