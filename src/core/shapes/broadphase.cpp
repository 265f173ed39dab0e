// A shape's proxies in the broadphase tree: made at its body's pose, re-fitted as the body moves,
// destroyed with the shape (broadphase.hpp).
#include "core/shapes/broadphase.hpp"

#include <algorithm>

namespace perpdot {

void Broadphase::createProxies(ShapeStore& shapes, const Pool<Body>& bodies, int index) {
    ShapeData& s = shapes[index];
    forgetBoxRoom(s.body);
    s.type = static_cast<ShapeType>(s.geometry.index());
    const Transform& xf = bodies[s.body].xf;
    if (!s.enabled || !bodies[s.body].enabled) return;  // out of the broadphase (World::setEnabled)
    const bool isStatic = bodies[s.body].type == BodyType::Static;
    const int children = collision.childCount(index);
    s.proxies.resize(children);
    for (int child = 0; child < children; ++child) {
        s.proxies[child] = collision.createProxy(collision.computeAABB(index, child, xf), {index, child}, isStatic);
        movedProxies.push_back(s.proxies[child]);
    }
}

void Broadphase::destroyProxies(ShapeStore& shapes, int index) {
    forgetBoxRoom(shapes[index].body);
    for (int proxy : shapes[index].proxies) {
        // A proxy id is reused by the tree: forget it in the move buffer before it goes.
        movedProxies.erase(std::remove(movedProxies.begin(), movedProxies.end(), proxy), movedProxies.end());
        collision.destroyProxy(proxy);
    }
    shapes[index].proxies.clear();
}

void Broadphase::synchronizeProxies(const ShapeStore& shapes, const Pool<Body>& bodies, int index, const Transform& xf,
                                    Vec2 displacement) {
    if (static_cast<size_t>(index) < boxRooms.size()) boxRooms[index].below = {-1.0f, -1.0f};  // its boxes change, its reach does not
    for (int s : bodies[index].shapes) {
        const std::vector<int>& proxies = shapes[s].proxies;
        for (int child = 0; child < static_cast<int>(proxies.size()); ++child)
            refitProxy(proxies[child], collision.computeAABB(s, child, xf), displacement);
    }
}

void Broadphase::refitProxy(int proxy, const AABB& aabb, Vec2 displacement) {
    const bool queued = collision.wasMoved(proxy);  // once, however often it moves before updatePairs
    if (collision.moveProxy(proxy, aabb, displacement) && !queued) movedProxies.push_back(proxy);
}

void Broadphase::moveInPlace(int proxy, const AABB& fat) {
    if (!collision.wasMoved(proxy)) movedProxies.push_back(proxy);
    collision.moveInPlace(proxy, fat);
}

void Broadphase::forgetBoxRoom(int index) {
    if (static_cast<size_t>(index) < boxRooms.size()) boxRooms[index] = BoxRoom{};
}

}  // namespace perpdot
