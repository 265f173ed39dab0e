// Joint scenes: pendulums, a chain, a suspension bridge, a ragdoll, a car on wheel joints, Box2D
// v3's joint grid benchmark, a motor-driven windmill and a prismatic slider.
#include <cmath>
#include <string>

#include "scene/builtin_registry.hpp"
#include "perpdot/portable_math.hpp"
#include "scene/ragdoll_figure.hpp"
#include "scene/scene_builders.hpp"

namespace perpdot {
namespace {

SceneJoint revolute(const std::string& a, const std::string& b, Vec2 anchor) {
    return {.type = JointType::Revolute, .bodyA = a, .bodyB = b, .anchor = anchor};
}

// A static body with no shapes, to hang things from.
void addAnchor(Scene& s, Vec2 position = {}) { addBody(s, {.name = "anchor", .type = BodyType::Static, .position = position}); }

// A 0.25 m ball on a 2 m arm, released 45° off the vertical: the cross-check's pendulum.
Scene pendulum() {
    Scene s;
    addAnchor(s, {0.0f, 10.0f});
    const float d = 2.0f;
    const SinCos start = sinCos(pi / 4.0f);
    const Vec2 bob{d * start.sin, 10.0f - d * start.cos};
    addBody(s, {.name = "bob", .position = bob, .shapes = {circleShape(0.25f)}});
    s.joints.push_back(revolute("anchor", "bob", {0.0f, 10.0f}));
    return s;
}

// Two 1 m bars, the first released horizontal: chaotic after a few swings.
Scene doublePendulum() {
    Scene s;
    addAnchor(s, {0.0f, 10.0f});
    addBody(s, {.name = "upper", .position = {0.5f, 10.0f}, .shapes = {boxShape(0.5f, 0.05f)}});
    addBody(s, {.name = "lower", .position = {1.5f, 10.0f}, .shapes = {boxShape(0.5f, 0.05f)}});
    s.joints.push_back(revolute("anchor", "upper", {0.0f, 10.0f}));
    s.joints.push_back(revolute("upper", "lower", {1.0f, 10.0f}));
    return s;
}

// 40 links of 0.5 m hung from one end, released horizontal, with a ball of 25 links at the tip.
Scene chain() {
    Scene s;
    addGround(s, 20.0f);
    const float top = 22.0f, half = 0.25f;
    addAnchor(s, {0.0f, top});
    std::string previous = "anchor";
    for (int i = 0; i < 40; ++i) {
        const std::string name = "link" + std::to_string(i);
        addBody(s, {.name = name, .position = {(2.0f * i + 1.0f) * half, top}, .shapes = {boxShape(half, 0.0625f)}});
        s.joints.push_back(revolute(previous, name, {2.0f * i * half, top}));
        previous = name;
    }
    SceneShape weight = circleShape(0.5f);
    weight.density = 2.0f;
    addBody(s, {.name = "weight", .position = {80.0f * half, top}, .shapes = {weight}});
    s.joints.push_back(revolute(previous, "weight", {80.0f * half, top}));
    return s;
}

// 30 planks between two posts, with a few boxes dropped on the deck.
Scene suspensionBridge() {
    Scene s;
    addGround(s, 30.0f);
    const int planks = 30;
    const float half = 0.5f, y = 5.0f, left = -half * planks;
    for (float x : {left - 0.5f, -left + 0.5f})
        addBody(s, {.name = x < 0 ? "left_post" : "right_post", .type = BodyType::Static, .position = {x, 2.5f},
                    .shapes = {boxShape(0.5f, 2.5f)}});
    std::string previous = "left_post";
    for (int i = 0; i < planks; ++i) {
        const std::string name = "plank" + std::to_string(i);
        addBody(s, {.name = name, .position = {left + (2.0f * i + 1.0f) * half, y}, .shapes = {boxShape(half, 0.125f)}});
        s.joints.push_back(revolute(previous, name, {left + 2.0f * i * half, y}));
        previous = name;
    }
    s.joints.push_back(revolute(previous, "right_post", {-left, y}));
    for (int i = 0; i < 3; ++i)
        addBody(s, {.name = "crate" + std::to_string(i), .position = {-4.0f + 4.0f * i, 8.0f + i},
                    .shapes = {boxShape(0.5f, 0.5f)}});
    return s;
}

// The bridge with breakable hinges (World::setJointBreakLimits), an anvil instead of the crates:
// the settling deck pulls its hinges up to 400 N, the 80 kg anvil 1,560 N; they break at 800 N.
Scene breakableBridge() {
    Scene s = suspensionBridge();
    while (s.bodies.back().name.starts_with("crate")) s.bodies.pop_back();
    for (SceneJoint& j : s.joints) j.breakForce = 800.0f;
    s.bodies.push_back({.name = "anvil", .position = {0.0f, 12.0f}, .shapes = {boxShape(1.0f, 1.0f)}});
    s.bodies.back().shapes[0].density = 20.0f;  // 80 kg
    return s;
}

// A limp human figure of boxes (ragdoll_figure.hpp), spinning as it falls to the ground.
Scene ragdoll() {
    Scene s;
    addGround(s, 20.0f);
    addRagdoll(s, {0.0f, 6.0f});
    s.bodies[1].angularVelocity = 2.0f;  // the torso; bodies[0] is the ground
    return s;
}

// A car with a motor on the rear wheel and spring suspension (wheel joints), driving over bumps.
Scene car() {
    Scene s;
    s.steps = 900;
    SceneBody ground{.name = "ground", .type = BodyType::Static};
    float x = -20.0f, previous = 0.0f;
    for (int i = 0; i < 40; ++i) {
        const float next = i % 4 == 3 ? 0.35f * static_cast<float>((i * 7) % 3) : 0.0f;
        ground.shapes.push_back(segmentShape({x, previous}, {x + 2.0f, next}));
        x += 2.0f;
        previous = next;
    }
    addBody(s, std::move(ground));
    const float y = 1.2f;
    addBody(s, {.name = "chassis", .position = {-15.0f, y}, .shapes = {boxShape(1.5f, 0.3f)}});
    for (float side : {-1.0f, 1.0f}) {
        const std::string name = side < 0 ? "rear_wheel" : "front_wheel";
        SceneShape wheel = circleShape(0.4f);
        wheel.friction = 0.9f;
        addBody(s, {.name = name, .position = {-15.0f + 1.1f * side, y - 0.65f}, .shapes = {wheel}});
        SceneJoint j{.type = JointType::Wheel, .bodyA = "chassis", .bodyB = name, .anchor = Vec2{-15.0f + 1.1f * side, y - 0.65f}};
        j.axis = {0.0f, 1.0f};
        j.hertz = 4.0f, j.dampingRatio = 0.7f;
        if (side < 0) j.enableMotor = true, j.motorSpeed = -8.0f, j.maxMotorTorque = 40.0f;
        s.joints.push_back(j);
    }
    return s;
}

// Box2D v3's joint grid benchmark: 100 × 100 circles (radius 0.4, 1 m apart) that do not collide
// with each other, each joined to its upper and left neighbours by revolute joints; the middle
// seven of the top row are static. Sleep off (per body, which the file format keeps).
Scene jointGrid() {
    Scene s;
    s.steps = 500;
    const int n = 100;
    SceneShape circle = circleShape(0.4f);
    circle.filter.category = 0x0002;
    circle.filter.mask = 0xFFFD;
    auto name = [](int k, int i) {
        std::string text = std::to_string(k);
        text += '_';
        text += std::to_string(i);
        return text;
    };
    for (int k = 0; k < n; ++k) {
        for (int i = 0; i < n; ++i) {
            const bool pinned = k >= n / 2 - 3 && k <= n / 2 + 3 && i == 0;
            const Vec2 p{static_cast<float>(k), -static_cast<float>(i)};
            addBody(s, {.name = name(k, i), .type = pinned ? BodyType::Static : BodyType::Dynamic, .position = p,
                        .allowSleep = false, .shapes = {circle}});
            if (i > 0)
                s.joints.push_back({.type = JointType::Revolute, .bodyA = name(k, i - 1), .bodyB = name(k, i),
                                    .localAnchorA = Vec2{0.0f, -0.5f}, .localAnchorB = Vec2{0.0f, 0.5f}});
            if (k > 0)
                s.joints.push_back({.type = JointType::Revolute, .bodyA = name(k - 1, i), .bodyB = name(k, i),
                                    .localAnchorA = Vec2{0.5f, 0.0f}, .localAnchorB = Vec2{-0.5f, 0.0f}});
        }
    }
    return s;
}

// Four blades turned at 1 rad/s by a revolute motor, paddling balls dropped on them.
Scene windmill() {
    Scene s;
    addGround(s, 20.0f);
    addBody(s, {.name = "tower", .type = BodyType::Static, .position = {0.0f, 3.0f}, .shapes = {boxShape(0.2f, 3.0f)}});
    addBody(s, {.name = "rotor", .position = {0.0f, 6.0f},
                .shapes = {boxShape(3.0f, 0.1f), boxShape(0.1f, 3.0f)}});
    SceneJoint motor = revolute("tower", "rotor", {0.0f, 6.0f});
    motor.enableMotor = true, motor.motorSpeed = 1.0f, motor.maxMotorTorque = 1000.0f;
    s.joints.push_back(motor);
    for (int i = 0; i < 8; ++i)
        addBody(s, {.name = "ball" + std::to_string(i), .position = {-2.6f + 0.75f * i, 11.0f + 0.5f * i},
                    .shapes = {circleShape(0.25f)}});
    return s;
}

// A block slides down a 30° rail (prismatic joint) until its lower limit stops it.
Scene prismaticSlider() {
    Scene s;
    addAnchor(s, {0.0f, 5.0f});
    const SinCos rail30 = sinCos(pi / 6.0f);
    const Vec2 axis{rail30.cos, rail30.sin};
    addBody(s, {.name = "slider", .position = {0.0f, 5.0f}, .angle = pi / 6.0f, .shapes = {boxShape(0.5f, 0.25f)}});
    SceneJoint rail{.type = JointType::Prismatic, .bodyA = "anchor", .bodyB = "slider", .anchor = Vec2{0.0f, 5.0f}};
    rail.axis = axis;
    rail.enableLimit = true, rail.lower = -3.0f, rail.upper = 3.0f;
    s.joints.push_back(rail);
    return s;
}

}  // namespace

std::vector<BuiltinScene> jointScenes() {
    return {
        {"pendulum", "a ball on a 2 m revolute arm released 45 degrees off the vertical", pendulum},
        {"double_pendulum", "two hinged bars released horizontal", doublePendulum},
        {"chain", "40 hinged links and a heavy ball, released horizontal", chain},
        {"suspension_bridge", "30 hinged planks between two posts, crates dropped on the deck", suspensionBridge},
        {"breakable_bridge", "the suspension bridge with hinges that break above 800 N; an 80 kg anvil snaps it", breakableBridge},
        {"ragdoll", "a figure of boxes with limited revolute joints falls to the ground", ragdoll},
        {"car", "a car on wheel joints (springs, rear motor) drives over bumps", car},
        {"joint_grid", "Box2D v3's benchmark: 100x100 circles linked by revolute joints, sleep off", jointGrid},
        {"windmill", "four blades on a motor-driven revolute joint paddle falling balls", windmill},
        {"prismatic_slider", "a block slides down a 30 degree rail to its lower limit", prismaticSlider},
    };
}

}  // namespace perpdot
