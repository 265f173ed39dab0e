// Shape casts (World::castShapeClosest, World::castShape) against closed forms: a swept shape
// stops where its surface meets the target's, within b2ShapeCast's tolerance of half the linear
// slop (2.5 mm), with the target's face normal; filters drop shapes; all hits come in order.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "features_helpers.hpp"
#include "perpdot/error.hpp"

namespace perpdot {
namespace {

constexpr uint16_t red = 0x0002, blue = 0x0004;
constexpr float slop = 0.0025f;  // b2ShapeCast stops within 0.5·linearSlop of the target distance

// Unit boxes (half extent 1) centred at x = 0 (red), 4 and 8 (blue), a ground segment at y = −3.
struct Boxes {
    World world{WorldDef{.gravity = {0.0f, 0.0f}}};
    ShapeId first, second, third, ground;
    Boxes() {
        first = world.createShape(features::addStatic(world, {0, 0}), {.filter = {.category = red}}, makeBox(1, 1));
        second = world.createShape(features::addStatic(world, {4, 0}), {.filter = {.category = blue}}, makeBox(1, 1));
        third = world.createShape(features::addStatic(world, {8, 0}), {.filter = {.category = blue}}, makeBox(1, 1));
        ground = world.createShape(features::addStatic(world, {0, 0}), {}, Segment{{-20, -3}, {20, -3}});
    }
};

Transform at(Vec2 p) { return {p, Rot{}}; }

// A circle of radius 0.5 from x = −5 along +x touches the face x = −1 when its centre is at
// x = −1.5: fraction 3.5/20.
TEST(ShapeCast, CircleHitsABoxFaceAtTheAnalyticFraction) {
    Boxes s;
    const std::optional<ShapeCastHit> hit = s.world.castShapeClosest(Circle{{}, 0.5f}, at({-5, 0}), {20, 0});
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->shape, s.first);
    EXPECT_NEAR(hit->fraction, 3.5f / 20.0f, slop / 20.0f);
    EXPECT_NEAR(hit->normal.x, -1.0f, 1e-5f);
    EXPECT_NEAR(hit->normal.y, 0.0f, 1e-5f);
    EXPECT_NEAR(hit->point.x, -1.0f, 0.01f + slop);  // on the face (Box2D's 1 cm polygon skin included)
    EXPECT_LE(std::fabs(hit->point.y), 1.0f);
}

TEST(ShapeCast, FilteredShapesAreMissed) {
    Boxes s;
    const Filter notRed{.mask = static_cast<uint16_t>(0xFFFF & ~red)};
    const std::optional<ShapeCastHit> hit = s.world.castShapeClosest(Circle{{}, 0.5f}, at({-5, 0}), {20, 0}, notRed);
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->shape, s.second);  // the red box is skipped: the next face is x = 3
    EXPECT_NEAR(hit->fraction, 7.5f / 20.0f, slop / 20.0f);
    const Filter onlyRed{.mask = red};
    EXPECT_FALSE(s.world.castShapeClosest(Circle{{}, 0.5f}, at({5, 5}), {0, -20}, onlyRed).has_value());
    EXPECT_TRUE(s.world.castShape(Circle{{}, 0.5f}, at({-5, 0}), {20, 0}, Filter{.mask = 0}).empty());
}

TEST(ShapeCast, AllHitsAreOrderedByFraction) {
    Boxes s;
    const std::vector<ShapeCastHit> hits = s.world.castShape(Circle{{}, 0.5f}, at({-5, 0}), {20, 0});
    ASSERT_EQ(hits.size(), 3u);  // the ground segment 3 m below is never reached
    const ShapeId order[] = {s.first, s.second, s.third};
    for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(hits[i].shape, order[i]);
        EXPECT_NEAR(hits[i].fraction, (3.5f + 4.0f * static_cast<float>(i)) / 20.0f, slop / 20.0f);
    }
}

// A 1 m box dropped from y = 5 onto the segment y = −3 at x = −10: its bottom (y = 4.5) travels
// 7.5 m to touch (both have Box2D's 1 cm skin; b2ShapeCast keeps one of them).
TEST(ShapeCast, BoxFallsOntoASegment) {
    Boxes s;
    const std::optional<ShapeCastHit> hit = s.world.castShapeClosest(makeBox(0.5f, 0.5f), at({-10, 5}), {0, -10});
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->shape, s.ground);
    EXPECT_NEAR(hit->fraction, (7.5f - 0.01f) / 10.0f, slop / 10.0f);
    EXPECT_NEAR(hit->normal.y, 1.0f, 1e-5f);
}

// A segment swept diagonally onto a circle: where the circle first meets the segment's end point
// p + t·d, |p + t·d − c| = r (the quadratic's smaller root).
TEST(ShapeCast, SegmentEndMeetsACircleAtTheQuadraticRoot) {
    World world{WorldDef{.gravity = {0.0f, 0.0f}}};
    const ShapeId disc = world.createShape(features::addStatic(world, {0, 0}), {}, Circle{{}, 1.0f});
    const Vec2 p{2.0f, 3.0f}, d{-2.0f, -6.0f};  // the segment's lower end, moving down and left
    const std::optional<ShapeCastHit> hit = world.castShapeClosest(Segment{{0, 0}, {2, 0}}, at(p), d);
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->shape, disc);
    // |p + t d|² = r², r = 1 (+ the segment's 1 cm skin, less b2ShapeCast's one skin: 1).
    const float a = dot(d, d), b = 2.0f * dot(p, d), c = dot(p, p) - 1.0f;
    const float t = (-b - std::sqrt(b * b - 4.0f * a * c)) / (2.0f * a);
    EXPECT_NEAR(hit->fraction, t, slop / length(d));
    const Vec2 radial = normalize(p + t * d);
    EXPECT_NEAR(hit->normal.x, radial.x, 1e-2f);
    EXPECT_NEAR(hit->normal.y, radial.y, 1e-2f);
    EXPECT_NEAR(length(hit->point), 1.0f, 0.01f + slop);
}

TEST(ShapeCast, OverlapAtTheStartIsAHitAtFractionZero) {
    Boxes s;
    const std::optional<ShapeCastHit> hit = s.world.castShapeClosest(Circle{{}, 0.5f}, at({0.5f, 0}), {0, 5});
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->shape, s.first);
    EXPECT_EQ(hit->fraction, 0.0f);
    EXPECT_NEAR(hit->normal.x, 0.0f, 1e-6f);
    EXPECT_NEAR(hit->normal.y, -1.0f, 1e-6f);
    EXPECT_EQ(hit->point, (Vec2{0.5f, 0.0f}));
}

TEST(ShapeCast, BadInputIsRefused) {
    Boxes s;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    EXPECT_THROW((void)s.world.castShapeClosest(Circle{{}, 0.5f}, at({0, 5}), {nan, 0}), Error);
    EXPECT_THROW((void)s.world.castShape(Circle{{}, 0.5f}, at({nan, 5}), {1, 0}), Error);
    EXPECT_THROW((void)s.world.castShapeClosest(Circle{{}, 0.0f}, at({0, 5}), {1, 0}), Error);
    EXPECT_THROW((void)s.world.castShapeClosest(Segment{{0, 0}, {0, 0}}, at({0, 5}), {1, 0}), Error);
}

}  // namespace
}  // namespace perpdot
