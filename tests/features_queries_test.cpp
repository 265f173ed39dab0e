// World queries: ray casts (closest, all), AABB, point and shape overlap, with filters.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "features_helpers.hpp"
#include "perpdot/error.hpp"

namespace perpdot {
namespace {

constexpr uint16_t red = 0x0002, blue = 0x0004;

// Two unit boxes on the x axis (red at x = 2, blue at x = 4), a circle of radius 0.5 at (0, 3).
struct Scene {
    World world{WorldDef{.gravity = {0.0f, 0.0f}}};
    ShapeId redBox, blueBox, disc;
    Scene() {
        redBox = world.createShape(features::addStatic(world, {2.0f, 0.0f}), {.filter = {.category = red}}, makeBox(0.5f, 0.5f));
        blueBox = world.createShape(features::addStatic(world, {4.0f, 0.0f}), {.filter = {.category = blue}}, makeBox(0.5f, 0.5f));
        disc = world.createShape(features::addDynamic(world, {0.0f, 3.0f}), {}, Circle{.radius = 0.5f});
    }
};

bool contains(const std::vector<ShapeId>& ids, ShapeId id) { return std::find(ids.begin(), ids.end(), id) != ids.end(); }

TEST(FeaturesQueries, ClosestRayHitIsTheNearFaceOfTheFirstBox) {
    Scene s;
    const std::optional<RayHit> hit = s.world.castRayClosest({0.0f, 0.0f}, {10.0f, 0.0f});
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->shape, s.redBox);
    EXPECT_NEAR(hit->point.x, 1.5f, 1e-4f);  // the face x = 2 - 0.5
    EXPECT_NEAR(hit->point.y, 0.0f, 1e-6f);
    EXPECT_NEAR(hit->fraction, 0.15f, 1e-5f);
    EXPECT_NEAR(hit->normal.x, -1.0f, 1e-6f);
    EXPECT_NEAR(hit->normal.y, 0.0f, 1e-6f);
}

TEST(FeaturesQueries, RayAgainstACircleGivesTheRadialNormal) {
    Scene s;
    // From (−3, 3 + 0.3) along +x: enters the circle at x = −sqrt(0.25 − 0.09) = −0.4.
    const std::optional<RayHit> hit = s.world.castRayClosest({-3.0f, 3.3f}, {6.0f, 0.0f});
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->shape, s.disc);
    EXPECT_NEAR(hit->point.x, -0.4f, 1e-4f);
    EXPECT_NEAR(hit->normal.x, -0.8f, 1e-4f);
    EXPECT_NEAR(hit->normal.y, 0.6f, 1e-4f);
}

TEST(FeaturesQueries, AllHitsAreOrderedAndFiltersSkipShapes) {
    Scene s;
    const std::vector<RayHit> hits = s.world.castRay({0.0f, 0.0f}, {10.0f, 0.0f});
    ASSERT_EQ(hits.size(), 2u);
    EXPECT_EQ(hits[0].shape, s.redBox);
    EXPECT_EQ(hits[1].shape, s.blueBox);
    EXPECT_NEAR(hits[1].point.x, 3.5f, 1e-4f);
    // A ray that only sees blue passes the red box.
    const std::optional<RayHit> blueOnly = s.world.castRayClosest({0.0f, 0.0f}, {10.0f, 0.0f}, {.category = 0xFFFF, .mask = blue});
    ASSERT_TRUE(blueOnly.has_value());
    EXPECT_EQ(blueOnly->shape, s.blueBox);
    // Too short a ray hits nothing.
    EXPECT_FALSE(s.world.castRayClosest({0.0f, 0.0f}, {1.4f, 0.0f}).has_value());
}

