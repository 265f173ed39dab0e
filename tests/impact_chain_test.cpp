// Simultaneous impacts through a chain of touching balls (impact_propagation.cpp): without gravity
// or friction, e = 1, a ball at 2 m/s into a touching row leaves every ball at rest but the last,
// which takes the 2 m/s — Newton's cradle, the textbook's sequence of two-body impacts — with kinetic
// energy and momentum kept; with e < 1 a head-on pair ends at Hecker's velocities,
// vA' = (1 − e) u / 2, vB' = (1 + e) u / 2 for equal masses and A at u into B at rest.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "perpdot/joints.hpp"
#include "perpdot/scene.hpp"
#include "perpdot/world.hpp"
#include "physics_scenes.hpp"

namespace perpdot {
namespace {

using test::dt;

constexpr float radius = 0.25f;

// `count` equal balls along x, `gap` apart, e = restitution, frictionless and weightless; the
// first `released` at speed u.
std::vector<BodyId> addRow(World& world, int count, float gap, float restitution, int released, float u) {
    const ShapeDef def = test::material(1.0f, 0.0f, restitution);
    std::vector<BodyId> balls;
    for (int i = 0; i < count; ++i) {
        balls.push_back(test::addDisc(world, {static_cast<float>(i) * (2.0f * radius + gap), 0.0f}, radius, def));
        if (i < released) world.setLinearVelocity(balls.back(), {u, 0.0f});
    }
    return balls;
}

WorldDef weightless() {
    WorldDef def;
    def.gravity = {0.0f, 0.0f};
    def.enableSleep = false;
    return def;
}

float kineticEnergy(const World& world, const std::vector<BodyId>& balls) {
    float energy = 0.0f;
    for (BodyId id : balls) energy += 0.5f * world.mass(id) * lengthSquared(world.linearVelocity(id));
    return energy;
}

Vec2 momentum(const World& world, const std::vector<BodyId>& balls) {
    Vec2 p;
    for (BodyId id : balls) p += world.mass(id) * world.linearVelocity(id);
    return p;
}

struct Cradle {
    int count, released;
    float gap;
};

class NewtonsCradle : public testing::TestWithParam<Cradle> {};

// The last `released` balls leave at u, the others stay: within 5 % of u, energy within 1 %,
// momentum to float rounding.
TEST_P(NewtonsCradle, TheLastBallsTakeTheSpeed) {
    const Cradle cradle = GetParam();
    const float u = 2.0f;
    World world(weightless());
    const std::vector<BodyId> balls = addRow(world, cradle.count, cradle.gap, 1.0f, cradle.released, u);
    const float energy0 = kineticEnergy(world, balls);
    const Vec2 p0 = momentum(world, balls);
    test::run(world, 60);
    for (int i = 0; i < cradle.count; ++i) {
        const float expected = i >= cradle.count - cradle.released ? u : 0.0f;
        EXPECT_NEAR(world.linearVelocity(balls[static_cast<size_t>(i)]).x, expected, 0.05f * u) << "ball " << i;
    }
    EXPECT_NEAR(kineticEnergy(world, balls), energy0, 0.01f * energy0);
    EXPECT_NEAR(length(momentum(world, balls) - p0), 0.0f, 1e-5f * length(p0));
}

INSTANTIATE_TEST_SUITE_P(Touching, NewtonsCradle, testing::Values(Cradle{5, 1, 0.0f}, Cradle{5, 2, 0.0f}, Cradle{7, 3, 0.0f}));
INSTANTIATE_TEST_SUITE_P(Gaps, NewtonsCradle, testing::Values(Cradle{5, 1, 0.001f}, Cradle{7, 2, 0.001f}));

// The cradle on pendulum strings, under gravity: `count` balls hung on 1 m rigid strings (distance
// joints) from pivots 2r + gap apart, the first `released` pulled aside together to 30° and let go.
// They meet the row at u = √(2 g L (1 − cos 30°)) = 1.64 m/s; after the impact the last `released`
// swing out at u and the others hang still: each ball's largest speed over the next quarter swing
// within 5 % of the textbook's (u or 0), and the mechanical energy (height from where the balls
// hang) kept within 1 %. A pair of circles has its contact from the step before they meet
// (collision.hpp, collisionSkin), so a ball that closes a gap mid-step passes the impact on the
// same step instead of going a step's travel into its neighbour first.
class NewtonsCradleOnStrings : public testing::TestWithParam<Cradle> {};

TEST_P(NewtonsCradleOnStrings, TheLastBallsSwingOut) {
    const Cradle cradle = GetParam();
    const float stringLength = 1.0f, g = 10.0f, release = 30.0f * pi / 180.0f;
    WorldDef def;
    def.gravity = {0.0f, -g};
    def.enableSleep = false;
    World world(def);
    const BodyId ceiling = world.createBody(test::bodyAt({0.0f, 0.0f}, BodyType::Static));
    std::vector<BodyId> balls;
    for (int i = 0; i < cradle.count; ++i) {
        const float pivot = static_cast<float>(i) * (2.0f * radius + cradle.gap);
        const float angle = i < cradle.released ? release : 0.0f;
        balls.push_back(test::addDisc(world, {pivot - stringLength * std::sin(angle), -stringLength * std::cos(angle)}, radius,
                                      test::material(1.0f, 0.0f, 1.0f)));
        DistanceJointDef string;
        string.bodyA = ceiling, string.bodyB = balls.back();
        string.localAnchorA = {pivot, 0.0f};
        string.length = stringLength;
        world.createJoint(string);
    }
    auto energy = [&] {
        float e = 0.0f;
        for (BodyId id : balls) e += world.mass(id) * (0.5f * lengthSquared(world.linearVelocity(id)) + g * (world.position(id).y + stringLength));
        return e;
    };
    const float u = std::sqrt(2.0f * g * stringLength * (1.0f - std::cos(release)));
    const float energy0 = energy();
    // Until the last ball is struck, then a quarter of the period 2π √(L/g) (30 steps).
    const BodyId last = balls.back();
    int step = 0;
    while (world.linearVelocity(last).x < 0.5f * u && step < 120) world.step(dt), ++step;
    ASSERT_LT(step, 120) << "the last ball was never struck";
    std::vector<float> fastest(balls.size(), 0.0f);
    for (int i = 0; i < 30; ++i) {
        for (size_t k = 0; k < balls.size(); ++k) fastest[k] = std::max(fastest[k], length(world.linearVelocity(balls[k])));
        EXPECT_NEAR(energy(), energy0, 0.01f * energy0) << "step " << i;
        world.step(dt);
    }
    for (int i = 0; i < cradle.count; ++i) {
        const float expected = i >= cradle.count - cradle.released ? u : 0.0f;
        EXPECT_NEAR(fastest[static_cast<size_t>(i)], expected, 0.05f * u) << "ball " << i;
    }
}

INSTANTIATE_TEST_SUITE_P(Released30Degrees, NewtonsCradleOnStrings,
                         testing::Values(Cradle{5, 1, 0.0f}, Cradle{5, 2, 0.0f}, Cradle{5, 3, 0.0f}, Cradle{7, 1, 0.0f},
                                         Cradle{7, 2, 0.0f}, Cradle{7, 3, 0.0f}, Cradle{5, 1, 0.001f}, Cradle{5, 2, 0.001f},
                                         Cradle{5, 3, 0.001f}, Cradle{7, 3, 0.001f}));

// The built-in newtons_cradle: the striker at 4 m/s ends its 30th step exactly touching the row,
// and the contact (within a circle pair's 1 cm skin) exists then: after 1 s the far ball runs at
// 4 m/s and the others are at rest, each to 0.01 m/s.
TEST(ImpactChain, TheBuiltInCradleHandsTheStrikersSpeedToTheFarBall) {
    SceneWorld cradle = buildWorld(findScene("newtons_cradle"));
    for (int i = 0; i < 60; ++i) cradle.step();
    for (size_t i = 0; i < cradle.bodies.size(); ++i) {
        const std::string& name = cradle.scene.bodies[i].name;
        if (cradle.scene.bodies[i].type != BodyType::Dynamic) continue;
        const float expected = name == "ball4" ? 4.0f : 0.0f;
        EXPECT_NEAR(length(cradle.world.linearVelocity(cradle.bodies[i]) - Vec2{expected, 0.0f}), 0.0f, 0.01f) << name;
    }
}

// Two touching balls head-on, e = 0.5: A keeps (1 − e) u / 2, B takes (1 + e) u / 2.
TEST(ImpactChainRestitution, HeadOnPairEndsAtHeckersVelocities) {
    const float e = 0.5f, u = 2.0f;
    World world(weightless());
    const std::vector<BodyId> balls = addRow(world, 2, 0.0f, e, 1, u);
    const Vec2 p0 = momentum(world, balls);
    test::run(world, 30);
    EXPECT_NEAR(world.linearVelocity(balls[0]).x, 0.5f * (1.0f - e) * u, 1e-4f * u);
    EXPECT_NEAR(world.linearVelocity(balls[1]).x, 0.5f * (1.0f + e) * u, 1e-4f * u);
    EXPECT_NEAR(length(momentum(world, balls) - p0), 0.0f, 1e-5f * length(p0));
}

// A game hears the impact: a ball at 5 m/s into a resting one, both with hit events, raises one
// hit at the approach speed, though the impact is resolved before the rows see the approach.
TEST(ImpactChain, AnImpactPassedOnRaisesItsHitEvent) {
    World world(weightless());
    ShapeDef def = test::material(1.0f, 0.0f, 1.0f);
    def.enableHitEvents = true;
    const BodyId striker = test::addDisc(world, {-1.0f, 0.0f}, radius, def);
    test::addDisc(world, {0.0f, 0.0f}, radius, def);
    world.setLinearVelocity(striker, {5.0f, 0.0f});
    int hits = 0;
    float speed = 0.0f;
    for (int i = 0; i < 30; ++i) {
        world.step(dt);
        for (const ContactHitEvent& e : world.contactEvents().hitEvents) {
            ++hits;
            speed = e.approachSpeed;
        }
    }
    EXPECT_EQ(hits, 1);
    EXPECT_NEAR(speed, 5.0f, 0.05f);
}

}  // namespace
}  // namespace perpdot
