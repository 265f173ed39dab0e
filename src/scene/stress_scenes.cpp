// The torture suite of `perpdot stress`: each scene reproduces one case where a
// solver shows its limits. The figures and criteria that judge them are in
// src/crosscheck/stress.cpp; the scenes say only what is built. Sleeping is turned off per body
// (allowSleep), so that the exported JSON runs exactly like the built-in scene.
#include <string>

#include "perpdot/portable_math.hpp"
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
// link has density `ratio`, so its mass is `ratio` times a link's.
Scene heavyChain(float ratio) {
    Scene s;
    s.steps = 10 * seconds;
    const Vec2 pin{0.0f, 20.0f};
    addBody(s, {.name = "pin", .type = BodyType::Static, .position = pin});
    const int links = 20;
    const float length = 0.5f;
    std::string previous = "pin";
    for (int i = 0; i < links; ++i) {
        SceneShape link = boxShape(0.5f * length, 0.05f);
        if (i == links - 1) link.density = ratio;
        const std::string name = "link" + std::to_string(i);
        addBody(s, {.name = name, .position = pin + Vec2{(static_cast<float>(i) + 0.5f) * length, 0.0f}, .allowSleep = false,
                    .shapes = {link}});
        s.joints.push_back({.type = JointType::Revolute, .bodyA = previous, .bodyB = name,
                            .anchor = pin + Vec2{static_cast<float>(i) * length, 0.0f}});
        previous = name;
    }
    return s;
}

