// The headline formula, tested directly through the engine: Hecker's two-body
// collision impulse
//   j = -(1+e) v_rel·n / (1/mA + 1/mB + perpDot(rA,n)²/IA + perpDot(rB,n)²/IB)
// on off-centre hits, then vA' = vA - j n/mA, ωA' = ωA - perpDot(rA, j n)/IA (and + for B);
// friction mixed as sqrt(μA μB); and the warm-start switch.
//
// Why the engine gives the closed form within float rounding: gravity is off, friction 0 and the
// bodies start 1 mm apart, inside the speculative margin, so the first step's rigid rows stop the
// approach at the contact (v_rel·n → 0 with the step's fixed anchors) and the restitution pass then
// drives v_rel·n to -e times its value before the step. Both passes use the effective mass of the
// bracket, so the total normal impulse is exactly Hecker's j.
#include <gtest/gtest.h>

#include <cmath>

#include "perpdot/world.hpp"
#include "physics_scenes.hpp"

namespace perpdot {
namespace {

using test::dt;

WorldDef weightless() {
    WorldDef def;
    def.gravity = {0.0f, 0.0f};
    def.enableSleep = false;
    return def;
}

struct Body {
    BodyId id;
    float m = 0.0f, I = 0.0f;
    Vec2 v;
    float w = 0.0f;
    Vec2 c;  // centre of mass
};

Body snapshotOf(const World& world, BodyId id) {
    return {id, world.mass(id), world.rotationalInertia(id), world.linearVelocity(id), world.angularVelocity(id), world.worldCenter(id)};
}

// Hecker's impulse on B along n (n from A to B) at the world point p, and the velocities after it.
struct Outcome {
    float j = 0.0f;
    Vec2 vA, vB;
    float wA = 0.0f, wB = 0.0f;
};

Outcome hecker(const Body& a, const Body& b, Vec2 p, Vec2 n, float e) {
    const Vec2 rA = p - a.c, rB = p - b.c;
    const Vec2 vRel = pointVelocity(b.v, b.w, rB) - pointVelocity(a.v, a.w, rA);
    const float rnA = perpDot(rA, n), rnB = perpDot(rB, n);
    const float k = 1.0f / a.m + 1.0f / b.m + rnA * rnA / a.I + rnB * rnB / b.I;
    Outcome o;
    o.j = -(1.0f + e) * dot(vRel, n) / k;
    const Vec2 J = o.j * n;
    o.vA = a.v - (1.0f / a.m) * J;
    o.vB = b.v + (1.0f / b.m) * J;
    o.wA = a.w - perpDot(rA, J) / a.I;
    o.wB = b.w + perpDot(rB, J) / b.I;
    return o;
}

// Linear momentum and angular momentum about the origin: Σ m v, Σ (m perpDot(c, v) + I ω).
Vec2 momentum(const World& world, std::initializer_list<BodyId> ids) {
    Vec2 p;
    for (BodyId id : ids) p += world.mass(id) * world.linearVelocity(id);
    return p;
}
float angularMomentum(const World& world, std::initializer_list<BodyId> ids) {
    float L = 0.0f;
    for (BodyId id : ids)
        L += world.mass(id) * perpDot(world.worldCenter(id), world.linearVelocity(id)) + world.rotationalInertia(id) * world.angularVelocity(id);
    return L;
}

class HeckerImpulse : public testing::TestWithParam<float> {};

// A ball falls on the end of a free rod lying across its path: the rod takes the impulse 0.9 m
// from its centre, so it both moves and spins; the ball's lever arm is along n (perpDot = 0).
TEST_P(HeckerImpulse, BallOnTheEndOfAFreeRod) {
    const float e = GetParam();
    World world(weightless());
    const ShapeDef def = test::material(1.0f, 0.0f, e);
    const BodyId rod = test::addBox(world, {0.0f, 0.0f}, 1.0f, 0.05f, def);
    const float radius = 0.1f;
    const BodyId ball = world.createBody(test::bodyAt({0.9f, 0.05f + radius + 0.001f}));
    world.createShape(ball, def, Circle{{}, radius});
    world.setLinearVelocity(ball, {0.0f, -5.0f});
    const Body a = snapshotOf(world, rod), b = snapshotOf(world, ball);
    const Vec2 p0 = momentum(world, {rod, ball});
    const float L0 = angularMomentum(world, {rod, ball});

    world.step(dt);
    const Outcome o = hecker(a, b, {0.9f, 0.05f}, {0.0f, 1.0f}, e);
    ASSERT_GT(o.j, 0.0f);
    const float tol = 2e-3f * std::fabs(o.vB.y - b.v.y);  // 0.2 % of the velocity change
    EXPECT_NEAR(world.linearVelocity(ball).y, o.vB.y, tol);
    EXPECT_NEAR(world.linearVelocity(ball).x, 0.0f, 1e-5f);
    EXPECT_NEAR(world.angularVelocity(ball), o.wB, 1e-4f);
    EXPECT_NEAR(world.linearVelocity(rod).y, o.vA.y, tol);
    EXPECT_NEAR(world.angularVelocity(rod), o.wA, 2e-3f * std::fabs(o.wA));
    // The bounce: v_rel·n afterwards is -e times before, at the contact point.
    const Vec2 rA = Vec2{0.9f, 0.05f} - world.worldCenter(rod);
    const float vnAfter = world.linearVelocity(ball).y - pointVelocity(world.linearVelocity(rod), world.angularVelocity(rod), rA).y;
    EXPECT_NEAR(vnAfter, 5.0f * e, 0.01f * 5.0f);
    // Momenta are kept by equal and opposite impulses at one point.
    EXPECT_NEAR(length(momentum(world, {rod, ball}) - p0), 0.0f, 1e-5f * length(p0));
    EXPECT_NEAR(angularMomentum(world, {rod, ball}), L0, 1e-5f * std::fabs(L0) + 1e-6f);
}

// A box turned 0.5 rad comes down corner first on a resting box, off its centre: both lever arms
// are off the normal, so both boxes spin.
TEST_P(HeckerImpulse, BoxCornerOnAnotherBoxOffCentre) {
    const float e = GetParam();
    World world(weightless());
    const ShapeDef def = test::material(1.0f, 0.0f, e);
    const BodyId lower = test::addBox(world, {0.0f, 0.0f}, 1.0f, 0.5f, def);
    // A 0.5 m box turned 0.5 rad: its lowest vertex is off to the side of its centre.
    const float half = 0.25f, angle = 0.5f;
    Vec2 lowest{0.0f, 1e9f};
    for (Vec2 v : {Vec2{-half, -half}, Vec2{half, -half}, Vec2{half, half}, Vec2{-half, half}})
        if (rotate(Rot::fromAngle(angle), v).y < lowest.y) lowest = rotate(Rot::fromAngle(angle), v);
    ASSERT_GT(std::fabs(lowest.x), 0.05f);
    const Vec2 corner{0.6f, 0.5f + 0.001f};
    const BodyId upper = test::addBox(world, corner - lowest, half, half, def, angle);
    world.setLinearVelocity(upper, {0.0f, -4.0f});
    const Body a = snapshotOf(world, lower), b = snapshotOf(world, upper);
    const Vec2 p0 = momentum(world, {lower, upper});
    const float L0 = angularMomentum(world, {lower, upper});

    world.step(dt);
    const std::vector<ContactData> contacts = world.contacts();
    ASSERT_EQ(contacts.size(), 1u);
    ASSERT_EQ(contacts[0].pointCount, 1);
    const Outcome o = hecker(a, b, contacts[0].points[0].point, {0.0f, 1.0f}, e);
    ASSERT_GT(o.j, 0.0f);
    const float dv = std::fabs(o.vB.y - b.v.y);
    EXPECT_NEAR(world.linearVelocity(upper).y, o.vB.y, 3e-3f * dv);
    EXPECT_NEAR(world.linearVelocity(lower).y, o.vA.y, 3e-3f * dv);
    EXPECT_NEAR(world.angularVelocity(upper), o.wB, 3e-3f * std::fabs(o.wB) + 1e-4f);
    EXPECT_NEAR(world.angularVelocity(lower), o.wA, 3e-3f * std::fabs(o.wA) + 1e-4f);
    EXPECT_NE(o.wA, 0.0f);
    EXPECT_NE(o.wB, 0.0f);
    EXPECT_NEAR(length(momentum(world, {lower, upper}) - p0), 0.0f, 1e-5f * length(p0));
    EXPECT_NEAR(angularMomentum(world, {lower, upper}), L0, 1e-5f * std::fabs(L0) + 1e-6f);
}

INSTANTIATE_TEST_SUITE_P(Restitution, HeckerImpulse, testing::Values(0.5f, 1.0f),
                         [](const auto& info) { return info.param == 1.0f ? std::string("e1") : std::string("e05"); });

// Unequal friction coefficients mix as sqrt(μA μB): a box sliding at 5 m/s on a ground of μ 0.8
// with its own μ 0.2 decelerates at sqrt(0.16) g = 4 m/s², not at 0.2 g, 0.8 g or their mean 5.
TEST(FrictionMixing, UnequalCoefficientsMixAsTheGeometricMean) {
    World world({.enableSleep = false});
    test::addGround(world, 0.0f, 50.0f, test::material(0.0f, 0.8f));
    const BodyId box = test::addBox(world, {0.0f, 0.5f}, 0.5f, 0.5f, test::material(1.0f, 0.2f));
    test::run(world, 10);  // settle on the ground
    world.setLinearVelocity(box, {5.0f, 0.0f});
    test::run(world, 1);
    const float v0 = world.linearVelocity(box).x;
    test::run(world, 30);
    const float a = (v0 - world.linearVelocity(box).x) / (30.0f * dt);
    EXPECT_NEAR(a, std::sqrt(0.2f * 0.8f) * 10.0f, 0.02f * 4.0f);
}

// Warm starting off: each step's rows start from zero impulse instead of the last step's. The
// stack still stands, but the switch is real: the soft rows, starting from nothing, end each step
// short of the load and the column rests measurably lower.
TEST(WarmStarting, OffStillStandsButSinksDeeper) {
    float top[2];
    for (const bool warm : {true, false}) {
        World world({.enableSleep = false, .enableWarmStarting = warm});
        test::addGround(world);
        BodyId last;
        for (int i = 0; i < 5; ++i) last = test::addBox(world, {0.0f, 0.5f + float(i)}, 0.5f, 0.5f);
        test::run(world, 300);
        EXPECT_NEAR(world.position(last).x, 0.0f, 0.05f) << (warm ? "warm" : "cold");
        EXPECT_NEAR(world.linearVelocity(last).y, 0.0f, 0.05f) << (warm ? "warm" : "cold");
        top[warm ? 0 : 1] = world.position(last).y;
    }
    EXPECT_GT(top[0] - top[1], 1e-3f) << "warm " << top[0] << ", cold " << top[1];
    EXPECT_GT(top[1], 4.5f - 0.5f) << "the cold column sank through";
}

}  // namespace
}  // namespace perpdot
