// Core scenes: each isolates one piece of the physics (free flight, contact, stacking,
// restitution, Coulomb friction, rolling, rotation, torque from an off-centre force).
#include <cmath>
#include <cstdio>

#include "scene/builtin_registry.hpp"
#include "perpdot/portable_math.hpp"
#include "scene/scene_builders.hpp"

namespace perpdot {
namespace {

Scene singleBox() {
    Scene s;
    s.steps = 240;
    addGround(s, 20.0f);
    addBody(s, {.name = "box", .position = {0.0f, 4.0f}, .shapes = {boxShape(0.5f, 0.5f)}});
    return s;
}

Scene verticalStack() {
    Scene s;
    addGround(s, 20.0f);
    for (int i = 0; i < 10; ++i) addBody(s, {.position = {0.0f, 0.5f + i}, .shapes = {boxShape(0.5f, 0.5f)}});
    return s;
}

Scene pyramid() {
    Scene s;
    const int rows = 20;
    addGround(s, 40.0f);
    addPyramid(s, rows, 0.5f, -0.5f * rows, 0.0f);
    return s;
}

Scene bouncingBalls() {
    Scene s;
    s.steps = 300;
    addGround(s, 20.0f);
    const float restitutions[] = {0.0f, 0.25f, 0.5f, 0.75f, 1.0f};
    for (int i = 0; i < 5; ++i) {
        SceneShape ball = circleShape(0.5f);
        ball.restitution = restitutions[i];
        char name[16];
        std::snprintf(name, sizeof name, "ball_e%.2f", restitutions[i]);
        addBody(s, {.name = name, .position = {-4.0f + 2.0f * i, 5.0f}, .shapes = {ball}});
    }
    return s;
}

// A static ramp: a box 0.5 m thick turned by `slope` about its centre.
SceneShape rampShape(float halfLength, float slope) { return boxShape(halfLength, 0.25f, {}, slope); }
// The point `height` above the ramp's top face, `along` metres from its middle.
Vec2 onRamp(Vec2 rampCenter, float slope, float along, float height) {
    return rampCenter + rotate(Rot::fromAngle(slope), {along, 0.25f + height});
}

// A block slides down an incline when tanθ > μ and holds when tanθ < μ. Each block has its own
// ramp with the same μ, so the mixed friction sqrt(μ_block μ_ramp) is exactly μ.
Scene frictionRamp() {
    Scene s;
    s.steps = 120;  // the fastest block slides 4.8 m of the 8 m below it
    const float slope = pi / 6.0f;  // tan 30° = 0.577
    const float mus[] = {0.3f, 0.5f, 0.7f, 0.9f};
    for (int i = 0; i < 4; ++i) {
        const Vec2 center{12.0f * i, 0.0f};
        SceneShape ramp = rampShape(5.0f, slope), block = boxShape(0.5f, 0.5f);
        ramp.friction = block.friction = mus[i];
        char name[16];
        std::snprintf(name, sizeof name, "mu%.1f", mus[i]);
        addBody(s, {.name = std::string("ramp_") + name, .type = BodyType::Static, .position = center, .shapes = {ramp}});
        addBody(s, {.name = std::string("block_") + name, .position = onRamp(center, slope, 3.0f, 0.5f),
                    .angle = slope, .shapes = {block}});
    }
    return s;
}

// A uniform disc rolls without slipping down a slope θ when μ ≥ tanθ/3; its centre then
// accelerates at (2/3) g sinθ and ω = v / r.
Scene rollingDisc() {
    Scene s;
    s.steps = 180;
    const float slope = 0.25f;
    addBody(s, {.name = "ramp", .type = BodyType::Static, .shapes = {rampShape(20.0f, -slope)}});
    addBody(s, {.name = "disc", .position = onRamp({}, -slope, -15.0f, 0.5f), .shapes = {circleShape(0.5f)}});
    return s;
}

Scene spinningBox() {
    Scene s;
    s.gravity = {};
    s.steps = 300;
    addBody(s, {.name = "box", .angularVelocity = 2.0f, .shapes = {boxShape(1.0f, 0.5f)}});
    return s;
}

// Zero gravity; a force at the end of a 2 m × 1 m box: the CM accelerates by F/m and the box
// spins up by τ/I with τ = perpDot(P - CM, F).
Scene offCenterPush() {
    Scene s;
    s.gravity = {};
    s.steps = 240;
    addBody(s, {.name = "box", .shapes = {boxShape(1.0f, 0.5f)}});
    s.actions.push_back({.kind = SceneAction::Kind::Force, .body = "box", .value = {0.0f, 10.0f},
                         .point = Vec2{1.0f, 0.0f}, .firstStep = 0, .lastStep = 59});
    return s;
}

// A ball launched at 45° at 10 m/s from 1 m above the ground: a parabola that lands after the
// last step (it is back at its launch height after 2 v sin45° / g ≈ 1.41 s = 85 steps).
Scene projectile() {
    Scene s;
    s.steps = 80;
    addGround(s, 20.0f);
    const float speed = 10.0f;
    const SinCos launch = sinCos(pi / 4.0f);
    addBody(s, {.name = "ball", .position = {-8.0f, 1.0f},
                .linearVelocity = {speed * launch.cos, speed * launch.sin}, .shapes = {circleShape(0.25f)}});
    return s;
}

}  // namespace

std::vector<BuiltinScene> coreScenes() {
    return {
        {"single_box", "a 1 m box dropped from 4 m onto the ground", singleBox},
        {"vertical_stack", "10 boxes of 1 m stacked on a static ground", verticalStack},
        {"pyramid", "a pyramid of 20 rows of 1 m boxes (210 boxes)", pyramid},
        {"bouncing_balls", "balls with restitution 0, 0.25, 0.5, 0.75 and 1 dropped on the ground", bouncingBalls},
        {"friction_ramp", "blocks on 30 degree ramps: mu 0.3, 0.5 slide (tan 30 = 0.577), mu 0.7, 0.9 hold", frictionRamp},
        {"rolling_disc", "a disc rolling without slipping down a 0.25 rad incline", rollingDisc},
        {"spinning_box", "zero gravity: a 2 m x 1 m box spinning at 2 rad/s", spinningBox},
        {"off_center_push", "zero gravity: a force at the end of a box makes it translate and spin", offCenterPush},
        {"projectile", "a ball launched at 45 degrees, 10 m/s; lands after the last step", projectile},
    };
}

}  // namespace perpdot