// The 20-link chain of heavyChain with its joints of every kind the direct solve takes: joint i is,
// by i mod 4, a hinge; a hinge limited to ±1 rad with a 1 N·m motor toward 0.5 rad/s; a weld; a
// slider along the link, limited to ±5 cm. The last link has density `ratio`.
Scene mixedChain(float ratio) {
    Scene s = heavyChain(ratio);
    for (size_t i = 0; i < s.joints.size(); ++i) {
        SceneJoint& j = s.joints[i];
        switch (i % 4) {
            case 1:
                j.enableLimit = true, j.lowerAngle = -1.0f, j.upperAngle = 1.0f;
                j.enableMotor = true, j.motorSpeed = 0.5f, j.maxMotorTorque = 1.0f;
                break;
            case 2: j.type = JointType::Weld; break;
            case 3:
                j.type = JointType::Prismatic, j.axis = {1.0f, 0.0f};
                j.enableLimit = true, j.lower = -0.05f, j.upper = 0.05f;
                break;
            default: break;
        }
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

// The large_pyramid benchmark scene (100 rows, 5,050 boxes, sleep off) for 10 s.
Scene largePile() {
    Scene s = findScene("large_pyramid");
    s.steps = 10 * seconds;
    return s;
}

// A 0.1 m ball of mass `mass` at `at`, falling at 10 m/s (the blow of the joint cases).
void addStriker(Scene& s, Vec2 at, float mass) {
    SceneShape ball = circleShape(0.1f);
    ball.density = mass / (3.14159265f * 0.1f * 0.1f);
    addBody(s, {.name = "striker", .position = at, .linearVelocity = {0.0f, -10.0f}, .allowSleep = false, .shapes = {ball}});
}

// Simultaneous impacts. `count` frictionless balls (e = 1, 0.25 m) in a row along x, `gap` apart,
// in zero gravity; the first `moving` of them travel at 2 m/s into the others (Newton's cradle).
Scene cradle(int count, int moving, float gap) {
    Scene s;
    s.steps = 3 * seconds;
    s.gravity = {0.0f, 0.0f};
    const float radius = 0.25f;
    for (int i = 0; i < count; ++i) {
        SceneShape ball = circleShape(radius);
        ball.restitution = 1.0f;
        ball.friction = 0.0f;
        addBody(s, {.name = "ball" + std::to_string(i), .position = {float(i) * (2.0f * radius + gap), 0.0f},
                    .linearVelocity = {i < moving ? 2.0f : 0.0f, 0.0f}, .allowSleep = false, .shapes = {ball}});
    }
    return s;
}

// The cradle on strings: `count` frictionless e = 1 balls (0.25 m) hung on 1 m rigid strings
// (distance joints) from a ceiling, their pivots 2r + `gap` apart; the first `released` pulled aside
// together to 30° and let go, under gravity (they meet the row at √(2 g L (1 − cos 30°)) = 1.64 m/s).
Scene cradleOnStrings(int count, int released, float gap) {
    Scene s;
    s.steps = 2 * seconds;
    const float radius = 0.25f, stringLength = 1.0f, release = 30.0f * pi / 180.0f;
    addBody(s, {.name = "ceiling", .type = BodyType::Static, .position = {0.0f, 0.0f}});
    for (int i = 0; i < count; ++i) {
        SceneShape ball = circleShape(radius);
        ball.restitution = 1.0f;
        ball.friction = 0.0f;
        const float pivot = float(i) * (2.0f * radius + gap);
        const SinCos a = sinCos(i < released ? release : 0.0f);
        const std::string name = "ball" + std::to_string(i);
        addBody(s, {.name = name, .position = {pivot - stringLength * a.sin, -stringLength * a.cos},
                    .allowSleep = false, .shapes = {ball}});
        s.joints.push_back({.type = JointType::Distance, .bodyA = "ceiling", .bodyB = name, .anchor = Vec2{pivot, 0.0f},
                            .anchorB = s.bodies.back().position});
    }
    return s;
}

// A billiard break: a cue ball at 5 m/s into a racked triangle of 15 touching balls (top-down:
// zero gravity, frictionless, e = 1).
Scene billiards() {
    Scene s;
    s.steps = 2 * seconds;
    s.gravity = {0.0f, 0.0f};
    const float radius = 0.25f, rowStep = 2.0f * radius * 0.8660254f;  // rows of touching balls: 2r·cos 30°
    const auto ball = [&](const std::string& name, Vec2 at, Vec2 velocity) {
        SceneShape shape = circleShape(radius);
        shape.restitution = 1.0f;
        shape.friction = 0.0f;
        addBody(s, {.name = name, .position = at, .linearVelocity = velocity, .allowSleep = false, .shapes = {shape}});
    };
    ball("cue", {-3.0f, 0.0f}, {5.0f, 0.0f});
    for (int row = 0; row < 5; ++row)
        for (int k = 0; k <= row; ++k)
            ball("ball" + std::to_string(row) + "_" + std::to_string(k),
                 {float(row) * rowStep, (float(k) - 0.5f * float(row)) * 2.0f * radius}, {});
    return s;
}

// Hard joints under impact (zero gravity): a light 1 m arm (0.1 kg) held at its left end by
// `joint` to a static pin, struck 0.9 m out by a 0.1 m ball 50 times its mass at 10 m/s.
Scene armStruck(JointType joint) {
    Scene s;
    s.steps = seconds;
    s.gravity = {0.0f, 0.0f};
    addBody(s, {.name = "pin", .type = BodyType::Static});
    SceneShape arm = boxShape(0.5f, 0.05f);
    arm.density = 1.0f;  // 0.1 kg
    addBody(s, {.name = "arm", .position = {0.5f, 0.0f}, .allowSleep = false, .shapes = {arm}});
    SceneJoint hold{.type = joint, .bodyA = "pin", .bodyB = "arm", .anchor = Vec2{0.0f, 0.0f}};
    if (joint == JointType::Revolute) hold.enableLimit = true, hold.lowerAngle = -0.05f, hold.upperAngle = 0.05f;
    s.joints.push_back(hold);
    addStriker(s, {0.9f, 0.25f}, 50.0f * 0.1f);
    return s;
}

// A light 0.5 m box (0.25 kg) on a vertical prismatic joint limited to ±5 cm, struck from above
// by a ball 50 times its mass at 10 m/s (zero gravity).
Scene sliderStruck() {
    Scene s;
    s.steps = seconds;
    s.gravity = {0.0f, 0.0f};
    addBody(s, {.name = "base", .type = BodyType::Static});
    addBody(s, {.name = "slider", .position = {0.0f, 0.0f}, .allowSleep = false, .shapes = {boxShape(0.25f, 0.25f)}});
    s.joints.push_back({.type = JointType::Prismatic, .bodyA = "base", .bodyB = "slider", .anchor = Vec2{0.0f, 0.0f},
                        .enableLimit = true, .lower = -0.05f, .upper = 0.05f, .axis = {0.0f, 1.0f}});
    addStriker(s, {0.0f, 0.5f}, 50.0f * 0.25f);
    return s;
}

// A suspension bridge of 20 hinged 0.5 m planks (0.05 kg each) hanging between two posts 9.74 m
// apart, its hinges on a circular arc 0.99 m deep in the middle: a closed loop of joints, carrying a
// load of 1000 planks' mass hung from its lowest hinge. It hangs because a deck pulled straight
// between posts exactly its length apart carries no load on hinges that do not stretch: the tension
// that holds a load W at a sag angle θ is W / (2 sin θ), without bound as θ goes to 0. The arc is
// not the loaded deck's shape: the load pulls it towards a V, 0.14 m deeper.
Scene loadedBridge() {
    Scene s;
    s.steps = 10 * seconds;
    const int planks = 20;
    const float half = 0.25f, y = 10.0f, arc = 0.8f;    // the posts' height; the arc's angle, rad
    const float step = arc / planks;                          // each plank's share of the arc
    const SinCos halfStep = sinCos(0.5f * step), halfArc = sinCos(0.5f * arc);
    const float radius = half / halfStep.sin;                 // so that each plank is a chord of it
    auto hinge = [&](int j) {                                 // hinge j of planks + 1, lowest in the middle
        const SinCos phi = sinCos(-0.5f * arc + step * float(j));
        return Vec2{radius * phi.sin, y - radius * (phi.cos - halfArc.cos)};
    };
    addBody(s, {.name = "left_post", .type = BodyType::Static, .position = hinge(0)});
    addBody(s, {.name = "right_post", .type = BodyType::Static, .position = hinge(planks)});
    std::string previous = "left_post";
    for (int i = 0; i < planks; ++i) {
        const std::string name = "plank" + std::to_string(i);
        const Vec2 p1 = hinge(i), p2 = hinge(i + 1);
        addBody(s, {.name = name, .position = 0.5f * (p1 + p2), .angle = atan2(p2.y - p1.y, p2.x - p1.x), .allowSleep = false,
                    .shapes = {boxShape(half, 0.05f)}});
        s.joints.push_back({.type = JointType::Revolute, .bodyA = previous, .bodyB = name, .anchor = p1});
        previous = name;
    }
    s.joints.push_back({.type = JointType::Revolute, .bodyA = previous, .bodyB = "right_post", .anchor = hinge(planks)});
    SceneShape load = boxShape(0.25f, 0.25f);
    load.density = 1000.0f * 0.05f / 0.25f;  // 50 kg
    // Hung from the lowest hinge on an arm of 0.6 m, 10 cm below the deck.
    const Vec2 lowest = hinge(planks / 2);
    addBody(s, {.name = "load", .position = lowest - Vec2{0.0f, 0.6f}, .allowSleep = false, .shapes = {load}});
    s.joints.push_back({.type = JointType::Revolute, .bodyA = "plank" + std::to_string(planks / 2 - 1), .bodyB = "load", .anchor = lowest});
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
        {"stress_chain", "stress: 20 hinged 0.5 m links, the last 100 times a link's mass, released horizontal, 10 s",
         [] { return heavyChain(100.0f); }},
        {"stress_tiles", "stress: a 1 m box sliding frictionless at 6 m/s over 40 separate 1 m tiles, 5 s", tiles},
        {"stress_pyramid20", "stress: a 20-row pyramid of unit boxes, sleep off, 60 s", pyramid20},
        {"stress_pile20", "stress: the 20-row pyramid of unit boxes, judged on its height, 60 s", pyramid20},
        {"stress_large_pile", "stress: the large_pyramid benchmark's 100-row pyramid (5,050 boxes), judged on its height, 10 s", largePile},
        {"stress_column100", "stress: 100 unit boxes stacked exactly touching, sleep off, 30 s", [] { return stack(100, 30 * seconds); }},
        {"stress_cradle5", "stress: a ball at 2 m/s into 4 touching balls, e = 1, zero gravity, 3 s", [] { return cradle(5, 1, 0.0f); }},
        {"stress_cradle7_two", "stress: two touching balls at 2 m/s into 5 touching balls, e = 1, 3 s", [] { return cradle(7, 2, 0.0f); }},
        {"stress_cradle_gaps", "stress: 5 balls 1 mm apart, the first three at 2 m/s, e = 1, 3 s", [] { return cradle(5, 3, 0.001f); }},
        {"stress_cradle_strings", "stress: 7 balls on 1 m strings 1 mm apart, the first three released from 30 degrees, e = 1, 2 s",
         [] { return cradleOnStrings(7, 3, 0.001f); }},
        {"stress_billiards", "stress: a cue ball at 5 m/s into a rack of 15 touching balls, e = 1, top-down, 2 s", billiards},
        {"stress_hinge_hit", "stress: a 0.1 kg hinged arm limited to +-0.05 rad struck by a 5 kg ball at 10 m/s, 1 s",
         [] { return armStruck(JointType::Revolute); }},
        {"stress_weld_hit", "stress: a 0.1 kg welded arm struck by a 5 kg ball at 10 m/s, 1 s", [] { return armStruck(JointType::Weld); }},
        {"stress_slider_hit", "stress: a 0.25 kg slider limited to +-5 cm struck along its axis by a 12.5 kg ball at 10 m/s, 1 s",
         sliderStruck},
        {"stress_chain1000", "stress: the 20-link chain with an end 1000 times a link's mass, 10 s", [] { return heavyChain(1000.0f); }},
        {"stress_chain10k", "stress: the 20-link chain with an end 10,000 times a link's mass, 10 s", [] { return heavyChain(10000.0f); }},
        {"stress_mixed1000",
         "stress: the 20-link chain of hinges, limited motored hinges, welds and limited sliders, its end 1000 times a link's mass, 10 s",
         [] { return mixedChain(1000.0f); }},
        {"stress_bridge1000", "stress: a hanging 20-plank bridge carrying 1000 times a plank's mass, 10 s", loadedBridge},
    };
}

}  // namespace perpdot
