// The torture suite of `perpdot stress` (issue 13): each scene reproduces one case where a
// solver shows its limits. The figures and criteria that judge them are in
// src/crosscheck/stress.cpp; the scenes say only what is built. Sleeping is turned off per body
// (allowSleep), so that the exported JSON runs exactly like the built-in scene.
#include <string>

#include "scene/builtin_registry.hpp"
#include "scene/scene_builders.hpp"

namespace perpdot {
namespace {

constexpr int seconds = 60;  // steps per second at the scenes' 1/60 s step

// `count` unit boxes stacked exactly touching on the ground, 1 m apart.
Scene stack(int count, int steps) {
    Scene s;
    s.steps = steps;
    addGround(s, 20.0f);
    for (int i = 0; i < count; ++i)
        addBody(s, {.name = "box" + std::to_string(i), .position = {0.0f, 0.5f + static_cast<float>(i)}, .allowSleep = false,
                    .shapes = {boxShape(0.5f, 0.5f)}});
    return s;
}

// A 0.25 m ball whose bottom starts 3 m above a ground of the same restitution.
Scene bounce(float restitution, int steps) {
    Scene s;
    s.steps = steps;
    addGround(s, 20.0f).shapes[0].restitution = restitution;
    SceneShape ball = circleShape(0.25f);
    ball.restitution = restitution;
    addBody(s, {.name = "ball", .position = {0.0f, 3.25f}, .allowSleep = false, .shapes = {ball}});
    return s;
}

Scene boxAtRest() {
    Scene s;
    s.steps = 5 * seconds;
    addGround(s, 20.0f);
    addBody(s, {.name = "box", .position = {0.0f, 0.5f}, .allowSleep = false, .shapes = {boxShape(0.5f, 0.5f)}});
    return s;
}

// Two 0.05 m bullets closing at 400 m/s in zero gravity; they would meet 2.37 steps after the start.
Scene bullets() {
    Scene s;
    s.steps = seconds;
    s.gravity = {0.0f, 0.0f};
    const float speed = 200.0f, start = speed * 2.37f / seconds;
    addBody(s, {.name = "left", .position = {-start, 0.0f}, .linearVelocity = {speed, 0.0f}, .bullet = true,
                .allowSleep = false, .shapes = {circleShape(0.025f)}});
    addBody(s, {.name = "right", .position = {start, 0.0f}, .linearVelocity = {-speed, 0.0f}, .bullet = true,
                .allowSleep = false, .shapes = {circleShape(0.025f)}});
    return s;
}

// A 1 m box of density `ratio` resting on a 1 m box of density 1 on the ground.
Scene heavyOnLight(float ratio) {
    Scene s;
    s.steps = 10 * seconds;
    addGround(s, 20.0f);
    addBody(s, {.name = "light", .position = {0.0f, 0.5f}, .allowSleep = false, .shapes = {boxShape(0.5f, 0.5f)}});
    SceneShape heavy = boxShape(0.5f, 0.5f);
    heavy.density = ratio;
    addBody(s, {.name = "heavy", .position = {0.0f, 1.5f}, .allowSleep = false, .shapes = {heavy}});
    return s;
}

// 20 links of 0.5 m (0.1 m thick) hinged end to end from a pin, released horizontal; the last
// link has density 100, so its mass is 100 times a link's.
Scene heavyChain() {
    Scene s;
    s.steps = 10 * seconds;
    const Vec2 pin{0.0f, 20.0f};
    addBody(s, {.name = "pin", .type = BodyType::Static, .position = pin});
    const int links = 20;
    const float length = 0.5f;
    std::string previous = "pin";
    for (int i = 0; i < links; ++i) {
        SceneShape link = boxShape(0.5f * length, 0.05f);
        if (i == links - 1) link.density = 100.0f;
        const std::string name = "link" + std::to_string(i);
        addBody(s, {.name = name, .position = pin + Vec2{(static_cast<float>(i) + 0.5f) * length, 0.0f}, .allowSleep = false,
                    .shapes = {link}});
        s.joints.push_back({.type = JointType::Revolute, .bodyA = previous, .bodyB = name,
                            .anchor = pin + Vec2{static_cast<float>(i) * length, 0.0f}});
        previous = name;
    }
    return s;
}

// A 1 m box sliding without friction at 6 m/s over 40 separate 1 m box tiles (one static body).
Scene tiles() {
    Scene s;
    s.steps = 5 * seconds;
    SceneBody& floor = addBody(s, {.name = "tiles", .type = BodyType::Static});
    for (int i = 0; i < 40; ++i) {
        floor.shapes.push_back(boxShape(0.5f, 0.5f, {static_cast<float>(i) + 0.5f, -0.5f}));
        floor.shapes.back().friction = 0.0f;
    }
    SceneShape box = boxShape(0.5f, 0.5f);
    box.friction = 0.0f;
    addBody(s, {.name = "box", .position = {1.0f, 0.5f}, .linearVelocity = {6.0f, 0.0f}, .allowSleep = false, .shapes = {box}});
    return s;
}

Scene pyramid20() {
    Scene s;
    s.steps = 60 * seconds;
    addGround(s, 40.0f);
    addPyramid(s, 20, 0.5f, -10.0f, 0.0f, false);
    return s;
}

}  // namespace

std::vector<BuiltinScene> stressScenes() {
    return {
        {"stress_stack30", "stress: 30 unit boxes stacked exactly touching, sleep off, 60 s", [] { return stack(30, 60 * seconds); }},
        {"stress_stack50", "stress: 50 unit boxes stacked exactly touching, sleep off, 30 s", [] { return stack(50, 30 * seconds); }},
        {"stress_bounce_e1", "stress: a 0.25 m ball, e = 1, dropped 3 m on an e = 1 ground, 16 s (8 bounces)",
         [] { return bounce(1.0f, 16 * seconds); }},
        {"stress_bounce_e05", "stress: a 0.25 m ball, e = 0.5, dropped 3 m on an e = 0.5 ground, 5 s",
         [] { return bounce(0.5f, 5 * seconds); }},
        {"stress_box_rest", "stress: a 1 m box placed at rest on the ground, 5 s", boxAtRest},
        {"stress_bullets", "stress: two 0.05 m bullets closing at 400 m/s, zero gravity, 1 s", bullets},
        {"stress_mass100", "stress: a 1 m box of density 100 on a 1 m box of density 1, 10 s", [] { return heavyOnLight(100.0f); }},
        {"stress_mass300", "stress: a 1 m box of density 300 on a 1 m box of density 1, 10 s", [] { return heavyOnLight(300.0f); }},
        {"stress_mass1000", "stress: a 1 m box of density 1000 on a 1 m box of density 1, 10 s", [] { return heavyOnLight(1000.0f); }},
        {"stress_chain", "stress: 20 hinged 0.5 m links, the last 100 times a link's mass, released horizontal, 10 s", heavyChain},
        {"stress_tiles", "stress: a 1 m box sliding frictionless at 6 m/s over 40 separate 1 m tiles, 5 s", tiles},
        {"stress_pyramid20", "stress: a 20-row pyramid of unit boxes, sleep off, 60 s", pyramid20},
    };
}

}  // namespace perpdot
