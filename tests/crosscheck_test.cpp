// The regression gates against Box2D 2.4's b2World (tests/crosscheck/*.json), each with its
// tolerance in the table below (and in the scene's description), plus physics checks that do
// not need Box2D: closed-form free flight, conserved momenta, friction stopping distance.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "perpdot/crosscheck.hpp"
#include "perpdot/scene.hpp"

namespace perpdot {
namespace {

using crosscheck::Report;

crosscheck::Options options(float tolerance, float angleTolerance, bool recordTrajectories = false) {
    crosscheck::Options o;
    o.tolerance = tolerance;
    o.angleTolerance = angleTolerance;
    o.recordTrajectories = recordTrajectories;
    return o;
}

Scene gateScene(const std::string& name) { return loadScene(std::string(PERPDOT_TEST_DATA) + "/../crosscheck/" + name + ".json"); }

std::string describe(const Report& r) {
    std::string text = r.scene + ":";
    for (const auto& m : r.bodies) {
        text += " " + m.name + " max|dx|=" + std::to_string(m.position.max) + "@" + std::to_string(m.position.maxStep) +
                " max|da|=" + std::to_string(m.angle.max);
    }
    return text;
}

// Each scene's gate, as its description states it (and docs/crosscheck.md explains).
struct Gate {
    const char* scene;
    float tolerance;       // metres
    float angleTolerance;  // radians
};

void PrintTo(const Gate& g, std::ostream* os) { *os << g.scene; }

class CrosscheckGate : public testing::TestWithParam<Gate> {};

TEST_P(CrosscheckGate, AgreesWithBox2D) {
    const Gate gate = GetParam();
    const Scene scene = gateScene(gate.scene);
    const Report r = crosscheck::run(scene, options(gate.tolerance, gate.angleTolerance));
    ASSERT_EQ(r.steps, scene.steps);
    EXPECT_TRUE(r.withinTolerance()) << "diverged at step " << r.divergenceStep << " (" << r.divergedBody << "); " << describe(r);
    for (size_t i = 0; i < r.bodies.size(); ++i) {
        EXPECT_NEAR(r.perpdot.mass[i], r.box2d.mass[i], 1e-5f * r.box2d.mass[i]) << r.bodies[i].name;
        EXPECT_NEAR(r.perpdot.rotationalInertia[i], r.box2d.rotationalInertia[i], 1e-4f * r.box2d.rotationalInertia[i] + 1e-6f)
            << r.bodies[i].name;
    }
    RecordProperty("max_position_error", describe(r));
}

// Free flight, spin, damping, gravity scale and scripted forces integrate exactly like Box2D 2.4
// (v += h(g + F/m), damping, x += h v): 1e-4 m over 600 steps; angles to 1e-3 rad, float rounding
// of accumulated angles of up to 62 rad added in 4 substeps (perpdot) or once (Box2D).
INSTANTIATE_TEST_SUITE_P(FreeMotion, CrosscheckGate,
                         testing::Values(Gate{"projectile", 1e-4f, 1e-3f}, Gate{"torque_free_spin", 1e-4f, 1e-3f},
                                         Gate{"damping", 1e-4f, 1e-3f}, Gate{"gravity_scale", 1e-4f, 1e-3f},
                                         Gate{"actions", 1e-4f, 1e-3f}, Gate{"filters", 1e-4f, 1e-3f}),
                         [](const auto& info) { return std::string(info.param.scene); });

// One contact: soft step (4 substeps) vs PGS + NGS. Resting agrees within 1 cm; sliding, rolling and
// bouncing differ by the amounts the scenes' descriptions derive (see the physics tests below).
INSTANTIATE_TEST_SUITE_P(SingleContact, CrosscheckGate,
                         testing::Values(Gate{"box_rest", 1e-2f, 1e-2f}, Gate{"box_slide", 0.035f, 1e-2f},
                                         Gate{"bounce", 0.12f, 1e-2f}, Gate{"disc_slope", 0.05f, 0.1f}),
                         [](const auto& info) { return std::string(info.param.scene); });

// Semi-implicit Euler in closed form: v_n = v0 + n h g, x_n = x0 + n h v0 + h² g n(n+1)/2.
TEST(CrosscheckPhysics, ProjectileFollowsSemiImplicitEuler) {
    const Scene scene = gateScene("projectile");
    const crosscheck::Trajectory t = crosscheck::record(scene, crosscheck::Engine::Perpdot);
    const float h = scene.timestep;
    const Vec2 x0 = scene.bodies[0].position, v0 = scene.bodies[0].linearVelocity, g = scene.gravity;
    for (int n : {1, 60, 300, 600}) {
        const float fn = float(n);
        const Vec2 v = v0 + fn * h * g;
        const Vec2 x = x0 + fn * h * v0 + (h * h * fn * (fn + 1.0f) / 2.0f) * g;
        const crosscheck::BodyState& s = t.at(n, 0);  // "box": origin = centre of mass
        EXPECT_NEAR(s.linearVelocity.x, v.x, 1e-4f) << n;
        EXPECT_NEAR(s.linearVelocity.y, v.y, 1e-3f) << n;
        EXPECT_NEAR(s.position.x, x.x, 1e-3f) << n;
        EXPECT_NEAR(s.position.y, x.y, 2e-3f) << n;
        EXPECT_NEAR(s.angle, scene.bodies[0].angle + fn * h * scene.bodies[0].angularVelocity, 1e-4f) << n;
    }
}

// No torque, no gravity: angular momentum about the origin, linear momentum and kinetic energy are
// constants of the motion in both engines.
TEST(CrosscheckPhysics, TorqueFreeSpinConservesMomentaAndEnergy) {
    const Report r = crosscheck::run(gateScene("torque_free_spin"));
    for (const crosscheck::EngineSeries* s : {&r.perpdot, &r.box2d}) {
        const float L0 = s->angularMomentum.front(), T0 = s->kineticEnergy.front();
        const Vec2 p0 = s->linearMomentum.front();
        for (size_t f = 0; f < s->angularMomentum.size(); f += 50) {
            EXPECT_NEAR(s->angularMomentum[f], L0, 1e-4f * std::abs(L0)) << f;
            EXPECT_NEAR(s->kineticEnergy[f], T0, 1e-4f * T0) << f;
            EXPECT_NEAR(s->linearMomentum[f].x, p0.x, 1e-5f) << f;
            EXPECT_NEAR(s->linearMomentum[f].y, p0.y, 1e-5f) << f;
        }
    }
}

// Coulomb friction μ g decelerates the block to rest after v²/(2 μ g) = 3.125 m. Box2D 2.4 moves each
// step with the end-of-step velocity (semi-implicit Euler: h Σ v_k, 3.083 m). perpdot gives a body in
// contact its gravity, and so the contact impulses, in 4 substeps and moves it with each substep's
// velocity: Σ (h/4)(v + k Δv/4) = h (v + (5/8) Δv) against Box2D's h (v + Δv), so for a steady
// acceleration a the engines drift apart by (3/8) a h per unit time: (3/8) μ g h t_stop = 0.031 m.
TEST(CrosscheckPhysics, SlidingBlockStopsWhereCoulombFrictionSays) {
    const Scene scene = gateScene("box_slide");
    const Report r = crosscheck::run(scene, options(1e-2f, 1e-2f, true));
    const float mu = 0.4f, g = 10.0f, h = scene.timestep, v0 = scene.bodies[1].linearVelocity.x;
    const float x0 = scene.bodies[1].position.x, tStop = v0 / (mu * g);
    const float perpdotStop = r.perpdotTrajectory.at(r.steps, 0).position.x - x0;
    const float box2dStop = r.box2dTrajectory.at(r.steps, 0).position.x - x0;
    EXPECT_NEAR(perpdotStop, v0 * v0 / (2.0f * mu * g), 0.015f);
    const int n = int(std::lround(tStop / h));  // steps until rest
    EXPECT_NEAR(box2dStop, h * (float(n) * v0 - mu * g * h * float(n) * float(n + 1) / 2.0f), 2e-3f);
    EXPECT_NEAR(perpdotStop - box2dStop, 0.375f * mu * g * h * tStop, 3e-3f);
    EXPECT_NEAR(r.perpdotTrajectory.at(r.steps, 0).linearVelocity.x, 0.0f, 1e-3f);
}

// The ball's first rebound: Box2D 2.4 gives e times its approach speed after the step's gravity;
// perpdot the speed whose discrete climb reaches e² of the discrete fall (contact_solver.cpp's
// reboundSpeed, V the approach speed after gravity, a = g). Afterwards the bounces die out below
// the restitution threshold and the ball rests on the segment in both.
TEST(CrosscheckPhysics, BounceReboundsWithRestitutionAndComesToRest) {
    const Scene scene = gateScene("bounce");
    const Report r = crosscheck::run(scene, options(1e-2f, 1e-2f, true));
    const float e = 0.5f, g = 10.0f, h = scene.timestep, gh = g * h;
    for (const crosscheck::Trajectory* t : {&r.perpdotTrajectory, &r.box2dTrajectory}) {
        int impact = 1;
        while (impact < r.steps && t->at(impact, 0).linearVelocity.y < 0.0f) ++impact;
        ASSERT_LT(impact, r.steps);
        const float V = -t->at(impact - 1, 0).linearVelocity.y + gh;  // approach speed, after the last step's gravity
        const float after = t->at(impact, 0).linearVelocity.y;
        if (t == &r.perpdotTrajectory)
            EXPECT_NEAR(after, 0.5f * (gh + std::sqrt(gh * gh + 4.0f * e * e * (V * V - gh * V))), 1e-3f);
        else
            EXPECT_NEAR(after, e * V, 1e-3f);
        EXPECT_NEAR(t->at(r.steps, 0).position.y, 0.255f, 0.005f);
        EXPECT_NEAR(t->at(r.steps, 0).linearVelocity.y, 0.0f, 0.05f);
    }
}

// Rolling without slipping down a slope of angle α: s = ½ (2/3) g sin α t² along the slope, and the
// engines differ by the (3/8) a h t of the sliding block above.
TEST(CrosscheckPhysics, DiscRollsWithTwoThirdsOfGSinAlpha) {
    const Scene scene = gateScene("disc_slope");
    const Report r = crosscheck::run(scene, options(1e-2f, 1e-2f, true));
    const float alpha = 20.0f * pi / 180.0f, t = float(r.steps) * scene.timestep;
    const float s = 0.5f * (2.0f / 3.0f) * 10.0f * std::sin(alpha) * t * t;
    for (const crosscheck::Trajectory* traj : {&r.perpdotTrajectory, &r.box2dTrajectory}) {
        const crosscheck::BodyState& end = traj->at(r.steps, 0);
        const float travelled = distance(end.position, scene.bodies[1].position);
        EXPECT_NEAR(travelled, s, 0.03f * s);
        EXPECT_NEAR(end.angularVelocity * 0.5f, -length(end.linearVelocity), 0.02f * length(end.linearVelocity));
    }
    const float a = (2.0f / 3.0f) * 10.0f * std::sin(alpha);
    const float perpdotTravel = distance(r.perpdotTrajectory.at(r.steps, 0).position, scene.bodies[1].position);
    const float box2dTravel = distance(r.box2dTrajectory.at(r.steps, 0).position, scene.bodies[1].position);
    EXPECT_NEAR(box2dTravel - perpdotTravel, 0.375f * a * scene.timestep * t, 5e-3f);
}

// A stack set up at Box2D's rest spacing: the solvers take different paths (the report says from
// which step they are 1 cm apart, if ever), but both must end with every box upright, where it
// started and at Box2D's height within 2 cm.
TEST(CrosscheckPhysics, StackRestsAtBox2DHeights) {
    const Scene scene = gateScene("stack");
    const Report r = crosscheck::run(scene, options(1e-2f, 1e-2f, true));
    RecordProperty("divergence_step", r.divergenceStep);
    std::printf("stack: diverged (1 cm) at step %d (%s); %s\n", r.divergenceStep, r.divergedBody.c_str(), describe(r).c_str());
    for (size_t b = 0; b < r.bodies.size(); ++b) {
        const crosscheck::BodyState& p = r.perpdotTrajectory.at(r.steps, int(b));
        const crosscheck::BodyState& x = r.box2dTrajectory.at(r.steps, int(b));
        EXPECT_NEAR(p.position.y, x.position.y, 0.02f) << r.bodies[b].name;
        EXPECT_NEAR(p.position.x, 0.0f, 0.02f) << r.bodies[b].name;
        EXPECT_NEAR(p.angle, 0.0f, 0.02f) << r.bodies[b].name;
        EXPECT_NEAR(p.position.y, scene.bodies[b + 1].position.y, 0.02f) << r.bodies[b].name;  // still standing
    }
    EXPECT_EQ(r.perpdot.contactCount.back(), r.box2d.contactCount.back());
}

// The main job's summary says why the engines' rest heights differ and compares like for like.
TEST(CrosscheckSummary, ExplainsTheSkinAndComparesLikeForLike) {
    const Scene scene = findScene("stress_box_rest");
    const std::string text = crosscheck::summarize(scene, 120);
    EXPECT_NE(text.find("rest heights: perpdot rests 1 bodies 0.014"), std::string::npos) << text;
    EXPECT_NE(text.find("Box2D 2.4 rests polygons on a 1 cm skin each"), std::string::npos) << text;
    EXPECT_NE(text.find("like for like (perpdot on Box2D's skin, --box2d-skin): rest heights agree within"), std::string::npos) << text;
    Scene skinned = scene;
    skinned.solver.box2dSkin = true;
    const std::string same = crosscheck::summarize(skinned, 120);
    EXPECT_EQ(same.find("rest heights: perpdot rests"), std::string::npos) << same;
    EXPECT_NE(same.find("on Box2D's skin (box2d_skin): rest heights agree within"), std::string::npos) << same;
}

// Dropped 1 cm, the box comes to rest with its 0.01 m skin touching the ground's, overlapping by at
// most the 0.005 m linear slop: its centre between 0.515 and 0.52 m, in both engines.
TEST(CrosscheckPhysics, BoxRestsOnGroundInBothEngines) {
    const Report r = crosscheck::run(gateScene("box_rest"), options(1e-2f, 1e-2f, true));
    for (const crosscheck::Trajectory* t : {&r.perpdotTrajectory, &r.box2dTrajectory}) {
        EXPECT_GE(t->at(r.steps, 0).position.y, 0.5f + 0.02f - 0.005f - 1e-3f);
        EXPECT_LE(t->at(r.steps, 0).position.y, 0.5f + 0.02f);
        EXPECT_NEAR(t->at(r.steps, 0).linearVelocity.y, 0.0f, 1e-3f);
    }
    EXPECT_EQ(r.perpdot.contactCount.back(), 1);
    EXPECT_EQ(r.box2d.contactCount.back(), 1);
}

// Masks, negative groups and sensors keep every shape of tests/crosscheck/filters.json apart: no
// touching contact in either engine at any step, while the sensor is overlapped.
TEST(CrosscheckPhysics, FilteredAndSensorShapesNeverTouch) {
    const Report r = crosscheck::run(gateScene("filters"));
    for (size_t f = 0; f < r.perpdot.contactCount.size(); ++f) {
        ASSERT_EQ(r.perpdot.contactCount[f], 0) << f;
        ASSERT_EQ(r.box2d.contactCount[f], 0) << f;
    }
}

// tests/crosscheck/joints.json: each joint of the scene holds its constraint. Checked on Box2D's side,
// which proves the Scene -> b2World conversion (anchors, axes, reference angles, spring stiffness
// from hertz and damping ratio), and on perpdot's.
void expectJointsHold(const crosscheck::Trajectory& t, float tolerance) {
    auto body = [&](const std::string& name) {
        for (size_t i = 0; i < t.bodies.size(); ++i)
            if (t.bodies[i] == name) return int(i);
        ADD_FAILURE() << "no body " << name;
        return 0;
    };
    const int bob = body("bob"), tip = body("tip"), weight = body("weight"), slider = body("slider"), wheel = body("wheel"),
              follower = body("follower");
    const Vec2 axis = normalize({1.0f, 1.0f});
    int upCrossings = 0, firstUp = -1, lastUp = -1;
    for (int f = 0; f < t.frameCount(); ++f) {
        const crosscheck::BodyState &b = t.at(f, bob), &w = t.at(f, tip), &s = t.at(f, slider), &k = t.at(f, wheel);
        EXPECT_NEAR(distance(b.position, {0.0f, 5.0f}), 2.0f, tolerance) << "revolute, frame " << f;
        EXPECT_NEAR(distance(b.position, w.position), 0.6f, tolerance) << "weld, frame " << f;
        EXPECT_NEAR(w.angle, b.angle, tolerance) << "weld, frame " << f;
        const Vec2 slide = s.position - Vec2{-4.0f, 4.0f};
        EXPECT_NEAR(perpDot(axis, slide), 0.0f, tolerance) << "prismatic, frame " << f;
        EXPECT_GE(dot(axis, slide), -1.0f - tolerance) << "prismatic lower limit, frame " << f;
        EXPECT_NEAR(s.angle, pi / 4.0f, tolerance) << "prismatic, frame " << f;
        EXPECT_NEAR(k.position.x, -8.0f, tolerance) << "wheel axis, frame " << f;
        if (f > 0 && t.at(f - 1, weight).linearVelocity.y < 0.0f && t.at(f, weight).linearVelocity.y >= 0.0f) {
            ++upCrossings;
            if (firstUp < 0) firstUp = f;
            lastUp = f;
        }
    }
    const int last = t.frameCount() - 1;
    // Gravity pulls the slider down its axis to the lower limit.
    EXPECT_NEAR(dot(axis, t.at(last, slider).position - Vec2{-4.0f, 4.0f}), -1.0f, tolerance);
    // The wheel turns at the motor speed and sags g/ω² = 1.6 cm on its 4 Hz suspension.
    EXPECT_NEAR(t.at(last, wheel).angularVelocity, -5.0f, 0.05f);
    const float omega4 = 2.0f * pi * 4.0f;
    EXPECT_NEAR(t.at(last, wheel).position.y, 1.5f - 10.0f / (omega4 * omega4), 2e-3f);
    // The motor joint brings the follower to the base's offset (1, 1), turned back to angle 0.
    EXPECT_NEAR(distance(t.at(last, follower).position, {11.0f, 1.0f}), 0.0f, 0.01f);
    EXPECT_NEAR(t.at(last, follower).angle, 0.0f, 0.01f);
    // The 2 Hz spring (damping ratio 0.1): period 1/(2 sqrt(1 - 0.01)) = 0.5025 s, within 5%; rest at
    // length 1.2 + g/ω² below the ceiling.
    ASSERT_GE(upCrossings, 3);
    const float period = float(lastUp - firstUp) / float(upCrossings - 1) * t.timestep;
    EXPECT_NEAR(period, 0.5025f, 0.025f);
    const float omega2 = 2.0f * pi * 2.0f;
    EXPECT_NEAR(t.at(last, weight).position.y, 5.0f - (1.2f + 10.0f / (omega2 * omega2)) - 0.3f, 0.01f);
}

TEST(CrosscheckBox2DScene, JointsHoldTheirConstraints) {
    expectJointsHold(crosscheck::record(gateScene("joints"), crosscheck::Engine::Box2D), 5e-3f);
}

TEST(CrosscheckPhysics, PerpdotJointsHoldTheirConstraints) {
    expectJointsHold(crosscheck::record(gateScene("joints"), crosscheck::Engine::Perpdot), 5e-3f);
}

}  // namespace
}  // namespace perpdot
