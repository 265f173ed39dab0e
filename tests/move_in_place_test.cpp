// A moved dynamic proxy keeps its leaf where it is (CollisionSystem::Impl::moveInPlace): its
// ancestors up to the nearest that holds the new box become the unions of their children again.
// Every ancestor must still hold its leaves and the leaf must be marked moved: the tree then finds
// exactly the fat boxes that overlap a probe, and pair finding sees the proxy as moved. A move
// that no near ancestor holds wears the tree toward its next rebuild.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "collide/collision.hpp"
#include "tree_probe.hpp"

namespace perpdot::collide {
namespace {

// A packed 25 x 25 grid of 0.4 m boxes, touching, their proxies and boxes in `proxies` and `boxes`.
void packGrid(CollisionSystem& collision, std::vector<int>& proxies, std::vector<AABB>& boxes) {
    collision.setGeometry(0, makeBox(0.2f, 0.2f));
    for (int i = 0; i < 25; ++i)
        for (int j = 0; j < 25; ++j) {
            const AABB box = collision.computeAABB(0, 0, {{0.4f * i, 0.4f * j}, Rot::fromAngle(0.0f)});
            proxies.push_back(collision.createProxy(box, {0, i * 25 + j}, false));
            boxes.push_back(box);
        }
}

// Whether ten probes of half-size `half` at random places each find exactly the fat boxes that
// overlap them.
bool probesFindExactly(const CollisionSystem& collision, const std::vector<int>& proxies, std::mt19937& random,
                       std::uniform_real_distribution<float>& place, float half) {
    for (int probe = 0; probe < 10; ++probe) {
        const Vec2 c{place(random), place(random)};
        const auto [found, expected] = test::foundAndExpected(collision, proxies, {c - Vec2{half, half}, c + Vec2{half, half}});
        if (found != expected) return false;
    }
    return true;
}

TEST(MoveInPlace, SmallMovesKeepEveryAncestorHoldingItsLeaves) {
    CollisionSystem collision;
    std::mt19937 random(7);
    // A packed grid of small boxes jiggling by up to a few centimetres a round: most re-fits stay
    // inside a near ancestor's box, a few leave it.
    std::uniform_real_distribution<float> jiggle(-0.06f, 0.06f), place(-1.0f, 11.0f);
    std::vector<int> proxies;
    std::vector<AABB> boxes;
    packGrid(collision, proxies, boxes);
    int moves = 0;
    for (int round = 0; round < 60; ++round) {
        for (size_t k = 0; k < proxies.size(); ++k) {
            const Vec2 d{jiggle(random), jiggle(random)};
            boxes[k] = {boxes[k].lower + d, boxes[k].upper + d};
            if (collision.room(proxies[k], boxes[k]) >= 0.0f) continue;
            ASSERT_TRUE(collision.moveProxy(proxies[k], boxes[k], d));
            EXPECT_TRUE(collision.wasMoved(proxies[k])) << "a moved leaf is queued for pair finding";
            EXPECT_GE(collision.room(proxies[k], boxes[k]), 0.0f);
            ++moves;
        }
        ASSERT_TRUE(probesFindExactly(collision, proxies, random, place, 0.7f)) << "round " << round;
        for (int proxy : proxies) collision.clearMoved(proxy);
    }
    EXPECT_GT(moves, 1000);
}

TEST(MoveInPlace, FarMovesKeepEveryAncestorHoldingItsLeavesAndWearTheTree) {
    CollisionSystem collision;
    std::mt19937 random(11);
    // Boxes thrown anywhere over a field forty times the grid's size: most land where no ancestor
    // of their leaf near it holds them, some outside the root's box.
    std::uniform_real_distribution<float> anywhere(-200.0f, 200.0f), place(-200.0f, 200.0f);
    std::vector<int> proxies;
    std::vector<AABB> boxes;
    packGrid(collision, proxies, boxes);
    collision.rebuildTreeIfWorn();  // the creations' wear
    int rebuilds = 0;
    for (int round = 0; round < 30; ++round) {
        for (size_t k = round % 3; k < proxies.size(); k += 3) {
            const Vec2 d = Vec2{anywhere(random), anywhere(random)} - boxes[k].lower;
            boxes[k] = {boxes[k].lower + d, boxes[k].upper + d};
            ASSERT_TRUE(collision.moveProxy(proxies[k], boxes[k], Vec2{}));
            EXPECT_TRUE(collision.wasMoved(proxies[k]));
            EXPECT_GE(collision.room(proxies[k], boxes[k]), 0.0f);
        }
        ASSERT_TRUE(probesFindExactly(collision, proxies, random, place, 20.0f)) << "round " << round;
        for (int proxy : proxies) collision.clearMoved(proxy);
        rebuilds += collision.rebuildTreeIfWorn() ? 1 : 0;
    }
    // 6,250 far moves of 625 leaves: about one rebuild every three rounds.
    EXPECT_GE(rebuilds, 5);
}

}  // namespace
}  // namespace perpdot::collide
