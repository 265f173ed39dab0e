// CollisionSystem::collide skips b2Collide* for shapes whose bounding circles are too far apart for
// it to report a point. The skip must never drop a point Box2D reports: random poses on both sides
// of the bound, each compared with Box2D's own b2CollidePolygons or b2CollidePolygonAndCircle on
// the same b2 shapes.
#include <box2d/box2d.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "collide/b2_convert.hpp"
#include "collide/collision.hpp"
#include "collide/polygon_b2.hpp"

namespace perpdot::collide {
namespace {

// Box2D's point count for shape A (a polygon) against B (a polygon, or the circle when given).
int box2dPointCount(const Polygon& a, const Transform& xfA, const Polygon* b, const Circle* circle, const Transform& xfB) {
    const b2PolygonShape pa = polygonToB2(a);
    b2Manifold m;
    m.pointCount = 0;
    if (circle) {
        const b2CircleShape c = toB2(*circle);
        b2CollidePolygonAndCircle(&m, &pa, toB2(xfA), &c, toB2(xfB));
    } else {
        const b2PolygonShape pb = polygonToB2(*b);
        b2CollidePolygons(&m, &pa, toB2(xfA), &pb, toB2(xfB));
    }
    return m.pointCount;
}

TEST(NarrowphaseBounds, SkippingNeverDropsAPointBox2DReports) {
    // Shapes off their origins, flat and rounded: the bound is about the body origin.
    const Polygon box = makeBox(0.2f, 0.2f);
    const Polygon plank = makeBox(0.4f, 0.05f, {0.1f, -0.05f}, 0.3f);
    Polygon rounded = makeBox(0.3f, 0.1f, {-0.05f, 0.02f});
    rounded.radius = 0.05f;
    const Circle disc{{0.1f, 0.05f}, 0.25f};
    const Polygon polygons[] = {box, plank, rounded};

    CollisionSystem collision;
    for (int i = 0; i < 3; ++i) collision.setGeometry(i, polygons[i]);
    collision.setGeometry(3, disc);

    std::mt19937 rng(7);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const float twoPi = 6.2831853f;
    int withPoints = 0, compared = 0;
    for (int a = 0; a < 3; ++a) {
        for (int b = 0; b < 4; ++b) {
            const float reach = collision.maxExtent(a) + collision.maxExtent(b);
            for (int k = 0; k < 20000; ++k) {
                // B's origin from 0.8 to 1.1 times the two extents away: touching, near and apart.
                const float direction = twoPi * unit(rng), distance = reach * (0.8f + 0.3f * unit(rng));
                const Transform xfA{{0.0f, 0.0f}, Rot::fromAngle(twoPi * unit(rng))};
                const Transform xfB{{distance * std::cos(direction), distance * std::sin(direction)}, Rot::fromAngle(twoPi * unit(rng))};
                const int expected = b < 3 ? box2dPointCount(polygons[a], xfA, &polygons[b], nullptr, xfB)
                                           : box2dPointCount(polygons[a], xfA, nullptr, &disc, xfB);
                const int got = collision.collide({a, 0}, xfA, {b, 0}, xfB, collide::Skin::Box2D).pointCount;
                ASSERT_EQ(got, expected) << "shapes " << a << ", " << b << " at distance " << distance << " of reach " << reach;
                withPoints += expected > 0 ? 1 : 0;
                ++compared;
            }
        }
    }
    // The poses reach both sides: many have points, many none.
    EXPECT_GT(withPoints, compared / 20);
    EXPECT_LT(withPoints, compared - compared / 20);
}

}  // namespace
}  // namespace perpdot::collide
