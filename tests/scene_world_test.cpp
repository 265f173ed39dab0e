// buildWorld and scripted actions: the World holds what the scene says, and actions obey
// Newton's laws for a force F at a point P: Δv = h F/m, Δω = h perpDot(P - CM, F)/I.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "perpdot/error.hpp"
#include "perpdot/scene.hpp"
#include "perpdot/state_hash.hpp"
#include "scene/scene_builders.hpp"

namespace perpdot {
namespace {

// Zero gravity, one 2 m × 1 m box turned by 0.3 rad, and the given actions.
Scene freeBox(std::vector<SceneAction> actions) {
    Scene s;
    s.gravity = {};
    SceneBody& box = addBody(s, {.name = "box", .position = {1.0f, 2.0f}, .angle = 0.3f, .shapes = {boxShape(1.0f, 0.5f)}});
    box.shapes[0].density = 2.0f;
    s.actions = std::move(actions);
    return s;
}

TEST(SceneWorld, BodiesAndShapesFollowTheScene) {
    const Scene scene = findScene("friction_ramp");
    SceneWorld built = buildWorld(scene);
    ASSERT_EQ(built.bodies.size(), scene.bodies.size());
    for (size_t i = 0; i < scene.bodies.size(); ++i) {
        const SceneBody& b = scene.bodies[i];
        EXPECT_EQ(built.world.bodyType(built.bodies[i]), b.type);
        EXPECT_EQ(built.world.position(built.bodies[i]), b.position);
        EXPECT_FLOAT_EQ(built.world.angle(built.bodies[i]), b.angle);
        const auto shapes = built.world.shapes(built.bodies[i]);
        ASSERT_EQ(shapes.size(), b.shapes.size());
        EXPECT_FLOAT_EQ(built.world.friction(shapes[0]), b.shapes[0].friction);
    }
    // A dynamic 1 m box of density 1: m = ρ·A = 1 kg, I = m (w² + h²)/12 = 1/6.
    const BodyId block = built.bodies[1];
    EXPECT_FLOAT_EQ(built.world.mass(block), 1.0f);
    EXPECT_NEAR(built.world.rotationalInertia(block), 1.0f / 6.0f, 1e-6f);
}

TEST(SceneWorld, SettingsReachTheWorld) {
    Scene scene = freeBox({});
    scene.gravity = {1.0f, -3.0f};
    scene.solver.substeps = 7;
    scene.enableSleep = false;
    SceneBody& box = scene.bodies[0];
    box.linearVelocity = {2.0f, -1.0f};
    box.angularVelocity = 0.5f;
    box.gravityScale = 0.25f;
    const SceneWorld built = buildWorld(scene);
    EXPECT_EQ(built.world.settings().gravity, scene.gravity);
    EXPECT_EQ(built.world.settings().substeps, 7);
    EXPECT_FALSE(built.world.settings().enableSleep);
    EXPECT_EQ(built.world.linearVelocity(built.bodies[0]), box.linearVelocity);
    EXPECT_EQ(built.world.angularVelocity(built.bodies[0]), 0.5f);
    EXPECT_EQ(built.world.gravityScale(built.bodies[0]), 0.25f);
}

TEST(SceneWorld, ForceAtAPointTranslatesAndSpins) {
    const Vec2 force{3.0f, -4.0f}, point{2.5f, 1.0f};
    SceneWorld built = buildWorld(freeBox({{.kind = SceneAction::Kind::Force, .body = "box", .value = force, .point = point}}));
    const World& w = built.world;
    const BodyId box = built.bodies[0];
    const float h = built.scene.timestep, m = w.mass(box), inertia = w.rotationalInertia(box);
    const Vec2 r = point - w.worldCenter(box);
    ASSERT_GT(std::abs(perpDot(r, force)), 1.0f);  // the point is well off the centre

    built.step();
    const float omega = h * perpDot(r, force) / inertia;
    EXPECT_NEAR(w.angularVelocity(box), omega, 1e-5f * std::abs(omega));
    EXPECT_NEAR(w.linearVelocity(box).x, h * force.x / m, 1e-6f);
    EXPECT_NEAR(w.linearVelocity(box).y, h * force.y / m, 1e-6f);

    built.step();  // the action covered step 0 only: no more torque, ω stays
    EXPECT_NEAR(w.angularVelocity(box), omega, 1e-5f * std::abs(omega));
    EXPECT_EQ(built.stepIndex, 2);
}

TEST(SceneWorld, ForceWithoutPointActsAtTheCentreOfMass) {
    SceneWorld built = buildWorld(freeBox({{.kind = SceneAction::Kind::Force, .body = "box", .value = {5.0f, 1.0f},
                                            .firstStep = 0, .lastStep = 9}}));
    for (int i = 0; i < 10; ++i) built.step();
    const float m = built.world.mass(built.bodies[0]);
    EXPECT_EQ(built.world.angularVelocity(built.bodies[0]), 0.0f);
    EXPECT_NEAR(built.world.linearVelocity(built.bodies[0]).x, 10 * built.scene.timestep * 5.0f / m, 1e-5f);
}

TEST(SceneWorld, ImpulsesAndTorquesApplyOnTheirSteps) {
    const Vec2 impulse{0.0f, 2.0f}, point{2.0f, 2.0f};
    SceneWorld built = buildWorld(freeBox({
        {.kind = SceneAction::Kind::Impulse, .body = "box", .value = impulse, .point = point, .firstStep = 1, .lastStep = 1},
        {.kind = SceneAction::Kind::Torque, .body = "box", .scalar = 3.0f, .firstStep = 2, .lastStep = 3},
        {.kind = SceneAction::Kind::AngularImpulse, .body = "box", .scalar = -0.5f, .firstStep = 5, .lastStep = 5},
    }));
    const World& w = built.world;
    const BodyId box = built.bodies[0];
    const float h = built.scene.timestep, m = w.mass(box), inertia = w.rotationalInertia(box);

    built.step();  // step 0: nothing
    EXPECT_EQ(w.angularVelocity(box), 0.0f);
    const Vec2 r = point - w.worldCenter(box);
    built.step();  // step 1: Δv = J/m, Δω = perpDot(r, J)/I
    float omega = perpDot(r, impulse) / inertia;
    EXPECT_NEAR(w.linearVelocity(box).y, impulse.y / m, 1e-6f);
    EXPECT_NEAR(w.angularVelocity(box), omega, 1e-5f);
    built.step();
    built.step();  // steps 2 and 3: Δω = h τ / I each
    omega += 2.0f * h * 3.0f / inertia;
    EXPECT_NEAR(w.angularVelocity(box), omega, 1e-5f);
    built.step();
    built.step();  // step 5: Δω = L / I
    omega += -0.5f / inertia;
    EXPECT_NEAR(w.angularVelocity(box), omega, 1e-5f);
}

TEST(SceneWorld, JointAnchorsAreWhereTheSceneSays) {
    Scene scene = freeBox({});
    addBody(scene, {.name = "pivot", .type = BodyType::Static, .position = {-1.0f, 2.0f}});
    scene.joints.push_back({.type = JointType::Revolute, .bodyA = "pivot", .bodyB = "box", .anchor = Vec2{0.0f, 2.0f}});
    scene.joints.push_back({.type = JointType::Distance, .bodyA = "pivot", .bodyB = "box", .anchor = Vec2{-1.0f, 2.0f},
                            .anchorB = Vec2{1.5f, 2.0f}});
    scene.joints.push_back({.type = JointType::Weld, .bodyA = "pivot", .bodyB = "box", .anchor = Vec2{0.5f, 2.0f}});
    SceneWorld built = buildWorld(scene);
    ASSERT_EQ(built.joints.size(), 3u);
    const auto near = [](Vec2 a, Vec2 b) { return distance(a, b) < 1e-5f; };
    EXPECT_TRUE(near(built.world.jointAnchorA(built.joints[0]), (Vec2{0.0f, 2.0f})));
    EXPECT_TRUE(near(built.world.jointAnchorB(built.joints[0]), (Vec2{0.0f, 2.0f})));
    EXPECT_TRUE(near(built.world.jointAnchorB(built.joints[1]), (Vec2{1.5f, 2.0f})));
    EXPECT_EQ(built.world.jointBodyA(built.joints[1]), built.bodies[1]);
    // Every joint is satisfied as built (the distance joint's length is the current distance, the
    // weld's reference angle is the bodies' angle difference), so nothing moves.
    for (int i = 0; i < 30; ++i) built.step();
    EXPECT_TRUE(near(built.world.position(built.bodies[0]), scene.bodies[0].position));
    EXPECT_NEAR(built.world.angle(built.bodies[0]), scene.bodies[0].angle, 1e-5f);
}

TEST(SceneWorld, HandBuiltMistakesAreRefused) {
    Scene scene = freeBox({{.kind = SceneAction::Kind::Torque, .body = "ghost", .scalar = 1.0f}});
    EXPECT_THROW(buildWorld(scene), Error);
    scene.actions.clear();
    scene.bodies[0].shapes[0].halfExtents = {-1.0f, 1.0f};
    try {
        buildWorld(scene);
        FAIL() << "a box with a negative half extent was built";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()).rfind("bodies[0].shapes[0]: ", 0), 0u) << e.what();
    }
}

