// Chains without ghost collisions: a box sliding over a floor made of many short chain segments
// never catches on a seam, because every one-sided chain edge knows its neighbours (ghost
// vertices). A floor of separate two-sided segments has no such knowledge; the second test
// measures the difference.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "features_helpers.hpp"

namespace perpdot {
namespace {

using features::dt;

struct Slide {
    float maxVerticalSpeed = 0.0f;  // |vy|
    float maxAngularSpeed = 0.0f;   // |ω|
    float maxSpeedIncrease = 0.0f;  // largest step-to-step growth of |vx| while sliding (≤ 0 when smooth)
    float maxDecelerationError = 0.0f;  // | Δvx/h − (−μ g) | while sliding
    float distance = 0.0f;
};

constexpr float mu = 0.2f, g = 10.0f, v0 = 8.0f;
constexpr float tileWidth = 0.5f;  // seams every 0.5 m, narrower than the 1 m box

// A 1 m box (friction μ on both) starts sliding at 8 m/s over a floor from x = −20 to 30.
Slide slide(bool chainFloor) {
    World world;
    const BodyId ground = features::addStatic(world, {});
    const ShapeDef floorDef{.friction = mu};
    if (chainFloor) {
        // Listed right to left: one-sided chain edges collide on the right of v1→v2, i.e. on top.
        Chain floor;
        for (float x = 30.0f; x >= -20.0f; x -= tileWidth) floor.vertices.push_back({x, 0.0f});
        world.createShape(ground, floorDef, floor);
    } else {
        for (float x = -20.0f; x < 30.0f; x += tileWidth) world.createShape(ground, floorDef, Segment{{x, 0.0f}, {x + tileWidth, 0.0f}});
    }
    const BodyId box = features::addDynamic(world, {-15.0f, 0.5f});
    world.createShape(box, {.friction = mu}, makeBox(0.5f, 0.5f));
    features::run(world, 30);  // settle
    world.setLinearVelocity(box, {v0, 0.0f});

    Slide s;
    const float startX = world.position(box).x;
    float previous = v0;
    for (int i = 0; i < 270; ++i) {  // 4.5 s; it stops after v0/(μ g) = 4 s
        world.step(dt);
        const Vec2 v = world.linearVelocity(box);
        s.maxVerticalSpeed = std::max(s.maxVerticalSpeed, std::fabs(v.y));
        s.maxAngularSpeed = std::max(s.maxAngularSpeed, std::fabs(world.angularVelocity(box)));
        if (v.x > 0.5f) {  // while sliding (at rest, static friction jitters at 1e-4 m/s)
            s.maxSpeedIncrease = std::max(s.maxSpeedIncrease, std::fabs(v.x) - previous);
            s.maxDecelerationError = std::max(s.maxDecelerationError, std::fabs((v.x - previous) / dt + mu * g));
        }
        previous = std::fabs(v.x);
    }
    s.distance = world.position(box).x - startX;
    return s;
}

TEST(FeaturesChain, BoxSlidesAcrossManyChainSegmentsWithoutSnagging) {
    const Slide s = slide(true);
    EXPECT_LT(s.maxVerticalSpeed, 0.01f);
    EXPECT_LT(s.maxAngularSpeed, 0.01f);
    EXPECT_LE(s.maxSpeedIncrease, 1e-4f);  // speed only ever decreases
    EXPECT_LT(s.maxDecelerationError, 0.05f * mu * g);  // Coulomb: dv/dt = −μ g throughout
    // v0²/(2 μ g) = 16 m, seams crossed every 0.5 m.
    EXPECT_NEAR(s.distance, v0 * v0 / (2.0f * mu * g), 0.3f);
}

TEST(FeaturesChain, SeparateSegmentsAreMeasuredForComparison) {
    // Two-sided segments each see the box's corner alone at a seam; Box2D 2.4's edge collision
    // may report the neighbouring segment's end as a face and bump the box. Record what happens.
    const Slide chain = slide(true), segments = slide(false);
    RecordProperty("segments_max_vy_mm_per_s", static_cast<int>(1000.0f * segments.maxVerticalSpeed));
    RecordProperty("segments_max_omega_mrad_per_s", static_cast<int>(1000.0f * segments.maxAngularSpeed));
    RecordProperty("segments_max_decel_error_mm_per_s2", static_cast<int>(1000.0f * segments.maxDecelerationError));
    RecordProperty("segments_distance_mm", static_cast<int>(1000.0f * segments.distance));
    std::printf("chain:    max|vy| %.4f  max|w| %.4f  decel err %.4f  distance %.3f\n", chain.maxVerticalSpeed,
                chain.maxAngularSpeed, chain.maxDecelerationError, chain.distance);
    std::printf("segments: max|vy| %.4f  max|w| %.4f  decel err %.4f  distance %.3f\n", segments.maxVerticalSpeed,
                segments.maxAngularSpeed, segments.maxDecelerationError, segments.distance);
    // The chain is never worse than the segments.
    EXPECT_LE(chain.maxVerticalSpeed, segments.maxVerticalSpeed + 1e-6f);
    EXPECT_LE(chain.maxAngularSpeed, segments.maxAngularSpeed + 1e-6f);
}

}  // namespace
}  // namespace perpdot
