// The broadphase, a part of the World: Box2D's tree of proxies (one per shape child, in
// collide::CollisionSystem), the proxies that left their fat AABB since the last updatePairs
// (the move buffer: updatePairs looks for their new pairs) and each body's box room
// (box_room.hpp). A shape's proxies are made, re-fitted and destroyed here, from the shape store
// and the bodies' poses.
#pragma once

#include <vector>

#include "collide/collision.hpp"
#include "core/base/pool.hpp"
#include "core/bodies/body_store.hpp"
#include "core/shapes/box_room.hpp"
#include "core/shapes/shape_store.hpp"

namespace perpdot {

struct Broadphase {
    collide::CollisionSystem collision;
    std::vector<int> movedProxies;  // proxies that left their fat AABB (or are new)
    std::vector<BoxRoom> boxRooms;  // by body index: where its boxes were last measured (refit_ahead.cpp)

    // The shape's proxies, one per child, at its body's pose (none while the shape or its body is
    // disabled), queued for updatePairs; its body's box room is forgotten.
    void createProxies(ShapeStore& shapes, const Pool<Body>& bodies, int shape);
    void destroyProxies(ShapeStore& shapes, int shape);
    // Re-fit every proxy of the body to transform xf (as b2DynamicTree::MoveProxy decides); its
    // box room's measured sides are forgotten. Proxies that left their fat AABB are queried for
    // pairs next step.
    void synchronizeProxies(const ShapeStore& shapes, const Pool<Body>& bodies, int body, const Transform& xf,
                            Vec2 displacement);
    // Re-fit one proxy to `aabb` if it left its fat AABB (collision.moveProxy), and queue it for
    // updatePairs once.
    void refitProxy(int proxy, const AABB& aabb, Vec2 displacement);
    // Moves an escaped proxy's leaf in place to `fat` (collision.inPlaceFat's), queued as refitProxy does.
    void moveInPlace(int proxy, const AABB& fat);
    // Its shapes, proxies or centre of mass changed: its box room (box_room.hpp) is not known.
    void forgetBoxRoom(int body);
};

}  // namespace perpdot
