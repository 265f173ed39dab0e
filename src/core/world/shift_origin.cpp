// World::shiftOrigin (b2World::ShiftOrigin): the world's coordinates are re-expressed about a new
// origin o, x' = x − o, for everything stored in world coordinates. Relative quantities (anchors
// from a centre of mass, a kept manifold's pose of B in A's frame, local anchors) stay as they are.
#include "core/joints/joint_store.hpp"
#include "core/world/world_impl.hpp"

namespace perpdot {

void World::shiftOrigin(Vec2 newOrigin) {
    Impl& w = *impl_;
    checkUnlocked(w.locked, "World::shiftOrigin");
    if (!isFinite(newOrigin)) throw Error("World::shiftOrigin: the new origin must be finite");
    w.bodies.forEachLive([&](int, Body& b) {
        b.xf.p -= newOrigin;
        b.center -= newOrigin;
    });
    w.contactCache.contacts.forEachLive([&](int, Contact& c) {
        for (ContactPointState& p : c.points) p.point -= newOrigin;
    });
    JointStore& store = *w.joints;
    store.joints.forEachLive([&](int, Joint& j) {
        if (j.type == JointType::Pulley) shiftPulleyGround(j, newOrigin);
    });
    w.broadphase.collision.shiftOrigin(newOrigin);
    w.broadphase.boxRooms.assign(w.broadphase.boxRooms.size(), BoxRoom{});  // measured about the old origin
}

}  // namespace perpdot
