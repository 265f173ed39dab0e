// What a scene file can say of the runtime API: a friction joint (top-down friction, Box2D's
// b2FrictionJoint) and bodies and shapes that start disabled. Each is checked on the physics it
// must produce, in perpdot and, through the cross-check, against Box2D 2.4's b2World.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "perpdot/crosscheck.hpp"
#include "perpdot/scene.hpp"

namespace perpdot {
namespace {

// A 2 kg puck (1 m box, density 2) gliding at 3 m/s over a top-down table (no gravity), held
// back by a friction joint of at most 1.5 N and 0.4 N·m: it decelerates at F/m = 0.75 m/s² and
// stops at t = 4 s; its spin of 2 rad/s falls at τ/I = 0.4 / (2/6) = 1.2 rad/s².
constexpr const char* puckScene = R"({"format": "perpdot-scene/1", "gravity": [0, 0], "steps": 300,
  "bodies": [{"name": "table", "type": "static"},
             {"name": "puck", "linear_velocity": [3, 0], "angular_velocity": 2,
              "shapes": [{"type": "box", "half_extents": [0.5, 0.5], "density": 2}]}],
  "joints": [{"type": "friction", "body_a": "table", "body_b": "puck", "local_anchor_a": [0, 0],
              "local_anchor_b": [0, 0], "max_force": 1.5, "max_torque": 0.4}]})";

TEST(SceneRuntimeState, FrictionJointDeceleratesAtMaxForceOverMass) {
    SceneWorld built = buildWorld(parseScene(puckScene));
    const BodyId puck = built.bodies[1];
    const float h = built.scene.timestep;
    for (int step = 1; step <= 300; ++step) {
        built.step();
        const float t = h * static_cast<float>(step);
        const float v = std::max(0.0f, 3.0f - 0.75f * t), w = std::max(0.0f, 2.0f - 1.2f * t);
        ASSERT_NEAR(built.world.linearVelocity(puck).x, v, 1.0e-3f) << "t = " << t;
        ASSERT_NEAR(built.world.angularVelocity(puck), w, 1.0e-3f) << "t = " << t;
    }
    // At rest after 4 s, 6 m from where it started (v0² / 2a).
    EXPECT_NEAR(built.world.position(puck).x, 6.0f, 0.02f);
}

TEST(SceneRuntimeState, FrictionJointDefaultsToBox2DsNothingAndRoundTrips) {
    const Scene s = parseScene(R"({"format": "perpdot-scene/1", "bodies": [{"name": "a", "type": "static"}, {"name": "b"}],
        "joints": [{"type": "friction", "body_a": "a", "body_b": "b"}]})");
    ASSERT_EQ(s.joints.size(), 1u);
    EXPECT_EQ(s.joints[0].type, JointType::Friction);
    EXPECT_EQ(s.joints[0].maxForce, 0.0f);  // b2FrictionJointDef's defaults
    EXPECT_EQ(s.joints[0].maxTorque, 0.0f);
    EXPECT_TRUE(parseScene(toJson(s)) == s);
    Scene one = s;
    one.joints[0].maxForce = 1.0f;  // SceneJoint's own default (the motor's): written all the same
    EXPECT_TRUE(parseScene(toJson(one)) == one);
}

// Both engines cap the joint's impulse at maxForce·h per step, so both decelerate at F/m; they
// differ only by their integrators. Box2D 2.4's x += h·v(after the step) stops short of the exact
// distance by a·h·T/2 (T: time to rest); perpdot, moving in 4 substeps, by a quarter of that. The
// cross-check's difference is the other three quarters: 0.75·0.75·h·4/2 = 1.9 cm and, for the
// spin, 0.75·1.2·h·(2/1.2)/2 = 0.0125 rad.
TEST(SceneRuntimeState, FrictionJointAgreesWithBox2DUpToItsIntegrator) {
    crosscheck::Options options;
    options.steps = 300;
    const crosscheck::Report report = crosscheck::run(parseScene(puckScene), options);
    ASSERT_EQ(report.bodies.size(), 1u);
    const float h = 1.0f / 60.0f;
    EXPECT_NEAR(report.bodies[0].position.max, 0.75f * 0.75f * h * 4.0f / 2.0f, 1.0e-3f);
    EXPECT_NEAR(report.bodies[0].angle.max, 0.75f * 1.2f * h * (2.0f / 1.2f) / 2.0f, 1.0e-3f);
}

