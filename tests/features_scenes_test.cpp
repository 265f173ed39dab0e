// The feature demo scenes do what their descriptions say once their SceneBehaviour is applied.
#include <gtest/gtest.h>

#include <algorithm>

#include <vector>

#include "perpdot/feature_scenes.hpp"

namespace perpdot {
namespace {

SceneWorld buildFeatureScene(const std::string& name) { return buildWorldWithBehaviour(findScene(name)); }

void runScene(SceneWorld& sw, int steps) {
    for (int i = 0; i < steps; ++i) sw.step();
}

int indexOf(const Scene& scene, const std::string& name) {
    for (size_t i = 0; i < scene.bodies.size(); ++i)
        if (scene.bodies[i].name == name) return static_cast<int>(i);
    return -1;
}

TEST(FeaturesScenes, OneWayPlatformsCatchWhatWasLaunchedThroughThem) {
    SceneWorld sw = buildFeatureScene("one_way_platform");
    runScene(sw, 300);
    // Every dynamic body ends above the platform it was launched under.
    int above = 0;
    for (size_t i = 0; i < sw.bodies.size(); ++i)
        if (sw.scene.bodies[i].type == BodyType::Dynamic) above += sw.world.position(sw.bodies[i]).y > 3.0f;
    EXPECT_EQ(above, 6);
}

TEST(FeaturesScenes, BulletsStopAtTheWallAndThePlank) {
    SceneWorld sw = buildFeatureScene("bullet_wall");
    runScene(sw, 120);
    for (int i = 0; i < 3; ++i) EXPECT_LT(sw.world.position(sw.bodies[indexOf(sw.scene, "bullet" + std::to_string(i))]).x, 10.0f);
    EXPECT_LT(sw.world.position(sw.bodies[indexOf(sw.scene, "ball")]).x, 10.0f);
}

TEST(FeaturesScenes, ConveyorsMoveTheBoxesToTheRightBelt) {
    SceneWorld sw = buildFeatureScene("conveyor");
    runScene(sw, 60);
    // On the upper belt (tangent speed +2 m/s) the boxes move right.
    int movingRight = 0;
    for (size_t i = 0; i < sw.bodies.size(); ++i)
        if (sw.scene.bodies[i].type == BodyType::Dynamic) movingRight += sw.world.linearVelocity(sw.bodies[i]).x > 1.0f;
    EXPECT_GE(movingRight, 6);
}

TEST(FeaturesScenes, SensorZoneReportsVisitors) {
    SceneWorld sw = buildFeatureScene("sensor_zone");
    int begins = 0;
    for (int i = 0; i < 120; ++i) {
        sw.step();
        begins += static_cast<int>(sw.world.sensorEvents().beginEvents.size());
    }
    EXPECT_EQ(begins, 12);  // every falling shape entered once
}

struct RecordingDraw : DebugDraw {
    std::vector<std::pair<Vec2, Vec2>> segments;
    std::vector<std::pair<Vec2, float>> points;  // position, size in pixels
    void drawPolygon(std::span<const Vec2>, Color) override {}
    void drawSolidPolygon(std::span<const Vec2>, float, Color) override {}
    void drawCircle(Vec2, float, Color) override {}
    void drawSolidCircle(Vec2, float, Rot, Color) override {}
    void drawSegment(Vec2 a, Vec2 b, Color) override { segments.push_back({a, b}); }
    void drawPoint(Vec2 p, float size, Color) override { points.push_back({p, size}); }
};

TEST(FeaturesScenes, LaserBeamEndsOnSurfaces) {
    SceneWorld sw = buildFeatureScene("laser");
    runScene(sw, 10);
    RecordingDraw draw;
    findSceneBehaviour("laser")->draw(sw, draw);
    ASSERT_GE(draw.segments.size(), 2u);  // at least one reflection inside the walls
    // Each reflected piece starts where the previous one ended (within the 1 mm offset).
    for (size_t i = 1; i < draw.segments.size(); ++i) EXPECT_LT(distance(draw.segments[i - 1].second, draw.segments[i].first), 2e-3f);
    // The first piece ends on a shape: a tiny query box there finds one.
    const Vec2 end = draw.segments[0].second;
    EXPECT_FALSE(sw.world.overlapAABB({end - Vec2{0.02f, 0.02f}, end + Vec2{0.02f, 0.02f}}).empty());
}

// Each swept shape's first touch (the 7-pixel points) lies on a shape of the world, and a sweep
// that touches anything reports that touch among all its hits (the 4-pixel points).
TEST(FeaturesScenes, ShapeCastsMarkTheFirstShapeOnTheirPath) {
    SceneWorld sw = buildFeatureScene("shape_casts");
    int firstTouches = 0;
    for (int frame = 0; frame < 8; ++frame) {
        runScene(sw, 40);
        RecordingDraw draw;
        findSceneBehaviour("shape_casts")->draw(sw, draw);
        for (const auto& point : draw.points) {
            const Vec2 p = point.first;  // a plain variable: clang 14 lambdas cannot capture bindings
            if (point.second != 7.0f) continue;
            ++firstTouches;
            EXPECT_FALSE(sw.world.overlapAABB({p - Vec2{0.02f, 0.02f}, p + Vec2{0.02f, 0.02f}}).empty()) << p.x << ", " << p.y;
            const bool listed = std::any_of(draw.points.begin(), draw.points.end(),
                                            [&](const auto& q) { return q.second == 4.0f && distance(q.first, p) < 1e-6f; });
            EXPECT_TRUE(listed) << "the closest hit is one of all the hits";
        }
    }
    EXPECT_GE(firstTouches, 8) << "at least one of the two sweeps touches something in every frame";
}

}  // namespace
}  // namespace perpdot
