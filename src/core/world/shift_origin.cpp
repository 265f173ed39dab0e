// The world's coordinates re-expressed about a new origin o, x' = x − o, for everything stored in
// world coordinates. Relative quantities (anchors from a centre of mass, a kept manifold's pose of
// B in A's frame, local anchors) stay as they are.
#include "core/world/shift_origin.hpp"

namespace perpdot {

void shiftOrigin(Pool<Body>& bodies, ContactCache& cache, JointStore& joints, Broadphase& broadphase, Vec2 newOrigin) {
    bodies.forEachLive([&](int, Body& b) {
        b.xf.p -= newOrigin;
        b.center -= newOrigin;
    });
    cache.contacts.forEachLive([&](int, Contact& c) {
        for (ContactPointState& p : c.points) p.point -= newOrigin;
    });
    joints.joints.forEachLive([&](int, Joint& j) {
        if (j.type == JointType::Pulley) shiftPulleyGround(j, newOrigin);
    });
    broadphase.collision.shiftOrigin(newOrigin);
    broadphase.boxRooms.assign(broadphase.boxRooms.size(), BoxRoom{});  // measured about the old origin
}

}  // namespace perpdot