// A ground of two boxes, the left one disabled, a ball over each; a disabled crate in mid-air
// and a ball under it. The left ball falls through the disabled box, the right one rests on the
// enabled box; the crate hangs where it is and the ball under it, which it does not block, rests
// on the ground beneath it.
constexpr const char* disabledScene = R"({"format": "perpdot-scene/1", "steps": 120,
  "bodies": [{"name": "ground", "type": "static",
              "shapes": [{"type": "box", "half_extents": [1, 0.5], "center": [-2, 0], "enabled": false},
                         {"type": "box", "half_extents": [1, 0.5], "center": [2, 0]},
                         {"type": "box", "half_extents": [1, 0.5], "center": [6, 0]}]},
             {"name": "left", "position": [-2, 1], "shapes": [{"type": "circle", "radius": 0.25}]},
             {"name": "right", "position": [2, 1], "shapes": [{"type": "circle", "radius": 0.25}]},
             {"name": "crate", "position": [6, 3], "enabled": false, "shapes": [{"type": "box", "half_extents": [0.5, 0.5]}]},
             {"name": "under", "position": [6, 1], "shapes": [{"type": "circle", "radius": 0.25}]}]})";

TEST(SceneRuntimeState, DisabledShapesAndBodiesTakeNoPartUntilEnabled) {
    SceneWorld built = buildWorld(parseScene(disabledScene));
    World& world = built.world;
    const BodyId ground = built.bodies[0], left = built.bodies[1], right = built.bodies[2], crate = built.bodies[3],
                 under = built.bodies[4];
    EXPECT_FALSE(world.isEnabled(world.shapes(ground)[0]));
    EXPECT_TRUE(world.isEnabled(world.shapes(ground)[1]));
    EXPECT_FALSE(world.isEnabled(crate));
    for (int i = 0; i < 120; ++i) built.step();
    EXPECT_LT(world.position(left).y, -3.0f);               // fell through the disabled box
    EXPECT_NEAR(world.position(right).y, 0.75f, 0.01f);     // rests on the enabled one
    EXPECT_EQ(world.position(crate), (Vec2{6.0f, 3.0f}));  // out of the simulation: gravity does not move it
    EXPECT_NEAR(world.position(under).y, 0.75f, 0.01f);
    // Enabled again, the crate falls from where it was onto the ball under it.
    world.setEnabled(crate, true);
    for (int i = 0; i < 120; ++i) built.step();
    EXPECT_NEAR(world.position(crate).y, 1.5f, 0.02f);  // on the ball (its top at 1 m), not through it
}

TEST(SceneRuntimeState, EnabledFlagsRoundTripAndAgreeWithBox2D) {
    const Scene s = parseScene(disabledScene);
    EXPECT_FALSE(s.bodies[0].shapes[0].enabled);
    EXPECT_TRUE(s.bodies[0].shapes[1].enabled);
    EXPECT_FALSE(s.bodies[3].enabled);
    EXPECT_TRUE(s.bodies[4].enabled);
    EXPECT_TRUE(parseScene(toJson(s)) == s);
    // Box2D 2.4: b2BodyDef::enabled for the crate, a fixture that collides with nothing for the box.
    crosscheck::Options options;
    options.steps = 120;
    const crosscheck::Report report = crosscheck::run(s, options);
    ASSERT_EQ(report.bodies.size(), 4u);
    for (const auto& body : report.bodies) EXPECT_LT(body.position.max, 1.0e-2f) << body.name;
}

}  // namespace
}  // namespace perpdot
