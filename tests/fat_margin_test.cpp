// A proxy's fat AABB keeps a margin for its size around its box (Box2D v3.2's rule: an eighth of
// the shape's size, at most 0.05 m; 0.02 m for static ones), narrower than the 0.1 m Box2D 2.4's
// tree adds, and the tree, whose leaves the adapter narrows, still finds exactly the proxies whose
// fat AABBs overlap a box.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "collide/collision.hpp"
#include "tree_probe.hpp"

namespace perpdot::collide {
namespace {

// The margin the proxy's fat AABB keeps around `box` (the same on every side at creation).
float marginAround(const CollisionSystem& collision, int proxy, const AABB& box) {
    const AABB fat = collision.fatAABB(proxy);
    EXPECT_NEAR(box.lower.x - fat.lower.x, fat.upper.y - box.upper.y, 1e-6f);
    return box.lower.x - fat.lower.x;
}

TEST(FatMargin, IsAnEighthOfTheShapeAtMostFiveCentimetres) {
    CollisionSystem collision;
    collision.setGeometry(0, Circle{{0.0f, 0.0f}, 0.08f});
    collision.setGeometry(1, Circle{{0.0f, 0.0f}, 2.0f});
    collision.setGeometry(2, makeBox(0.2f, 0.2f));
    const Transform at{{3.0f, 4.0f}, Rot::fromAngle(0.0f)};
    auto marginOf = [&](int shape, bool isStatic) {
        const AABB box = collision.computeAABB(shape, 0, at);
        return marginAround(collision, collision.createProxy(box, {shape, 0}, isStatic), box);
    };
    EXPECT_NEAR(marginOf(0, false), 0.01f, 1e-6f);                                      // 0.08 / 8
    EXPECT_NEAR(marginOf(1, false), 0.05f, 1e-6f);                                      // capped
    EXPECT_NEAR(marginOf(2, false), 0.125f * (0.2f * std::sqrt(2.0f) + 2.0f * linearSlop), 1e-6f);  // corner + skin
    EXPECT_NEAR(marginOf(1, true), 4.0f * linearSlop, 1e-6f);                           // static
}

TEST(FatMargin, TheNarrowedTreeFindsEveryOverlappingFatBox) {
    CollisionSystem collision;
    std::mt19937 random(11);
    std::uniform_real_distribution<float> place(-10.0f, 10.0f), step(-0.3f, 0.3f), half(0.05f, 0.6f);
    std::vector<int> proxies;
    std::vector<AABB> boxes;
    for (int i = 0; i < 300; ++i) {
        collision.setGeometry(i, Circle{{0.0f, 0.0f}, half(random)});
        const Vec2 c{place(random), place(random)};
        const AABB box = collision.computeAABB(i, 0, {c, Rot::fromAngle(0.0f)});
        proxies.push_back(collision.createProxy(box, {i, 0}, i % 7 == 0));
        boxes.push_back(box);
    }
    for (int round = 0; round < 20; ++round) {
        for (size_t i = 0; i < proxies.size(); ++i) {  // every proxy moves: some re-fit, some not
            const Vec2 d{step(random), step(random)};
            boxes[i] = {boxes[i].lower + d, boxes[i].upper + d};
            if (collision.room(proxies[i], boxes[i]) < 0.0f) {
                EXPECT_TRUE(collision.moveProxy(proxies[i], boxes[i], d));
            }
            EXPECT_GE(collision.room(proxies[i], boxes[i]), 0.0f);
        }
        const Vec2 c{place(random), place(random)};
        const AABB probe{c - Vec2{2.0f, 2.0f}, c + Vec2{2.0f, 2.0f}};
        const auto [found, expected] = test::foundAndExpected(collision, proxies, probe);
        EXPECT_EQ(found, expected) << "round " << round;
        EXPECT_FALSE(expected.empty());
    }
}

}  // namespace
}  // namespace perpdot::collide