TEST(FeaturesQueries, AABBQueryUsesTightBounds) {
    Scene s;
    const std::vector<ShapeId> around = s.world.overlapAABB({{1.0f, -1.0f}, {3.6f, 1.0f}});
    EXPECT_TRUE(contains(around, s.redBox));
    EXPECT_TRUE(contains(around, s.blueBox));  // its left face is x = 3.5
    EXPECT_FALSE(contains(around, s.disc));
    // Between the boxes' faces (2.5 .. 3.5) but clear of both by more than the polygon skin.
    EXPECT_TRUE(s.world.overlapAABB({{2.6f, -1.0f}, {3.4f, 1.0f}}).empty());
    EXPECT_EQ(s.world.overlapAABB({{1.0f, -1.0f}, {3.6f, 1.0f}}, {.mask = red}), std::vector<ShapeId>{s.redBox});
}

TEST(FeaturesQueries, PointQueryFindsTheSolidShapeContainingIt) {
    Scene s;
    EXPECT_EQ(s.world.overlapPoint({2.4f, 0.4f}), std::vector<ShapeId>{s.redBox});
    EXPECT_EQ(s.world.overlapPoint({0.3f, 3.3f}), std::vector<ShapeId>{s.disc});
    EXPECT_TRUE(s.world.overlapPoint({0.4f, 3.4f}).empty());  // |(0.4, 0.4)| = 0.57 > 0.5
    EXPECT_TRUE(s.world.overlapPoint({2.4f, 0.4f}, {.mask = blue}).empty());
}

TEST(FeaturesQueries, ShapeOverlapWithAUserCircleAndPolygon) {
    Scene s;
    // A circle of radius 0.6 centred at (3, 0) reaches both boxes (0.5 away each).
    const std::vector<ShapeId> both = s.world.overlapShape(Circle{.radius = 0.6f}, Transform{{3.0f, 0.0f}, {}});
    EXPECT_TRUE(contains(both, s.redBox));
    EXPECT_TRUE(contains(both, s.blueBox));
    EXPECT_TRUE(s.world.overlapShape(Circle{.radius = 0.4f}, Transform{{3.0f, 0.0f}, {}}).empty());
    // A thin box turned 90°: 0.2 wide along x once turned, centred between the boxes: no overlap;
    // 1.2 long along x (not turned): both.
    const Polygon bar = makeBox(0.6f, 0.1f);
    EXPECT_TRUE(s.world.overlapShape(bar, Transform{{3.0f, 0.0f}, Rot::fromAngle(0.5f * pi)}).empty());
    EXPECT_EQ(s.world.overlapShape(bar, Transform{{3.0f, 0.0f}, {}}).size(), 2u);
    EXPECT_EQ(s.world.overlapShape(bar, Transform{{3.0f, 0.0f}, {}}, {.mask = blue}), std::vector<ShapeId>{s.blueBox});
}

// Query shapes get a created shape's checks: a hand-filled polygon with too many vertices (which
// would index past the adapter's 8), a non-convex one, a zero radius, a non-finite transform; and
// a ray of zero length (Box2D's tree asserts on one) just hits nothing.
TEST(FeaturesQueries, BadQueryShapesAreRefusedAndAZeroRayHitsNothing) {
    Scene s;
    Polygon tooMany = makeBox(1.0f, 1.0f);
    tooMany.count = 40;
    EXPECT_THROW((void)s.world.overlapShape(tooMany, Transform{}), Error);
    Polygon dent = makeBox(1.0f, 1.0f);
    dent.vertices[1] = {0.0f, 0.0f};
    EXPECT_THROW((void)s.world.overlapShape(dent, Transform{}), Error);
    EXPECT_THROW((void)s.world.overlapShape(Circle{.radius = 0.0f}, Transform{}), Error);
    const float inf = std::numeric_limits<float>::infinity();
    EXPECT_THROW((void)s.world.overlapShape(Circle{}, Transform{{inf, 0.0f}, {}}), Error);
    EXPECT_FALSE(s.world.castRayClosest({3.0f, 0.0f}, {0.0f, 0.0f}).has_value());
    EXPECT_TRUE(s.world.castRay({3.0f, 0.0f}, {1e-30f, 0.0f}).empty());
}

}  // namespace
}  // namespace perpdot