// A body the scene starts asleep hangs where it is until something touches it: a ball dropped
// from 1 m lands on it after √(2h/g) = 0.45 s and wakes it, and from then both fall.
TEST(SceneWorld, ABodyStartedAsleepWaitsForATouch) {
    Scene s;
    s.gravity = {0.0f, -9.8f};
    addBody(s, {.name = "sleeper", .position = {0.0f, 0.0f}, .awake = false, .shapes = {boxShape(0.5f, 0.5f)}});
    addBody(s, {.name = "ball", .position = {0.0f, 1.75f}, .shapes = {SceneShape{.kind = SceneShape::Kind::Circle, .radius = 0.25f}}});
    SceneWorld built = buildWorld(s);
    const BodyId sleeper = built.bodies[0];
    EXPECT_FALSE(built.world.isAwake(sleeper));
    for (int i = 0; i < 20; ++i) built.step();  // 0.33 s: the ball is still falling
    EXPECT_FALSE(built.world.isAwake(sleeper));
    EXPECT_EQ(built.world.position(sleeper), (Vec2{0.0f, 0.0f}));
    for (int i = 0; i < 40; ++i) built.step();
    EXPECT_TRUE(built.world.isAwake(sleeper));
    EXPECT_LT(built.world.position(sleeper).y, -0.1f);
}

