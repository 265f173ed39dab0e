// Free-body dynamics: semi-implicit Euler flight, torque-free spin, forces and impulses at
// points (Hecker's τ = perpDot(r, F)), damping and gravity scale.
//
// Float rounding bounds used below: one float operation is exact to ε/2 relative (ε = 2^-23);
// a quantity updated k times by operations on magnitudes ≤ M drifts by at most k·ε·M.
#include <gtest/gtest.h>

#include <cmath>

#include "perpdot/world.hpp"
#include "physics_scenes.hpp"

namespace perpdot {
namespace {

using test::dt;
using test::epsilon;

WorldDef zeroGravity() { return {.gravity = {0.0f, 0.0f}}; }

TEST(Dynamics, FreeFlightFollowsTheDiscreteSemiImplicitEulerParabola) {
    // v_n = v0 - g n h, and x += h v after v is updated, so
    //   y_n = y0 + v0 n h - g h² n(n+1)/2   (exact discrete),
    //   y_n = y(t) - g h t / 2              (analytic y(t) = y0 + v0 t - g t²/2, t = n h).
    World world;
    const double g = 10.0, h = dt, x0 = -1.0, y0 = 10.0, vx = 2.0, vy = 8.0;
    const BodyId ball = test::addDisc(world, {-1.0f, 10.0f}, 0.25f);
    world.setLinearVelocity(ball, {2.0f, 8.0f});

    const int steps = 120;
    // Rounding: per step, y += Δy (|y| ≤ 13.2 m) and v += g h (|v| ≤ 12 m/s, its error is then carried
    // for the remaining T = 2 s): |error| ≤ n ε (max|y| + max|v| T).
    const double tol = steps * epsilon * (13.2 + 12.0 * 2.0);
    for (int n = 1; n <= steps; ++n) {
        world.step(dt);
        const double t = n * h;
        const double yDiscrete = y0 + vy * n * h - g * h * h * n * (n + 1) / 2;
        const Vec2 p = world.position(ball);
        ASSERT_NEAR(p.y, yDiscrete, tol) << "step " << n;
        ASSERT_NEAR(p.x, x0 + vx * t, tol) << "step " << n;
        ASSERT_NEAR(world.linearVelocity(ball).y, vy - g * t, n * epsilon * 12.0) << "step " << n;
        // The analytic parabola is missed by exactly g h t/2, no more.
        const double yAnalytic = y0 + vy * t - g * t * t / 2;
        ASSERT_LE(std::fabs(p.y - yAnalytic), g * h * t / 2 + tol) << "step " << n;
    }
    // And that error is really there (this is semi-implicit, not exact or explicit, Euler).
    EXPECT_GT(std::fabs(world.position(ball).y - (y0 + vy * 2.0 - g * 2.0)), 0.9 * g * h * 2.0 / 2);
}

TEST(Dynamics, GravityScaleScalesTheFallAcceleration) {
    // v_n = v0 + s g n h for gravity scale s; up to n ε |v| of rounding.
    World world;
    const float scales[] = {0.5f, 0.0f, -1.0f, 2.0f};
    std::vector<BodyId> balls;
    for (int i = 0; i < 4; ++i) {
        BodyDef def = test::bodyAt({3.0f * i, 0.0f});
        def.gravityScale = scales[i];
        const BodyId b = world.createBody(def);
        world.createShape(b, {}, Circle{{}, 0.5f});
        balls.push_back(b);
    }
    const int steps = 60;
    test::run(world, steps);
    for (int i = 0; i < 4; ++i) {
        const double v = -10.0 * scales[i] * steps * dt;
        EXPECT_NEAR(world.linearVelocity(balls[i]).y, v, 4 * steps * epsilon * 20.0) << "scale " << scales[i];
        EXPECT_FLOAT_EQ(world.gravityScale(balls[i]), scales[i]);
    }
    // Changing the scale mid-flight changes the acceleration from the next step on.
    world.setGravityScale(balls[0], 3.0f);
    const float before = world.linearVelocity(balls[0]).y;
    world.step(dt);
    EXPECT_NEAR(world.linearVelocity(balls[0]).y - before, -10.0 * 3.0 * dt, 8 * epsilon * 20.0);
}

TEST(Dynamics, TorqueFreeSpinKeepsOmegaAndKineticEnergy) {
    // Zero gravity, no torque: ω stays ω0, the centre of mass stays put, E = ½ I ω² is constant,
    // and the body origin (away from the CM) circles the CM at fixed distance.
    World world(zeroGravity());
    const BodyId box = world.createBody(test::bodyAt({1.0f, 2.0f}));
    world.createShape(box, {}, makeBox(1.0f, 0.5f, {0.5f, 0.2f}));
    world.setAngularVelocity(box, 3.0f);
    const Vec2 center = world.worldCenter(box);
    const float I = world.rotationalInertia(box);
    const double energy0 = 0.5 * I * 3.0 * 3.0;
    const float arm = length(world.localCenter(box));

    const int steps = 600;
    for (int n = 1; n <= steps; ++n) {
        world.step(dt);
        const float w = world.angularVelocity(box);
        const Vec2 v = world.linearVelocity(box);
        ASSERT_NEAR(w, 3.0f, 4 * epsilon * 3.0f) << "step " << n;
        const double energy = 0.5 * I * w * w + 0.5 * world.mass(box) * dot(v, v);
        ASSERT_NEAR(energy, energy0, 8 * epsilon * energy0) << "step " << n;
    }
    // The CM is never pushed: it moves only by rounding of c = c0 + Δp.
    EXPECT_NEAR(world.worldCenter(box).x, center.x, steps * epsilon * 4.0f);
    EXPECT_NEAR(world.worldCenter(box).y, center.y, steps * epsilon * 4.0f);
    // θ = ω t, accumulated in 4 substeps per step on a magnitude ≤ 30 rad.
    const double theta = 3.0 * steps * dt;
    EXPECT_NEAR(world.angle(box), theta, 4 * steps * epsilon * theta);
    EXPECT_NEAR(distance(world.position(box), world.worldCenter(box)), arm, 64 * epsilon * 4.0f);
}

TEST(Dynamics, ForceAtAPointGivesLinearAndAngularAcceleration) {
    // Box 2 x 1, ρ = 1: m = 2, I = m (4 + 1)/12. One step: v = h F/m, ω = h τ/I, τ = perpDot(P - CM, F).
    World world(zeroGravity());
    const BodyId box = test::addBox(world, {0.0f, 0.0f}, 1.0f, 0.5f, test::material(1.0f));
    const double m = 2.0, I = m * 5.0 / 12.0;
    ASSERT_NEAR(world.mass(box), m, 16 * epsilon * m);
    ASSERT_NEAR(world.rotationalInertia(box), I, 64 * epsilon * I);

    const Vec2 F{3.0f, -4.0f}, r{-0.7f, 0.4f};
    world.applyForce(box, F, world.worldCenter(box) + r);
    world.step(dt);
    const double tau = perpDot(r, F);  // (-0.7)(-4) - (0.4)(3) = 1.6
    EXPECT_NEAR(world.linearVelocity(box).x, dt * F.x / m, 8 * epsilon * dt * 4);
    EXPECT_NEAR(world.linearVelocity(box).y, dt * F.y / m, 8 * epsilon * dt * 4);
    EXPECT_NEAR(world.angularVelocity(box), dt * tau / I, 8 * epsilon * dt * tau / I);
    // Positions follow the new velocity (semi-implicit): x1 = h v1.
    EXPECT_NEAR(world.worldCenter(box).y, dt * dt * F.y / m, 16 * epsilon * dt * dt * 4);

    // The force lasts one step: the next step changes nothing.
    const Vec2 v1 = world.linearVelocity(box);
    const float w1 = world.angularVelocity(box);
    world.step(dt);
    EXPECT_EQ(world.linearVelocity(box), v1);
    EXPECT_EQ(world.angularVelocity(box), w1);

    // A pure torque: α = τ/I and no linear change.
    world.applyTorque(box, 2.0f);
    world.step(dt);
    EXPECT_NEAR(world.angularVelocity(box) - w1, dt * 2.0 / I, 8 * epsilon * dt * 2.0 / I);
    EXPECT_EQ(world.linearVelocity(box), v1);
}

// The step that does not integrate a body (put to sleep after the force) still ends its forces:
// woken later, it does not take a force from steps before.
TEST(Dynamics, AForceEndsWithTheStepEvenOnABodyPutToSleep) {
    World world(zeroGravity());
    const BodyId box = test::addBox(world, {0.0f, 0.0f}, 1.0f, 0.5f, test::material(1.0f));
    world.applyForce(box, {3.0f, 0.0f}, world.worldCenter(box) + Vec2{0.0f, 0.5f});
    world.setAwake(box, false);
    world.step(dt);
    world.setAwake(box, true);
    world.step(dt);
    EXPECT_EQ(world.linearVelocity(box), Vec2{});
    EXPECT_EQ(world.angularVelocity(box), 0.0f);
}

TEST(Dynamics, TorqueIsTakenAboutTheCentreOfMassNotTheOrigin) {
    // Box at local (1, 0), body turned 90°: the CM is at world (0, 1). F = (1, 0) at the body
    // origin (0, 0) has r = (0, -1), τ = perpDot(r, F) = 1; the same force at the CM has τ = 0.
    World world(zeroGravity());
    const BodyId body = world.createBody(test::bodyAt({}, BodyType::Dynamic, pi / 2));
    world.createShape(body, {}, makeBox(0.5f, 0.5f, {1.0f, 0.0f}));
    ASSERT_NEAR(world.worldCenter(body).y, 1.0f, 4 * epsilon);
    const float I = world.rotationalInertia(body);

    world.applyForce(body, {1.0f, 0.0f}, world.worldCenter(body));
    world.step(dt);
    EXPECT_EQ(world.angularVelocity(body), 0.0f);
    world.applyForce(body, {1.0f, 0.0f}, world.position(body));
    world.step(dt);
    EXPECT_NEAR(world.angularVelocity(body), dt * 1.0f / I, 8 * epsilon * dt / I);
}

TEST(Dynamics, OffCentreImpulseChangesVAndOmegaAtOnce) {
    // Δv = J/m, Δω = perpDot(r, J)/I, before any step.
    World world(zeroGravity());
    const BodyId box = test::addBox(world, {2.0f, -1.0f}, 1.0f, 0.5f, test::material(1.5f));
    const float m = world.mass(box), I = world.rotationalInertia(box);
    const Vec2 J{0.5f, 2.0f}, r{1.0f, -0.25f};
    world.applyLinearImpulse(box, J, world.worldCenter(box) + r);
    EXPECT_NEAR(world.linearVelocity(box).x, J.x / m, 4 * epsilon * J.x / m);
    EXPECT_NEAR(world.linearVelocity(box).y, J.y / m, 4 * epsilon * J.y / m);
    EXPECT_NEAR(world.angularVelocity(box), perpDot(r, J) / I, 4 * epsilon * std::fabs(perpDot(r, J) / I));
    // The velocity of the struck point is v + ω perp(r).
    const Vec2 vp = world.pointVelocity(box, world.worldCenter(box) + r);
    const Vec2 expected = pointVelocity(J * (1.0f / m), perpDot(r, J) / I, r);
    EXPECT_NEAR(vp.x, expected.x, 8 * epsilon * 4);
    EXPECT_NEAR(vp.y, expected.y, 8 * epsilon * 4);
}

TEST(Dynamics, OffCentreCollisionConservesMomentum) {
    // Zero gravity: a 1 kg box at 5 m/s hits a 3 kg box 0.3 m off its centre line. Contact impulses
    // are equal and opposite, so linear momentum Σ m v and angular momentum about the origin
    // Σ (I ω + m perpDot(c, v)) are conserved; with e = 0 kinetic energy can only drop.
    World world(zeroGravity());
    const BodyId a = test::addBox(world, {-2.0f, 0.3f}, 0.5f, 0.5f, test::material(1.0f));
    const BodyId b = test::addBox(world, {0.0f, 0.0f}, 0.5f, 0.5f, test::material(3.0f));
    world.setLinearVelocity(a, {5.0f, 0.0f});
    auto momentum = [&] {
        Vec2 p;
        double L = 0, E = 0;
        for (BodyId id : {a, b}) {
            const float m = world.mass(id), I = world.rotationalInertia(id), w = world.angularVelocity(id);
            const Vec2 v = world.linearVelocity(id);
            p += m * v;
            L += I * w + m * perpDot(world.worldCenter(id), v);
            E += 0.5 * m * dot(v, v) + 0.5 * I * w * w;
        }
        return std::tuple{p, L, E};
    };
    const auto [p0, L0, E0] = momentum();
    int contactSteps = 0;
    for (int i = 0; i < 90; ++i) {
        world.step(dt);
        contactSteps += world.contactCount() > 0;
    }
    const auto [p1, L1, E1] = momentum();
    ASSERT_GT(contactSteps, 0);
    ASSERT_GT(world.linearVelocity(b).x, 0.5f) << "the boxes did not collide";
    ASSERT_GT(std::fabs(world.angularVelocity(b)), 0.01f) << "the off-centre hit did not spin";
    // Rounding: ≤ 40 impulse applications per contact per step (4 substeps × warm start, solve,
    // relax × 2 points × 2 rows), each exact to ε relative on |m v| ≤ |p0| for both bodies.
    const double tol = 2 * 40 * contactSteps * epsilon * length(p0);
    EXPECT_NEAR(p1.x, p0.x, tol);
    EXPECT_NEAR(p1.y, p0.y, tol);
    EXPECT_NEAR(L1, L0, tol * 3.0);  // lever arms ≤ 3 m
    EXPECT_LE(E1, E0 * (1 + tol));
}

TEST(Dynamics, DampingDividesVelocityByOnePlusHcEachStep) {
    // dv/dt = -c v integrated implicitly: v_n = v0 / (1 + h c)^n. The factor is rounded (3 ops) and
    // applied n times: ≤ (4n + 2) ε relative. The continuous e^{-ct} differs by ≈ c² h t/2 relative.
    World world(zeroGravity());
    BodyDef def = test::bodyAt({});
    def.linearVelocity = {4.0f, -3.0f};
    def.angularVelocity = 5.0f;
    def.linearDamping = 0.5f;
    def.angularDamping = 2.0f;
    const BodyId disc = world.createBody(def);
    world.createShape(disc, {}, Circle{{}, 0.5f});
    const int n = 90;
    test::run(world, n);
    const double h = dt, t = n * h;
    const double linear = std::pow(1 + h * 0.5, -n), angular = std::pow(1 + h * 2.0, -n);
    const double rel = (4 * n + 2) * epsilon;
    EXPECT_NEAR(world.linearVelocity(disc).x, 4.0 * linear, rel * 4.0 * linear);
    EXPECT_NEAR(world.linearVelocity(disc).y, -3.0 * linear, rel * 3.0 * linear);
    EXPECT_NEAR(world.angularVelocity(disc), 5.0 * angular, rel * 5.0 * angular);
    const double vExact = 4.0 * std::exp(-0.5 * t), wExact = 5.0 * std::exp(-2.0 * t);
    EXPECT_NEAR(world.linearVelocity(disc).x, vExact, 0.5 * 0.5 * h * t * vExact);  // 2 × c² h t/2
    EXPECT_NEAR(world.angularVelocity(disc), wExact, 2.0 * 2.0 * h * t * wExact);
}

}  // namespace
}  // namespace perpdot
