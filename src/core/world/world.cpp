// World construction, settings, and read-only views of the contact cache.
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
        if (c.touching) out.push_back(impl_->contactData(c));
    });
    return out;
}

}  // namespace perpdot