TEST(SceneWorld, StateHashIsDeterministicAndSensitive) {
    SceneWorld a = buildWorld(findScene("pyramid")), b = buildWorld(findScene("pyramid"));
    EXPECT_EQ(stateHash(a.world), stateHash(b.world));
    for (int i = 0; i < 30; ++i) {
        a.step();
        b.step();
    }
    EXPECT_EQ(stateHash(a.world), stateHash(b.world));
    const uint64_t before = stateHash(a.world);
    a.world.setAngularVelocity(a.bodies.back(), a.world.angularVelocity(a.bodies.back()) + 1e-3f);
    EXPECT_NE(stateHash(a.world), before);
}

// --- the built-in scenes do what their descriptions say ---

TEST(BuiltinScenes, ProjectileFollowsTheDiscreteParabolaWithoutContact) {
    SceneWorld built = buildWorld(findScene("projectile"));
    const SceneBody& ball = built.scene.bodies[1];
    const float h = built.scene.timestep, g = built.scene.gravity.y;
    for (int n = 1; n <= built.scene.steps; ++n) {
        built.step();
        ASSERT_EQ(built.world.contactCount(), 0) << "step " << n;
        // a free body, semi-implicit Euler once per step: v_n = v0 + n h g, y_n = y0 + n h v0 + h² g n(n+1)/2
        const Vec2 p = built.world.position(built.bodies[1]);
        EXPECT_NEAR(p.x, ball.position.x + n * h * ball.linearVelocity.x, 1e-3f);
        EXPECT_NEAR(p.y, ball.position.y + n * h * ball.linearVelocity.y + h * h * g * n * (n + 1) / 2, 1e-3f);
    }
}

