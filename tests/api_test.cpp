// The World API's promises: stale handles are detected, invalid shapes are refused with a message
// that names the problem, and destroying a body mid-simulation leaves a consistent world.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "perpdot/error.hpp"
#include "perpdot/world.hpp"
#include "physics_scenes.hpp"

namespace perpdot {
namespace {

using test::dt;

// Runs `f`, expecting perpdot::Error whose message contains `needle`.
template <class F>
void expectError(F&& f, const std::string& needle) {
    try {
        f();
        ADD_FAILURE() << "no perpdot::Error (expected one mentioning \"" << needle << "\")";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << "message: " << e.what();
    }
}

TEST(Api, StaleBodyIdIsAnErrorEvenAfterItsSlotIsReused) {
    World world;
    const BodyId old = test::addBox(world, {0.0f, 1.0f}, 0.5f, 0.5f);
    const ShapeId oldShape = world.shapes(old).front();
    world.destroyBody(old);
    EXPECT_FALSE(world.isValid(old));
    EXPECT_FALSE(world.isValid(oldShape));
    expectError([&] { world.position(old); }, "BodyId");
    expectError([&] { world.applyForce(old, {1.0f, 0.0f}, {}); }, "BodyId");
    expectError([&] { world.destroyBody(old); }, "BodyId");
    expectError([&] { world.friction(oldShape); }, "ShapeId");

    // The slot comes back with a new generation: the old handle still does not reach it.
    const BodyId reused = test::addBox(world, {5.0f, 1.0f}, 0.5f, 0.5f);
    ASSERT_EQ(reused.index, old.index);
    EXPECT_NE(reused.generation, old.generation);
    EXPECT_TRUE(world.isValid(reused));
    EXPECT_EQ(world.position(reused).x, 5.0f);
    expectError([&] { world.position(old); }, "BodyId");
    expectError([&] { world.position(BodyId{}); }, "BodyId");
}

TEST(Api, StaleShapeIdIsAnError) {
    World world;
    const BodyId body = test::addBox(world, {0.0f, 1.0f}, 0.5f, 0.5f);
    const ShapeId extra = world.createShape(body, {}, Circle{{1.0f, 0.0f}, 0.25f});
    world.destroyShape(extra);
    EXPECT_FALSE(world.isValid(extra));
    expectError([&] { world.circle(extra); }, "ShapeId");
    expectError([&] { world.setFriction(extra, 0.1f); }, "ShapeId");
    expectError([&] { world.destroyShape(extra); }, "ShapeId");
    EXPECT_EQ(world.shapes(body).size(), 1u);
    // Asking a live shape for the wrong geometry is an error too.
    expectError([&] { world.circle(world.shapes(body).front()); }, "not a circle");
}

TEST(Api, InvalidShapesAreRefusedWithAMessage) {
    World world;
    const BodyId body = world.createBody(test::bodyAt({}));
    const float nan = std::numeric_limits<float>::quiet_NaN();

    const Vec2 dart[] = {{0, 0}, {2, 1}, {0, 0.5f}, {-2, 1}};  // turns right at (0, 0.5)
    expectError([&] { makePolygon(dart); }, "convex");
    const Vec2 star[] = {{0, 1}, {0.6f, -0.8f}, {-0.95f, 0.3f}, {0.95f, 0.3f}, {-0.6f, -0.8f}};  // winds twice
    expectError([&] { makePolygon(star); }, "convex");
    std::vector<Vec2> nine;
    for (int k = 0; k < 9; ++k) nine.push_back({std::cos(2 * pi * k / 9), std::sin(2 * pi * k / 9)});
    expectError([&] { makePolygon(nine); }, "3 to 8 vertices");
    const Vec2 withNaN[] = {{0, 0}, {1, 0}, {nan, 1}};
    expectError([&] { makePolygon(withNaN); }, "not finite");
    const Vec2 square[] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    expectError([&] { makePolygon(square, -0.1f); }, "radius");

    // A hand-filled Polygon gets the same scrutiny at createShape.
    Polygon raw;
    raw.count = 3;
    raw.vertices[0] = {0, 0};
    raw.vertices[1] = {1, 0};
    raw.vertices[2] = {2, 0};  // collinear
    expectError([&] { world.createShape(body, {}, raw); }, "convex");

    ShapeDef negative;
    negative.density = -1.0f;
    expectError([&] { world.createShape(body, negative, makeBox(0.5f, 0.5f)); }, "density");
    expectError([&] { world.createShape(body, {}, Circle{{}, 0.0f}); }, "radius");
    expectError([&] { world.createShape(body, {}, Circle{{nan, 0.0f}, 1.0f}); }, "finite");
    expectError([&] { world.createShape(body, {}, Segment{{1, 1}, {1, 1}}); }, "segment");
    expectError([&] { makeBox(0.0f, 1.0f); }, "half extents");

    // Nothing half-made was left behind.
    EXPECT_TRUE(world.shapes(body).empty());
    EXPECT_EQ(world.mass(body), 1.0f) << "a dynamic body without shapes has the default unit mass";
}

TEST(Api, DestroyingABodyMidSimulationKeepsTheWorldConsistent) {
    // Three boxes stacked on the ground fall asleep; destroying the middle one removes its contacts,
    // wakes the top box, which then falls onto the bottom one.
    World world;
    test::addGround(world);
    const BodyId bottom = test::addBox(world, {0.0f, 0.5f}, 0.5f, 0.5f);
    const BodyId middle = test::addBox(world, {0.0f, 1.5f}, 0.5f, 0.5f);
    const BodyId top = test::addBox(world, {0.0f, 2.5f}, 0.5f, 0.5f);
    test::run(world, 120);
    ASSERT_FALSE(world.isAwake(top)) << "the stack should be asleep after 2 s";
    ASSERT_EQ(world.contactCount(), 3);
    const ShapeId middleShape = world.shapes(middle).front();
    const float topY = world.position(top).y;

    world.destroyBody(middle);
    EXPECT_EQ(world.bodyCount(), 3);
    const std::vector<BodyId> ids = world.bodies();
    EXPECT_EQ(std::count(ids.begin(), ids.end(), middle), 0);
    EXPECT_EQ(world.contactCount(), 1) << "only ground-bottom is left";
    for (const ContactData& c : world.contacts()) {
        EXPECT_TRUE(world.isValid(c.shapeA) && world.isValid(c.shapeB));
        EXPECT_NE(c.shapeA, middleShape);
        EXPECT_NE(c.shapeB, middleShape);
    }
    EXPECT_TRUE(world.isAwake(top)) << "the box above lost its support";
    EXPECT_TRUE(world.isAwake(bottom)) << "the box below lost its load";

    // It falls the 1 m gap (0.45 s) and lands on the bottom box: it ends about 1 m lower.
    test::run(world, 90);
    EXPECT_NEAR(world.position(top).y, topY - 1.0f, 0.05f);
    EXPECT_EQ(world.contactCount(), 2);
}

}  // namespace
}  // namespace perpdot
