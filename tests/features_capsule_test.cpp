// Capsules: mass from area integrals, manifolds against every shape type, slope friction, tipping,
// queries, scene JSON and bad input.
#include <gtest/gtest.h>

#include <cmath>

#include "features_helpers.hpp"
#include "perpdot/error.hpp"
#include "perpdot/scene.hpp"

namespace perpdot::features {
namespace {

TEST(Capsule, MassMatchesClosedForm) {
    const float r = 0.3f, len = 1.2f, rho = 2.0f;
    const MassData m = computeMass(Capsule{{-0.6f, 0.1f}, {0.6f, 0.1f}, r}, rho);
    // m = ρ(2rL + πr²); I = ρ[2rL(L² + 4r²)/12 + πr²(r²/2 + L²/4) + 4r³L/3] about the midpoint.
    const float mass = rho * (2 * r * len + pi * r * r);
    const float inertia = rho * (2 * r * len * (len * len + 4 * r * r) / 12 + pi * r * r * (r * r / 2 + len * len / 4) + 4 * r * r * r * len / 3);
    EXPECT_NEAR(m.mass, mass, 1e-5f * mass);
    EXPECT_NEAR(m.rotationalInertia, inertia, 1e-4f * inertia);
    EXPECT_NEAR(m.center.x, 0.0f, 1e-6f);
    EXPECT_NEAR(m.center.y, 0.1f, 1e-6f);
}

TEST(Capsule, BadGeometryIsRefused) {
    World world;
    const BodyId b = addDynamic(world, {});
    EXPECT_THROW(world.createShape(b, {}, Capsule{{0, 0}, {1, 0}, 0.0f}), Error);
    EXPECT_THROW(world.createShape(b, {}, Capsule{{0, 0}, {1, 0}, -1.0f}), Error);
    EXPECT_THROW(world.createShape(b, {}, Capsule{{0, 0}, {0.001f, 0}, 0.2f}), Error);
    EXPECT_THROW(world.createShape(b, {}, Capsule{{0, NAN}, {1, 0}, 0.2f}), Error);
    EXPECT_THROW(world.createShape(b, {}, Capsule{{0, 0}, {1, 0}, INFINITY}), Error);
}

// A capsule dropped flat onto each kind of ground rests on two contact points at its cap centres.
void expectFlatLanding(World& world) {
    const BodyId body = addDynamic(world, {0.0f, 1.0f});
    const ShapeId capsule = world.createShape(body, {}, Capsule{{-0.5f, 0.0f}, {0.5f, 0.0f}, 0.25f});
    run(world, 120);
    EXPECT_NEAR(world.position(body).y, 0.25f, 0.03f);
    EXPECT_NEAR(world.angle(body), 0.0f, 1e-3f);
    int points = 0;
    for (const ContactData& c : world.contacts())
        if (c.shapeA == capsule || c.shapeB == capsule) {
            points = c.pointCount;
            if (c.pointCount == 2) {
                EXPECT_NEAR(std::fabs(c.points[0].point.x - c.points[1].point.x), 1.0f, 0.02f);
            }
        }
    EXPECT_EQ(points, 2);
}

TEST(Capsule, DroppedFlatOnBoxLandsOnTwoPoints) {
    World world;
    addGround(world);
    expectFlatLanding(world);
}

TEST(Capsule, DroppedFlatOnSegmentAndChainLandsOnTwoPoints) {
    World a;
    a.createShape(addStatic(a, {}), {}, Segment{{-5, 0}, {5, 0}});
    expectFlatLanding(a);
    World b;
    b.createShape(addStatic(b, {}), {}, Chain{{{5, 0}, {-5, 0}}, false, ChainSide::Left});  // one-sided: shapes collide from above
    expectFlatLanding(b);
}

TEST(Capsule, DroppedFlatOnCapsuleLandsOnTwoPoints) {
    World world;
    world.createShape(addStatic(world, {0.0f, -0.5f}), {}, Capsule{{-3, 0}, {3, 0}, 0.5f});
    expectFlatLanding(world);
}

// Cap-to-cap along one line: Box2D 2.4's face-normal test alone would report a side contact.
TEST(Capsule, CollinearCapsulesMeetEndToEnd) {
    World world({.gravity = {0, 0}});
    world.createShape(addStatic(world, {}), {}, Capsule{{-1, 0}, {1, 0}, 0.2f});
    const BodyId moving = addDynamic(world, {2.6f, 0.0f}, {-1.0f, 0.0f});
    world.createShape(moving, {}, Capsule{{-0.5f, 0}, {0.5f, 0}, 0.2f});
    run(world, 120);
    EXPECT_NEAR(world.position(moving).y, 0.0f, 1e-3f);  // not pushed sideways
    EXPECT_GT(world.position(moving).x, 1.85f);          // stopped by the caps: 1 + 0.2 + 0.2 + 0.5
    EXPECT_LT(world.linearVelocity(moving).x, 0.05f);
}

TEST(Capsule, CircleAndBoxRestOnCapsule) {
    World world;
    world.createShape(addStatic(world, {}), {}, Capsule{{-3, 0}, {3, 0}, 0.5f});
    const BodyId ball = addDynamic(world, {-1.0f, 2.0f});
    world.createShape(ball, {}, Circle{{}, 0.3f});
    const BodyId box = addDynamic(world, {1.0f, 2.0f});
    world.createShape(box, {}, makeBox(0.3f, 0.3f));
    run(world, 180);
    EXPECT_NEAR(world.position(ball).y, 0.8f, 0.02f);
    EXPECT_NEAR(world.position(box).y, 0.81f, 0.03f);
}

// On a slope of angle θ with μ: holds when tanθ < μ, slides at a = g(sinθ − μ cosθ) above.
float slideAcceleration(float theta, float mu) {
    World world;
    const Vec2 down{std::cos(theta), -std::sin(theta)};  // downhill along the slope, to +x
    const Vec2 normal{std::sin(theta), std::cos(theta)};
    world.createShape(addStatic(world, {}), {.friction = mu}, Segment{-20.0f * down, 20.0f * down});
    const float r = 0.25f;
    const BodyId body = world.createBody({.type = BodyType::Dynamic, .position = r * normal, .angle = -theta});
    world.createShape(body, {.friction = mu}, Capsule{{-0.5f, 0}, {0.5f, 0}, r});
    run(world, 30);  // settle onto the slope
    const float v0 = dot(world.linearVelocity(body), down);
    run(world, 60);
    return (dot(world.linearVelocity(body), down) - v0) / (60 * dt);
}

TEST(Capsule, SlopeHoldsBelowFrictionAngle) {
    EXPECT_NEAR(slideAcceleration(0.3f, 0.5f), 0.0f, 0.02f);  // tan 0.3 = 0.31 < 0.5
}

TEST(Capsule, SlopeSlidesAtCoulombRateAboveFrictionAngle) {
    const float theta = 0.5f, mu = 0.2f;  // tan 0.5 = 0.55 > 0.2
    const float expected = 10.0f * (std::sin(theta) - mu * std::cos(theta));
    EXPECT_NEAR(slideAcceleration(theta, mu), expected, 0.03f * expected);
}

TEST(Capsule, BalancedOnEndCapTipsOver) {
    World world;
    addGround(world);
    const BodyId body = addDynamic(world, {0.0f, 0.8f});
    world.createShape(body, {}, Capsule{{0.0f, -0.55f}, {0.0f, 0.55f}, 0.25f});
    world.setAngularVelocity(body, 0.05f);  // the smallest nudge: a round cap has no stable balance
    run(world, 300);
    EXPECT_NEAR(world.position(body).y, 0.25f, 0.03f);
    EXPECT_NEAR(std::fabs(std::remainder(world.angle(body), pi)), 0.5f * pi, 0.02f);
}

TEST(Capsule, QueriesSeeTheRoundedSurface) {
    World world({.gravity = {0, 0}});
    const ShapeId capsule = world.createShape(addStatic(world, {}), {}, Capsule{{-1, 0}, {1, 0}, 0.5f});
    // Down onto the side: hits y = 0.5; along the axis: hits the cap at x = -1.5.
    const auto side = world.castRayClosest({0.3f, 3.0f}, {0.0f, -6.0f});
    ASSERT_TRUE(side.has_value());
    EXPECT_EQ(side->shape, capsule);
    EXPECT_NEAR(side->point.y, 0.5f, 1e-4f);
    EXPECT_NEAR(side->normal.y, 1.0f, 1e-4f);
    const auto cap = world.castRayClosest({-4.0f, 0.0f}, {6.0f, 0.0f});
    ASSERT_TRUE(cap.has_value());
    EXPECT_NEAR(cap->point.x, -1.5f, 1e-4f);
    EXPECT_NEAR(cap->normal.x, -1.0f, 1e-4f);
    EXPECT_EQ(world.overlapPoint({1.3f, 0.1f}).size(), 1u);  // in the cap
    EXPECT_TRUE(world.overlapPoint({1.45f, 0.45f}).empty());  // inside the core's box, outside the cap
    EXPECT_EQ(world.overlapShape(Circle{{}, 0.1f}, Transform{{0.0f, 0.55f}, {}}).size(), 1u);
}

TEST(Capsule, SnapshotRestoresBitExactly) {
    World world;
    addGround(world);
    const BodyId body = addDynamic(world, {0.0f, 2.0f});
    world.setAngularVelocity(body, 1.0f);
    world.createShape(body, {}, Capsule{{-0.5f, 0.0f}, {0.5f, 0.2f}, 0.25f});
    run(world, 20);
    const std::vector<uint8_t> bytes = world.snapshot();
    run(world, 60);
    const Transform first = world.transform(body);
    World copy;
    copy.restore(bytes);
    run(copy, 60);
    EXPECT_EQ(copy.transform(body).p, first.p);
    EXPECT_EQ(copy.transform(body).q, first.q);
    EXPECT_EQ(copy.capsule(copy.shapes(body)[0]), (Capsule{{-0.5f, 0.0f}, {0.5f, 0.2f}, 0.25f}));
}

TEST(Capsule, SceneJsonRoundTripsAndRefusesBadInput) {
    const std::string json = R"({"format": "perpdot-scene/1", "bodies": [{"type": "dynamic",
        "shapes": [{"type": "capsule", "center1": [-0.5, 0], "center2": [0.5, 0], "radius": 0.25}]}]})";
    const Scene scene = parseScene(json);
    ASSERT_EQ(scene.bodies[0].shapes[0].kind, SceneShape::Kind::Capsule);
    EXPECT_EQ(parseScene(toJson(scene)), scene);
    SceneWorld sim = buildWorld(scene);
    EXPECT_NEAR(sim.world.mass(sim.bodies[0]), computeMass(Capsule{{-0.5f, 0}, {0.5f, 0}, 0.25f}, 1.0f).mass, 1e-5f);
    auto refused = [&](const std::string& shape, const std::string& path) {
        const std::string bad = R"({"format": "perpdot-scene/1", "bodies": [{"shapes": [)" + shape + "]}]}";
        try {
            parseScene(bad);
            ADD_FAILURE() << shape;
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
        }
    };
    refused(R"({"type": "capsule", "center1": [0, 0], "center2": [1, 0], "radius": 0})", "shapes[0].radius");
    refused(R"({"type": "capsule", "center1": [0, 0], "center2": [0, 0], "radius": 0.2})", "shapes[0].center2");
    refused(R"({"type": "capsule", "center1": [0, 0], "radius": 0.2})", "center2");
    refused(R"({"type": "capsule", "center1": [0, 0], "center2": [1, 0], "radius": 0.2, "vertices": []})", "vertices");
}

}  // namespace
}  // namespace perpdot::features
