// The two facts the broadphase's skipped checks rest on (refit_ahead.cpp): CollisionSystem::room is
// >= 0 exactly when a proxy's fat AABB holds a box, after which a re-fit holds it with the margin;
// and a body's BoxRoom bound never says "inside" for a pose whose box sticks out.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

#include "collide/collision.hpp"
#include "core/shapes/box_room.hpp"

namespace perpdot {
namespace {

bool holds(const AABB& outer, const AABB& inner) {
    return outer.lower.x <= inner.lower.x && outer.lower.y <= inner.lower.y && inner.upper.x <= outer.upper.x &&
           inner.upper.y <= outer.upper.y;
}

TEST(BoxRoom, RoomSaysWhetherTheFatBoxHoldsABox) {
    collide::CollisionSystem collision;
    std::mt19937 random(20261126);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    int inside = 0, outside = 0;
    for (const float origin : {0.0f, 37.5f, -1234.5f, 40000.0f}) {
        for (int trial = 0; trial < 2000; ++trial) {
            const Vec2 centre{origin + 10.0f * unit(random), origin + 10.0f * unit(random)};
            const Vec2 half{0.05f + 0.5f * std::fabs(unit(random)), 0.05f + 0.5f * std::fabs(unit(random))};
            const int proxy = collision.createProxy({centre - half, centre + half}, {trial, 0}, false);
            const float reach = trial % 3 == 0 ? 0.02f : trial % 3 == 1 ? 0.15f : 0.6f;
            const Vec2 d{reach * unit(random), reach * unit(random)};
            const AABB next{centre + d - half, centre + d + half};
            const float room = collision.room(proxy, next);
            ASSERT_EQ(room >= 0.0f, holds(collision.fatAABB(proxy), next)) << "origin " << origin << ", trial " << trial;
            if (room < 0.0f) {
                ASSERT_TRUE(collision.moveProxy(proxy, next, d));
                ASSERT_GE(collision.room(proxy, next), 0.049f);  // the 0.05 m margin of a child without geometry, rounded
            }
            ++(room >= 0.0f ? inside : outside);
            collision.destroyProxy(proxy);
        }
    }
    EXPECT_GT(inside, 1000);
    EXPECT_GT(outside, 1000);
}

// A box off the body origin, on a body whose centre of mass is off it too, measured in a fat box
// of 0.1 m margin at one pose; at poses moved and turned about that, wherever the bound says
// "inside", the box is.
TEST(BoxRoom, TheBoundNeverPassesABoxThatSticksOut) {
    const Vec2 localCenter{0.3f, -0.2f};
    const std::array<Vec2, 4> corners{Vec2{-0.4f, 0.0f}, Vec2{0.6f, 0.0f}, Vec2{0.6f, 0.5f}, Vec2{-0.4f, 0.5f}};
    float reach = 0.0f;  // of the corners about the centre of mass
    for (Vec2 c : corners) reach = std::max(reach, length(c - localCenter));
    auto boxAt = [&](Vec2 center, Rot q) {
        const Transform xf{center - rotate(q, localCenter), q};
        AABB box{transformPoint(xf, corners[0]), transformPoint(xf, corners[0])};
        for (Vec2 c : corners) {
            const Vec2 p = transformPoint(xf, c);
            box.lower = {std::min(box.lower.x, p.x), std::min(box.lower.y, p.y)};
            box.upper = {std::max(box.upper.x, p.x), std::max(box.upper.y, p.y)};
        }
        return box;
    };
    std::mt19937 random(7);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    int passed = 0;
    for (const float origin : {0.0f, 500.0f, -30000.0f}) {
        for (int trial = 0; trial < 20000; ++trial) {
            const Vec2 c0{origin + 5.0f * unit(random), origin + 5.0f * unit(random)};
            const Rot q0 = Rot::fromAngle(3.14159f * unit(random));
            const AABB box0 = boxAt(c0, q0);
            // A fat box with different room on each side, as a moving body's has.
            const Vec2 below{0.02f + 0.1f * std::fabs(unit(random)), 0.02f + 0.1f * std::fabs(unit(random))};
            const Vec2 above{0.02f + 0.3f * std::fabs(unit(random)), 0.02f + 0.1f * std::fabs(unit(random))};
            const AABB fat{box0.lower - below, box0.upper + above};
            const BoxRoom measured{c0, q0, reach, box0.lower - fat.lower, fat.upper - box0.upper};
            const float scale = trial % 2 == 0 ? 0.02f : 0.12f;
            const Vec2 c1 = c0 + Vec2{scale * unit(random), scale * unit(random)};
            const Rot q1 = Rot::fromAngle(q0.angle() + 2.0f * scale * unit(random));
            if (!measured.holds(c1, q1)) continue;
            ++passed;
            ASSERT_TRUE(holds(fat, boxAt(c1, q1))) << "origin " << origin << ", trial " << trial;
        }
    }
    EXPECT_GT(passed, 10000);  // the bound is not so loose that it never tells
}

// A body measured never (or forgotten) is measured: no pose passes, however near.
TEST(BoxRoom, AnUnmeasuredBodyNeverPasses) {
    const BoxRoom unknown{};
    EXPECT_FALSE(unknown.holds(unknown.center, unknown.q));
    EXPECT_FALSE(unknown.holds({0.5f, 0.5f}, Rot::fromAngle(2.0f)));  // a negative reach must not help
}

}  // namespace
}  // namespace perpdot
