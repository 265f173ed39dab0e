// World construction, settings, read-only views of the contact cache and the events, and the
// contact stages' view of the world.
#include "core/contacts/contact_world.hpp"
#include "core/world/events.hpp"
#include "core/world/world_impl.hpp"

namespace perpdot {

World::World(const WorldDef& def) : impl_(std::make_unique<Impl>(def)) {}
World::~World() = default;
World::World(World&&) noexcept = default;
World& World::operator=(World&&) noexcept = default;

const WorldDef& World::settings() const { return impl_->def; }

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
