// The broadphase keeps static proxies in a second tree as well, which continuous collision
// searches: it must hold exactly the live static proxies, where they are now.
#include <gtest/gtest.h>

#include <set>

#include "collide/collision.hpp"

namespace perpdot::collide {
namespace {

std::set<int> staticProxiesIn(const CollisionSystem& collision, const AABB& box) {
    std::set<int> found;
    collision.queryStatic(box, [&](int proxy) {
        found.insert(proxy);
        return true;
    });
    return found;
}

AABB boxAt(Vec2 centre) { return {centre - Vec2{0.5f, 0.5f}, centre + Vec2{0.5f, 0.5f}}; }

TEST(StaticTree, HoldsTheLiveStaticProxiesWhereTheyAre) {
    CollisionSystem collision;
    const AABB everywhere{{-100.0f, -100.0f}, {100.0f, 100.0f}};
    const int wall = collision.createProxy(boxAt({0.0f, 0.0f}), {0, 0}, true);
    const int ball = collision.createProxy(boxAt({0.2f, 0.0f}), {1, 0}, false);
    const int floor = collision.createProxy(boxAt({10.0f, 0.0f}), {2, 0}, true);
    EXPECT_EQ(staticProxiesIn(collision, everywhere), (std::set<int>{wall, floor}));
    EXPECT_EQ(staticProxiesIn(collision, boxAt({0.0f, 0.0f})), std::set<int>{wall});  // not the dynamic ball
    EXPECT_EQ(collision.proxyKey(*staticProxiesIn(collision, boxAt({10.0f, 0.0f})).begin()).shape, 2);

    // A static body moved by setTransform: found at its new place only.
    EXPECT_TRUE(collision.moveProxy(floor, boxAt({50.0f, 0.0f}), {40.0f, 0.0f}));
    EXPECT_TRUE(staticProxiesIn(collision, boxAt({10.0f, 0.0f})).empty());
    EXPECT_EQ(staticProxiesIn(collision, boxAt({50.0f, 0.0f})), std::set<int>{floor});

    // Destroyed: gone, and a dynamic proxy that reuses its id is not static.
    collision.destroyProxy(wall);
    EXPECT_EQ(staticProxiesIn(collision, everywhere), std::set<int>{floor});
    const int reused = collision.createProxy(boxAt({0.0f, 0.0f}), {3, 0}, false);
    EXPECT_EQ(staticProxiesIn(collision, everywhere), std::set<int>{floor});
    collision.destroyProxy(reused);
    collision.destroyProxy(ball);
}

}  // namespace
}  // namespace perpdot::collide
