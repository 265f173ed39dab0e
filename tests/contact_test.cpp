// Contact response: restitution (bounce apex), Coulomb friction on an incline, rolling.
// Friction mixes as sqrt(μA μB) and restitution as max(eA, eB), so every test sets both shapes.
#include <gtest/gtest.h>

#include <cmath>

#include "perpdot/world.hpp"
#include "physics_scenes.hpp"

namespace perpdot {
namespace {

using test::dt;
using test::epsilon;

constexpr float g = 10.0f;

// Drop a ball whose bottom is `drop` above the ground; return (fall height, rise height), both
// measured from the lowest point of the first bounce so that the collision skin cancels.
std::pair<float, float> bounce(float restitution, float drop) {
    World world;
    test::addGround(world, 0.0f, 50.0f, test::material(1.0f, 0.6f, 0.0f));
    const float r = 0.25f;
    const BodyId ball = test::addDisc(world, {0.0f, r + drop}, r, test::material(1.0f, 0.6f, restitution));
    const float y0 = world.position(ball).y;
    float lowest = y0, apex = -1.0f;
    bool bounced = false;
    for (int i = 0; i < 300; ++i) {
        world.step(dt);
        const float y = world.position(ball).y, vy = world.linearVelocity(ball).y;
        if (!bounced) {
            lowest = std::min(lowest, y);
            bounced = lowest < y0 - 0.5f * drop && vy >= 0.0f;
        } else if (vy <= 0.0f) {
            apex = y;
            break;
        }
    }
    return {y0 - lowest, apex < 0.0f ? 0.0f : apex - lowest};
}

TEST(Contact, BouncingBallApexIsESquaredTimesDropHeight) {
    // Rebound speed = e × impact speed, so the apex is e² H. Discretisation bounds, with impact
    // speed v = sqrt(2 g H) and h = 1/60:
    //  - the velocity the restitution pass reflects is the one at the start of the impact step,
    //    uncertain by one step of gravity g h: changes e² v²/2g by e² v h;
    //  - semi-implicit Euler's fall: v² = 2 g H - g h v, i.e. e² v h / 2 on the rise;
    //  - semi-implicit Euler's rise stops v' h / 2 = e v h / 2 short of v'²/2g.
    const float H = 2.0f;
    const float v = std::sqrt(2.0f * g * H);
    for (float e : {0.5f, 0.8f}) {
        const auto [fall, rise] = bounce(e, H);
        // The contact exists only once the shapes overlap (b2Collide* makes no speculative points and
        // a ball this slow is not swept), so the ball may sink up to one step of travel v h, less
        // the 0.01 m polygon skin, before it is stopped.
        ASSERT_GE(fall, H - 0.01f);
        ASSERT_LE(fall, H + v * dt);
        const float tolerance = 1.5f * e * e * v * dt + 0.5f * e * v * dt;
        EXPECT_NEAR(rise, e * e * fall, tolerance) << "e = " << e;
    }
    // Without restitution (e = 0 mixes with the ground's 0) the ball only climbs out of its overlap:
    // its bottom never rises above the ground's 0.01 m skin.
    const auto [fall, rise] = bounce(0.0f, H);
    EXPECT_LT(H - fall + rise, 0.01f) << "fell " << fall << ", rose " << rise;
}

struct Incline {
    World world;
    BodyId block;
    float theta;
    Vec2 downhill, normal;  // unit vectors along and out of the slope
};

// A static ramp at angle θ and a 1 m x 0.5 m block resting on it, both with friction μ.
void makeIncline(Incline& s, float theta, float mu, bool disc) {
    s.theta = theta;
    const Rot q = Rot::fromAngle(theta);
    s.downhill = rotate(q, {-1.0f, 0.0f});
    s.normal = rotate(q, {0.0f, 1.0f});
    const BodyId ramp = s.world.createBody(test::bodyAt({}, BodyType::Static));
    s.world.createShape(ramp, test::material(0.0f, mu), makeBox(20.0f, 0.25f, {}, theta));
    // Start 2 mm above the surface (inside the speculative margin) so it settles at once.
    const float lift = 0.25f + 0.002f;
    if (disc) {
        s.block = test::addDisc(s.world, rotate(q, {5.0f, lift + 0.5f}), 0.5f, test::material(1.0f, mu));
    } else {
        s.block = test::addBox(s.world, rotate(q, {5.0f, lift + 0.25f}), 0.5f, 0.25f, test::material(1.0f, mu), theta);
    }
}

TEST(Contact, BlockOnInclineHoldsWhenTanThetaBelowMu) {
    // θ = 20°: tan θ = 0.364 < μ = 0.6, so static friction holds the block. A slide at even 0.5 % of g
    // would cover ½ a t² = 10 cm in 2 s; the rigid friction rows allow only the settling transient.
    Incline s;
    makeIncline(s, 20.0f * pi / 180.0f, 0.6f, false);
    test::run(s.world, 12);  // 0.2 s to settle onto the contact
    const Vec2 start = s.world.position(s.block);
    test::run(s.world, 120);
    EXPECT_LT(std::fabs(dot(s.world.position(s.block) - start, s.downhill)), 0.005f);
    EXPECT_LT(std::fabs(dot(s.world.linearVelocity(s.block), s.downhill)), 0.01f);
    // The same block on ice slides: the hold is friction's doing.
    Incline ice;
    makeIncline(ice, 20.0f * pi / 180.0f, 0.0f, false);
    test::run(ice.world, 132);
    EXPECT_GT(dot(ice.world.linearVelocity(ice.block), ice.downhill), 0.9f * g * std::sin(ice.theta) * 2.0f);
}

TEST(Contact, BlockOnSteepInclineSlidesWithCoulombDeceleration) {
    // θ = 30°, μ = 0.2 < tan θ: a = g (sin θ - μ cos θ), measured from the velocity along the slope
    // over [0.5 s, 1.5 s]. Along the slope m Δv_t = (m g sin θ - μ N̄) Δt exactly, and across it
    // N̄ = m g cos θ + m Δv_n / Δt, so the measured a misses the formula by μ |Δv_n| / Δt, plus float
    // rounding of ~10 operations per substep on |v| ≤ 5 m/s over 240 substeps (≈ 2e-3 m/s).
    Incline s;
    const float mu = 0.2f;
    makeIncline(s, 30.0f * pi / 180.0f, mu, false);
    test::run(s.world, 30);
    const Vec2 v1 = s.world.linearVelocity(s.block);
    test::run(s.world, 60);
    const Vec2 v2 = s.world.linearVelocity(s.block);
    const float vn1 = dot(v1, s.normal), vn2 = dot(v2, s.normal);
    ASSERT_LT(std::fabs(vn1) + std::fabs(vn2), 0.02f) << "the block should be settled on the slope";
    const float a = dot(v2 - v1, s.downhill) / 1.0f;
    const float expected = g * (std::sin(s.theta) - mu * std::cos(s.theta));
    EXPECT_NEAR(a, expected, mu * std::fabs(vn2 - vn1) / 1.0f + 2e-3f);
}

// A 1 m box dropped 1 cm rests on its true surface (on the static ground each polygon keeps 0.5 mm
// of Box2D's skin as a rest gap); with WorldDef::box2dSkin it rests on Box2D 2.4's skins as b2World does: 0.015 m higher.
TEST(Contact, BoxRestsOnItsTrueSurfaceOrOnBox2DsSkin) {
    for (const bool box2dSkin : {false, true}) {
        World world({.box2dSkin = box2dSkin});
        test::addGround(world);
        const BodyId box = test::addBox(world, {0.0f, 0.51f}, 0.5f, 0.5f);
        test::run(world, 120);
        const float rest = box2dSkin ? 0.5f + 2 * 0.01f - 0.005f : 0.5f;  // skins less the linear slop
        EXPECT_NEAR(world.position(box).y, rest, 2e-3f) << (box2dSkin ? "on Box2D's skin" : "true surfaces");
        EXPECT_NEAR(world.linearVelocity(box).y, 0.0f, 1e-3f);
    }
}

// The rest gap follows the partner's type: a box keeps 1 mm (0.5 mm of skin each) over a static
// or a kinematic box, and none over a dynamic one (docs/stress.md, "True-surface contact").
TEST(Contact, RestGapIsKeptOnlyAgainstStaticAndKinematicBodies) {
    for (const BodyType type : {BodyType::Static, BodyType::Kinematic}) {
        World world({.enableSleep = false});
        const BodyId below = world.createBody(test::bodyAt({0.0f, -0.5f}, type));
        world.createShape(below, {}, makeBox(0.5f, 0.5f));
        const BodyId box = test::addBox(world, {0.0f, 0.5f}, 0.5f, 0.5f);
        test::run(world, 300);
        const float gap = world.position(box).y - 0.5f;
        EXPECT_GT(gap, 0.0005f) << (type == BodyType::Static ? "static" : "kinematic");
        EXPECT_LT(gap, 0.0011f) << (type == BodyType::Static ? "static" : "kinematic");
    }
    World world({.enableSleep = false});
    test::addGround(world);
    const BodyId lower = test::addBox(world, {0.0f, 0.5f}, 0.5f, 0.5f);
    const BodyId upper = test::addBox(world, {0.0f, 1.5f}, 0.5f, 0.5f);
    test::run(world, 300);
    // No gap: the upper box rests on the lower one's true surface, its rows' rest sink offset
    // (support_sinks.hpp), where a 1 mm gap would put it 1.001 m apart.
    const float apart = world.position(upper).y - world.position(lower).y;
    EXPECT_NEAR(apart, 1.0f, 2e-4f) << "dynamic on dynamic";
}

TEST(Contact, DiscRollsWithoutSlippingAtTwoThirdsGSinTheta) {
    // A disc (I = m r²/2) rolling without slip: a = g sin θ / (1 + I/(m r²)) = ⅔ g sin θ and ω r = v.
    // Friction needed: ⅓ m g sin θ ≤ μ m g cos θ for μ ≥ tan θ / 3 = 0.19; μ = 0.8 keeps it rolling.
    // The friction row zeroes the slip at the contact anchor, which (as in Box2D) sits midway
    // through the resting overlap of about linearSlop = 0.005 m: the disc rolls on a radius
    // r' ∈ [R - slop, R]. Hence ω R / v ∈ [1, R/(R - slop)] and
    // a ∈ [g sin θ / (1 + ½ (R/(R - slop))²), ⅔ g sin θ].
    Incline s;
    makeIncline(s, 30.0f * pi / 180.0f, 0.8f, true);
    test::run(s.world, 30);
    const Vec2 v1 = s.world.linearVelocity(s.block);
    test::run(s.world, 60);
    const Vec2 v2 = s.world.linearVelocity(s.block);
    const float R = 0.5f, slop = 0.005f, gs = g * std::sin(s.theta);
    const float aRolling = 2.0f / 3.0f * gs;
    const float aShortRadius = gs / (1.0f + 0.5f * (R / (R - slop)) * (R / (R - slop)));
    const float a = dot(v2 - v1, s.downhill);
    EXPECT_LE(a, aRolling + 2e-3f);  // 2e-3: float rounding over the window, as for the block
    EXPECT_GE(a, aShortRadius - 2e-3f);

    // Rolling, not sliding: ω R matches the speed along the slope within the same radius band.
    const float v = dot(v2, s.downhill), w = s.world.angularVelocity(s.block);
    EXPECT_GT(w, 0.0f) << "rolling down to the left turns counter-clockwise";
    EXPECT_GE(w * R, v * (1.0f - 1e-4f));
    EXPECT_LE(w * R, v * R / (R - slop));
    // A frictionless disc would slide at g sin θ without turning: the test tells the two apart.
    Incline ice;
    makeIncline(ice, 30.0f * pi / 180.0f, 0.0f, true);
    test::run(ice.world, 90);
    EXPECT_NEAR(ice.world.angularVelocity(ice.block), 0.0f, 1e-3f);  // rolling would be ~7 rad/s by now
    EXPECT_GT(dot(ice.world.linearVelocity(ice.block), ice.downhill), 1.4f * 0.9f * gs);
}

}  // namespace
}  // namespace perpdot
