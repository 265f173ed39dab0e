// CollisionSystem::proxyKeeps: the workers' answer to "would moveProxy leave the tree alone?" must
// be b2DynamicTree::MoveProxy's own answer for every move — inside the fat AABB, out of it, a
// fat AABB grown too large for a box that stopped (the "huge" test), either side of a predicted
// displacement, far from the origin where float rounding bites. A wrong "keeps" would skip a
// re-fit (a missed pair); a wrong "moves" would only cost a serial call, but both break the claim
// that the check copies MoveProxy's float operations.
#include <gtest/gtest.h>

#include <random>

#include "collide/collision.hpp"

namespace perpdot::collide {
namespace {

TEST(ProxyKeeps, AgreesWithMoveProxyOnEveryMove) {
    CollisionSystem collision;
    std::mt19937 random(20261125);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    int keeps = 0, moves = 0;
    for (const float origin : {0.0f, 37.5f, -1234.5f, 40000.0f}) {
        for (int trial = 0; trial < 2000; ++trial) {
            const Vec2 centre{origin + 10.0f * unit(random), origin + 10.0f * unit(random)};
            const Vec2 half{0.05f + 0.5f * std::fabs(unit(random)), 0.05f + 0.5f * std::fabs(unit(random))};
            const int proxy = collision.createProxy({centre - half, centre + half}, {trial, 0}, false);
            // A first move, sometimes fast, so the fat AABB is stretched along the displacement.
            const Vec2 first{0.5f * unit(random) * (trial % 3 == 0 ? 4.0f : 0.2f), 0.5f * unit(random)};
            collision.moveProxy(proxy, {centre + first - half, centre + first + half}, first);
            // Then small and large moves, and boxes that shrink.
            const float reach = trial % 4 == 0 ? 0.02f : trial % 4 == 1 ? 0.15f : trial % 4 == 2 ? 0.6f : 3.0f;
            const Vec2 d{reach * unit(random), reach * unit(random)};
            const Vec2 shrunk = trial % 5 == 0 ? 0.5f * half : half;
            const AABB next{centre + first + d - shrunk, centre + first + d + shrunk};
            const bool predicted = collision.proxyKeeps(proxy, next, d);
            const bool moved = collision.moveProxy(proxy, next, d);
            ASSERT_EQ(predicted, !moved) << "origin " << origin << ", trial " << trial;
            ++(predicted ? keeps : moves);
            collision.destroyProxy(proxy);
        }
    }
    // Both answers were exercised many times (545 and 7,455 with this seed).
    EXPECT_GT(keeps, 400);
    EXPECT_GT(moves, 400);
}

// A static proxy is mirrored in a second tree: proxyKeeps leaves it to moveProxy.
TEST(ProxyKeeps, LeavesStaticProxiesToMoveProxy) {
    CollisionSystem collision;
    const AABB box{{-0.5f, -0.5f}, {0.5f, 0.5f}};
    const int wall = collision.createProxy(box, {0, 0}, true);
    EXPECT_FALSE(collision.proxyKeeps(wall, box, {}));
    EXPECT_FALSE(collision.moveProxy(wall, box, {}));  // it does keep: the answer is only conservative
}

}  // namespace
}  // namespace perpdot::collide