TEST(BuiltinScenes, SpinningBoxKeepsItsAngularVelocity) {
    SceneWorld built = buildWorld(findScene("spinning_box"));
    for (int n = 0; n < built.scene.steps; ++n) built.step();
    const float omega = built.scene.bodies[0].angularVelocity;
    EXPECT_FLOAT_EQ(built.world.angularVelocity(built.bodies[0]), omega);
    EXPECT_NEAR(built.world.angle(built.bodies[0]), omega * built.scene.steps * built.scene.timestep, 1e-3f);
    EXPECT_EQ(built.world.linearVelocity(built.bodies[0]), (Vec2{}));
}

TEST(BuiltinScenes, FrictionRampBlocksSlideOnlyWhenTanThetaExceedsMu) {
    SceneWorld built = buildWorld(findScene("friction_ramp"));
    for (int n = 0; n < built.scene.steps; ++n) built.step();
    for (size_t i = 1; i < built.bodies.size(); i += 2) {  // ramp, block, ramp, block...
        const SceneBody& block = built.scene.bodies[i];
        const float mu = block.shapes[0].friction, tanTheta = std::tan(block.angle);
        const float moved = distance(block.position, built.world.position(built.bodies[i]));
        if (tanTheta > mu)
            EXPECT_GT(moved, 1.0f) << block.name;
        else
            EXPECT_LT(moved, 0.05f) << block.name;
    }
}

TEST(BuiltinScenes, BouncingBallsReboundHigherWithMoreRestitution) {
    SceneWorld built = buildWorld(findScene("bouncing_balls"));
    std::vector<float> highest(built.bodies.size(), -1e9f);
    for (int n = 0; n < built.scene.steps; ++n) {
        built.step();
        if (n < 75) continue;  // every ball has hit the ground once (free fall of 4.5 m takes 57 steps)
        for (size_t i = 1; i < built.bodies.size(); ++i)
            highest[i] = std::max(highest[i], built.world.position(built.bodies[i]).y);
    }
    for (size_t i = 2; i < built.bodies.size(); ++i)
        EXPECT_GT(highest[i], highest[i - 1] + 0.1f) << built.scene.bodies[i].name;
    EXPECT_LT(highest[1], 0.6f);  // e = 0 stays on the ground (radius 0.5)
    EXPECT_GT(highest.back(), 4.0f);  // e = 1 comes back near its 5 m start
}

TEST(BuiltinScenes, RollingDiscRollsWithoutSlipping) {
    SceneWorld built = buildWorld(findScene("rolling_disc"));
    for (int n = 0; n < built.scene.steps; ++n) built.step();
    const BodyId disc = built.bodies[1];
    const Vec2 v = built.world.linearVelocity(disc);
    const float radius = built.scene.bodies[1].shapes[0].radius;
    ASSERT_GT(length(v), 1.0f);
    EXPECT_NEAR(-built.world.angularVelocity(disc) * radius, length(v), 0.02f * length(v));  // rolls right: ω < 0
}

TEST(BuiltinScenes, VerticalStackStands) {
    SceneWorld built = buildWorld(findScene("vertical_stack"));
    for (int n = 0; n < built.scene.steps; ++n) built.step();
    // Box2D 2.4's polygon skin (radius 0.01 each, less the 0.005 slop) keeps ~1.5 cm between
    // resting boxes, so ten contacts lift the top box by up to 0.15 m.
    for (size_t i = 1; i < built.bodies.size(); ++i) {
        const Vec2 p = built.world.position(built.bodies[i]);
        EXPECT_NEAR(p.x, 0.0f, 0.1f) << i;
        EXPECT_NEAR(p.y, built.scene.bodies[i].position.y, 0.2f) << i;
        EXPECT_NEAR(built.world.angle(built.bodies[i]), 0.0f, 0.01f) << i;
        EXPECT_LT(length(built.world.linearVelocity(built.bodies[i])), 0.01f) << i;
    }
}

}  // namespace
}  // namespace perpdot
