// Demo scenes for the viewer: each shows one behaviour that is easy to see and hard to fake
// (stacking on friction alone, momentum passed along a row, spin from an off-centre impulse, ...).
#include <cmath>
#include <cstdint>
#include <string>

#include "scene/builtin_registry.hpp"
#include "scene/scene_builders.hpp"

namespace perpdot {
namespace {

constexpr float degrees = pi / 180.0f;

SceneShape withMaterial(SceneShape shape, float friction, float restitution) {
    shape.friction = friction;
    shape.restitution = restitution;
    return shape;
}

// Box2D v3's card house (Solver2D) at 5x scale: leaning pairs of cards at ±25°, a flat card
// bridging neighbouring pairs, five storeys; it stands on friction (μ = 0.7) alone.
Scene cardHouse() {
    Scene s;
    s.steps = 600;
    SceneBody& ground = addGround(s, 10.0f);
    ground.shapes[0].friction = 0.7f;
    const float cardHalfHeight = 1.0f, cardHalfThickness = 0.02f;
    const SceneShape card = withMaterial(boxShape(cardHalfThickness, cardHalfHeight), 0.7f, 0.0f);
    const float pairStep = 0.875f;
    float y = cardHalfHeight - 0.1f, z0 = -3.5f;
    for (int perRow = 5; perRow > 0; --perRow) {
        float z = z0;
        for (int i = 0; i < perRow; ++i) {
            if (i != perRow - 1) {
                addBody(s, {.position = {z + 1.25f, y + cardHalfHeight - 0.075f}, .angle = 90.0f * degrees, .shapes = {card}});
            }
            addBody(s, {.position = {z, y}, .angle = -25.0f * degrees, .shapes = {card}});
            z += pairStep;
            addBody(s, {.position = {z, y}, .angle = 25.0f * degrees, .shapes = {card}});
            z += pairStep;
        }
        y += 2.0f * cardHalfHeight - 0.15f;
        z0 += pairStep;
    }
    return s;
}

// Five touching balls (restitution 1, no friction) on a frictionless table between two walls;
// a sixth ball arrives at 4 m/s. The impact passes down the row as the textbook's sequence of
// two-body impacts (impact_propagation.cpp) and the far ball leaves at the striker's speed.
Scene newtonsCradle() {
    Scene s;
    s.steps = 900;
    const float r = 0.5f;
    const SceneShape ball = withMaterial(circleShape(r), 0.0f, 1.0f);
    SceneBody& ground = addGround(s, 7.5f);
    ground.shapes[0] = withMaterial(ground.shapes[0], 0.0f, 1.0f);
    for (float x : {-7.0f, 7.0f}) {
        addBody(s, {.name = x < 0 ? "left_wall" : "right_wall", .type = BodyType::Static, .position = {x, 1.5f},
                    .shapes = {withMaterial(boxShape(0.25f, 1.5f), 0.0f, 1.0f)}});
    }
    for (int i = 0; i < 5; ++i) {
        addBody(s, {.name = "ball" + std::to_string(i), .position = {-2.0f + 2.0f * r * i, r}, .allowSleep = false,
                    .shapes = {ball}});
    }
    addBody(s, {.name = "striker", .position = {-5.0f, r}, .linearVelocity = {4.0f, 0.0f}, .allowSleep = false,
                .shapes = {ball}});
    return s;
}

// Hecker's off-centre hit, zero gravity: a ball strikes a thin free rod 0.3 m from its end.
// The impulse j n makes the rod translate (Δv = j n / m) and spin (Δω = perpDot(r, j n) / I).
// Seen from the pair's centre of mass (total momentum zero), so both stay in view.
Scene offcenterHit() {
    Scene s;
    s.gravity = {0.0f, 0.0f};
    s.steps = 300;
    SceneShape rod = boxShape(2.0f, 0.1f), ball = withMaterial(circleShape(0.25f), 0.3f, 0.5f);
    rod.density = 1.0f;   // m = 0.8 kg
    ball.density = 4.0f;  // m = 0.785 kg
    const float ballSpeed = 1.5f, rodSpeed = -ballSpeed * (4.0f * pi * 0.0625f) / 0.8f;
    addBody(s, {.name = "rod", .position = {0.0f, 1.0f}, .linearVelocity = {0.0f, rodSpeed}, .shapes = {rod}});
    addBody(s, {.name = "ball", .position = {-1.7f, -1.5f}, .linearVelocity = {0.0f, ballSpeed}, .shapes = {ball}});
    return s;
}

// A hollow box of four walls on one kinematic body turning at 0.5 rad/s, tumbling 96 boxes.
Scene tumbler() {
    Scene s;
    s.steps = 900;
    const float half = 5.0f, wall = 0.25f;
    addBody(s, {.name = "tumbler", .type = BodyType::Kinematic, .position = {0.0f, 0.0f}, .angularVelocity = 0.5f,
                .shapes = {boxShape(wall, half, {-half, 0.0f}), boxShape(wall, half, {half, 0.0f}),
                           boxShape(half, wall, {0.0f, -half}), boxShape(half, wall, {0.0f, half})}});
    for (int row = 0; row < 8; ++row) {
        for (int column = 0; column < 12; ++column) {
            addBody(s, {.position = {-3.3f + 0.6f * column, -4.4f + 0.6f * row}, .shapes = {boxShape(0.25f, 0.25f)}});
        }
    }
    return s;
}

// 150 circles, boxes and triangles of varied sizes, in 15 jittered rows of 10, fall into a bucket.
// Sizes, offsets and angles come from a fixed linear congruential sequence, so the scene never changes.
Scene rain() {
    Scene s;
    s.steps = 900;
    addGround(s, 8.0f);
    for (float x : {-7.75f, 7.75f}) {
        addBody(s, {.name = x < 0 ? "left_wall" : "right_wall", .type = BodyType::Static, .position = {x, 4.0f},
                    .shapes = {boxShape(0.25f, 4.0f)}});
    }
    uint32_t state = 12345u;
    const auto uniform = [&state](float lo, float hi) {  // Numerical Recipes' LCG
        state = 1664525u * state + 1013904223u;
        return lo + (hi - lo) * static_cast<float>(state >> 8) / static_cast<float>(1u << 24);
    };
    for (int i = 0; i < 150; ++i) {
        const float size = uniform(0.2f, 0.45f);
        SceneShape shape;
        switch (i % 3) {
            case 0: shape = circleShape(size); break;
            case 1: shape = boxShape(size, uniform(0.6f, 1.0f) * size); break;
            default: shape = polygonShape({{-size, -0.6f * size}, {size, -0.6f * size}, {0.0f, size}}); break;
        }
        const int column = i % 10, row = i / 10;  // 15 rows of 10
        const Vec2 position{-6.3f + 1.4f * column + uniform(-0.25f, 0.25f), 4.0f + 1.2f * row + uniform(0.0f, 0.3f)};
        addBody(s, {.position = position, .angle = uniform(-pi, pi), .shapes = {shape}});
    }
    return s;
}

// 20 dominoes; an impulse at the top of the first one tips it (τ = perpDot(r, J)) into the next.
Scene dominoes() {
    Scene s;
    s.steps = 600;
    addGround(s, 14.0f);
    const float halfThickness = 0.1f, halfHeight = 1.0f, spacing = 1.2f;
    for (int i = 0; i < 20; ++i) {
        addBody(s, {.name = "domino" + std::to_string(i), .position = {-11.5f + spacing * i, halfHeight},
                    .shapes = {boxShape(halfThickness, halfHeight)}});
    }
    s.actions.push_back({.kind = SceneAction::Kind::Impulse, .body = "domino0", .value = {0.3f, 0.0f},
                         .point = Vec2{-11.5f, 2.0f * halfHeight}, .firstStep = 0, .lastStep = 0});
    return s;
}

}  // namespace

std::vector<BuiltinScene> demoScenes() {
    return {
        {"card_house", "five storeys of leaning cards (Box2D v3's card house at 5x scale), standing on friction mu = 0.7",
         cardHouse},
        {"newtons_cradle",
         "a ball hits five touching balls (restitution 1, no friction): the impact passes down the row and the far "
         "ball leaves at the striker's speed",
         newtonsCradle},
        {"offcenter_hit", "zero gravity: a ball hits a free rod near its end; the rod translates and spins (Hecker)",
         offcenterHit},
        {"tumbler", "a kinematic hollow box turning at 0.5 rad/s tumbles 96 boxes", tumbler},
        {"rain", "150 circles, boxes and triangles rain into a bucket", rain},
        {"dominoes", "an impulse at the top of the first of 20 dominoes topples the row", dominoes},
    };
}

}  // namespace perpdot
