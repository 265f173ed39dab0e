// Chains' explicit solid side (Chain::solid) and ghost vertices (prevVertex, nextVertex): terrain
// given left to right holds a box driven along it by default and lets it through when declared
// solid on the other side; two open chains joined with ghost vertices slide a box across the seam
// exactly like one chain; both settings survive snapshots and the scene format.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "perpdot/error.hpp"
#include "perpdot/scene.hpp"
#include "perpdot/world.hpp"
#include "physics_scenes.hpp"

namespace perpdot {
namespace {

using test::dt;

// Rolling hills y = 1.5 sin(x/4), sampled every metre from x = -10 to 60, left to right.
float hill(float x) { return 1.5f * std::sin(0.25f * x); }
std::vector<Vec2> terrain() {
    std::vector<Vec2> v;
    for (int i = -10; i <= 60; ++i) v.push_back({static_cast<float>(i), hill(static_cast<float>(i))});
    return v;
}

// A 1 m box dropped on the terrain and driven right at 4 m/s for 8 s: the lowest its bottom ever
// came relative to the ground under it (negative: below the surface).
float drive(ChainSide solid) {
    World world(WorldDef{.enableSleep = false});
    world.createShape(world.createBody({}), {}, Chain{terrain(), false, solid});
    const BodyId box = test::addBox(world, {0.0f, 2.0f}, 0.5f, 0.5f, test::material(1.0f, 0.3f));
    float lowest = 1e9f;
    for (int i = 0; i < 480; ++i) {
        const Vec2 v = world.linearVelocity(box);
        world.setLinearVelocity(box, {4.0f, v.y});
        world.step(dt);
        const Vec2 p = world.position(box);
        // Chords of the sine lie below it by at most 1.5·(1 − cos(1/8)) = 0.012 m.
        lowest = std::min(lowest, p.y - 0.5f - hill(p.x));
    }
    return lowest;
}

TEST(ChainSide, LeftToRightTerrainIsSolidBelowByDefault) {
    EXPECT_EQ(Chain{}.solid, ChainSide::Right);
    const float held = drive(ChainSide::Right);
    EXPECT_GT(held, -0.8f) << "the box went into the ground";  // a tilted box's centre dips below 0.5 m up
    const float through = drive(ChainSide::Left);  // declared solid above: the box falls through
    EXPECT_LT(through, -10.0f);
}

// A floor made of two open chains meeting at x = 0, each given the other's neighbouring vertex as
// its ghost: a box sliding across the seam moves exactly as on one chain (no catch, no bump).
struct Slide {
    float maxVerticalSpeed = 0.0f, maxAngularSpeed = 0.0f;
    Vec2 end;
};
Slide slide(bool split) {
    World world(WorldDef{.enableSleep = false});
    const BodyId ground = world.createBody({});
    const ShapeDef floor{.friction = 0.2f};
    if (split) {
        world.createShape(ground, floor, Chain{{{-10.0f, 0.0f}, {0.0f, 0.0f}}, false, ChainSide::Right, std::nullopt, Vec2{0.5f, 0.0f}});
        world.createShape(ground, floor, Chain{{{0.0f, 0.0f}, {0.5f, 0.0f}, {20.0f, 0.0f}}, false, ChainSide::Right, Vec2{-10.0f, 0.0f}});
    } else {
        world.createShape(ground, floor, Chain{{{-10.0f, 0.0f}, {0.0f, 0.0f}, {0.5f, 0.0f}, {20.0f, 0.0f}}});
    }
    const BodyId box = test::addBox(world, {-3.0f, 0.5f}, 0.5f, 0.5f, test::material(1.0f, 0.2f));
    test::run(world, 30);
    world.setLinearVelocity(box, {6.0f, 0.0f});
    Slide s;
    for (int i = 0; i < 90; ++i) {
        world.step(dt);
        s.maxVerticalSpeed = std::max(s.maxVerticalSpeed, std::fabs(world.linearVelocity(box).y));
        s.maxAngularSpeed = std::max(s.maxAngularSpeed, std::fabs(world.angularVelocity(box)));
    }
    s.end = world.position(box);
    return s;
}

TEST(ChainSide, GhostVerticesJoinTwoOpenChainsWithoutACatch) {
    const Slide one = slide(false), two = slide(true);
    EXPECT_GT(two.end.x, 1.0f) << "it crossed the seam";
    EXPECT_LT(two.maxVerticalSpeed, 0.01f);
    EXPECT_LT(two.maxAngularSpeed, 0.01f);
    EXPECT_NEAR(two.end.x, one.end.x, 1e-3f);
    EXPECT_NEAR(two.end.y, one.end.y, 1e-3f);
}

TEST(ChainSide, SideAndGhostsSurviveSnapshotsAndTheSceneFormat) {
    World world;
    const BodyId ground = world.createBody({});
    const Chain made{{{0.0f, 0.0f}, {1.0f, 0.5f}, {2.0f, 0.0f}}, false, ChainSide::Right, Vec2{-1.0f, 0.2f}, Vec2{3.0f, 0.1f}};
    const ShapeId shape = world.createShape(ground, {}, made);
    EXPECT_EQ(world.chain(shape), made);
    World restored;
    restored.restore(world.snapshot());
    EXPECT_EQ(restored.chain(shape), made);
    EXPECT_EQ(restored.snapshot(), world.snapshot());
    EXPECT_THROW(world.createShape(ground, {}, Chain{{{0, 0}, {1, 0}, {1, 1}}, true, ChainSide::Right, Vec2{-1, 0}}), Error);

    const char* json = R"({"format": "perpdot-scene/1", "bodies": [{"name": "ground", "type": "static", "shapes": [
        {"type": "chain", "vertices": [[0, 0], [1, 0.5], [2, 0]], "solid": "right", "prev_vertex": [-1, 0.2], "next_vertex": [3, 0.1]},
        {"type": "chain", "vertices": [[0, 0], [1, 0]]}]}]})";
    const Scene scene = parseScene(json);
    const SceneShape& s = scene.bodies[0].shapes[0];
    EXPECT_EQ(s.solid, ChainSide::Right);
    EXPECT_EQ(s.prevVertex, (Vec2{-1.0f, 0.2f}));
    EXPECT_EQ(s.nextVertex, (Vec2{3.0f, 0.1f}));
    EXPECT_EQ(scene.bodies[0].shapes[1].solid, ChainSide::Left) << "scene files before the key meant Box2D's side";
    EXPECT_EQ(parseScene(toJson(scene)), scene);
    try {
        parseScene(R"({"format": "perpdot-scene/1", "bodies": [{"name": "g", "type": "static", "shapes": [{"type": "chain", "vertices": [[0, 0], [1, 0]], "solid": "up"}]}]})");
        ADD_FAILURE() << "accepted solid: up";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("bodies[0].shapes[0].solid"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace perpdot
