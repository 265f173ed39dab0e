// Continuous collision between moving bodies: bullets against bullets and against fast dynamic
// bodies, over a matrix of sizes (0.02-1 m), closing speeds (up to 1,000 m/s), shapes (circles,
// boxes) and approach angles. Each pair must collide (its velocities change), keep its momentum,
// never end a step overlapping deeper than a small tolerance, and never pass through.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "perpdot/world.hpp"

namespace perpdot {
namespace {

constexpr float dt = 1.0f / 60.0f;

enum class Kind { Circle, Box };

struct Piece {
    Kind kind = Kind::Circle;
    float size = 0.05f;  // diameter or side, metres
    BodyId id{};
};

// Penetration depth of two convex outlines (separating axes over both outlines' edge normals);
// negative or zero when they are apart.
float polygonDepth(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
    float depth = 1e9f;
    for (const std::vector<Vec2>* poly : {&a, &b})
        for (size_t i = 0; i < poly->size(); ++i) {
            const Vec2 e = (*poly)[(i + 1) % poly->size()] - (*poly)[i];
            const Vec2 axis = normalize(Vec2{e.y, -e.x});
            float minA = 1e9f, maxA = -1e9f, minB = 1e9f, maxB = -1e9f;
            for (Vec2 p : a) minA = std::min(minA, dot(p, axis)), maxA = std::max(maxA, dot(p, axis));
            for (Vec2 p : b) minB = std::min(minB, dot(p, axis)), maxB = std::max(maxB, dot(p, axis));
            depth = std::min(depth, std::min(maxA - minB, maxB - minA));
        }
    return depth;
}

// Depth of a circle (centre c, radius r) in a convex outline: r minus the signed distance from
// c to the outline (negative inside).
float circleDepth(Vec2 c, float r, const std::vector<Vec2>& poly) {
    float inside = -1e9f;  // largest signed distance to an edge line: < 0 when c is inside
    float outside = 1e9f;  // distance to the nearest edge segment
    for (size_t i = 0; i < poly.size(); ++i) {
        const Vec2 p = poly[i], e = poly[(i + 1) % poly.size()] - p;
        const Vec2 n = normalize(Vec2{e.y, -e.x});  // counter-clockwise outline: outward normal
        inside = std::max(inside, dot(c - p, n));
        const float t = std::clamp(dot(c - p, e) / dot(e, e), 0.0f, 1.0f);
        outside = std::min(outside, distance(c, p + t * e));
    }
    return r - (inside > 0.0f ? outside : inside);
}

std::vector<Vec2> outline(const World& world, const Piece& p) {
    const Transform xf = world.transform(p.id);
    const float h = 0.5f * p.size;
    std::vector<Vec2> corners;
    for (Vec2 c : {Vec2{-h, -h}, Vec2{h, -h}, Vec2{h, h}, Vec2{-h, h}}) corners.push_back(transformPoint(xf, c));
    return corners;
}

float depth(const World& world, const Piece& a, const Piece& b) {
    if (a.kind == Kind::Circle && b.kind == Kind::Circle)
        return 0.5f * (a.size + b.size) - distance(world.position(a.id), world.position(b.id));
    if (a.kind == Kind::Circle) return circleDepth(world.position(a.id), 0.5f * a.size, outline(world, b));
    if (b.kind == Kind::Circle) return circleDepth(world.position(b.id), 0.5f * b.size, outline(world, a));
    return polygonDepth(outline(world, a), outline(world, b));
}

BodyId addPiece(World& world, Piece& p, Vec2 position, Vec2 velocity, bool bullet) {
    p.id = world.createBody({.type = BodyType::Dynamic, .position = position, .linearVelocity = velocity, .bullet = bullet});
    if (p.kind == Kind::Circle) world.createShape(p.id, {}, Circle{.radius = 0.5f * p.size});
    else world.createShape(p.id, {}, makeBox(0.5f * p.size, 0.5f * p.size));
    return p.id;
}

struct Case {
    Kind kindA, kindB;
    float sizeA, sizeB;
    float closingSpeed;    // m/s
    float angle;           // between the paths: 0 head-on
    float offset;          // of B's path sideways, in units of the smaller size
    bool bulletB = true;   // B a bullet too, or a fast ordinary dynamic body
};

std::string describe(const Case& c) {
    const auto kind = [](Kind k) { return k == Kind::Circle ? "circle" : "box"; };
    return std::string(kind(c.kindA)) + " " + std::to_string(c.sizeA) + " m vs " + (c.bulletB ? "bullet " : "dynamic ") +
           kind(c.kindB) + " " + std::to_string(c.sizeB) + " m at " + std::to_string(c.closingSpeed) + " m/s, angle " +
           std::to_string(c.angle) + ", offset " + std::to_string(c.offset);
}

struct Outcome {
    bool collided = false;     // the relative velocity changed
    bool separated = false;    // and stopped approaching (along the line of centres at impact)
    float momentumError = 0;   // |Σ m v - p0| / (|m_A v_A| + |m_B v_B|), worst over the steps
    float impactDepth = 0;     // penetration at the end of the step of the impact, metres
    float laterDepth = 0;      // worst penetration at the end of a later step (the contact's work)
    bool swappedSides = false; // B's centre crossed to A's side of the line through A normal to the approach
};

// A moves along +x at speed s; B comes from the other side along a path turned by `angle` from
// head-on (and shifted sideways), so that the closing speed is c.closingSpeed. Both would reach
// the origin 2.37 steps after the start: the impact falls inside a step.
Outcome collide(const Case& c) {
    World world({.gravity = {0.0f, 0.0f}});
    const float s = c.closingSpeed / (2.0f * std::cos(0.5f * c.angle));
    const Vec2 vA{s, 0.0f}, vB{-s * std::cos(c.angle), s * std::sin(c.angle)};
    const float meet = 2.37f * dt;
    const Vec2 side{std::sin(c.angle), std::cos(c.angle)};  // normal to B's path
    Piece a{c.kindA, c.sizeA}, b{c.kindB, c.sizeB};
    addPiece(world, a, -meet * vA, vA, true);
    addPiece(world, b, -meet * vB + (c.offset * std::min(c.sizeA, c.sizeB)) * side, vB, c.bulletB);
    const float mA = world.mass(a.id), mB = world.mass(b.id);
    const Vec2 p0 = mA * vA + mB * vB;
    const float scale = mA * s + mB * s;
    const Vec2 approach = normalize(vB - vA);  // B's velocity relative to A, before the impact
    const float side0 = dot(world.position(b.id) - world.position(a.id), approach);
    Outcome out;
    for (int i = 0; i < 8; ++i) {
        world.step(dt);
        const Vec2 va = world.linearVelocity(a.id), vb = world.linearVelocity(b.id);
        out.momentumError = std::max(out.momentumError, length(mA * va + mB * vb - p0) / scale);
        const float relative = dot(vb - va, approach);  // c.closingSpeed before the impact
        const float d = depth(world, a, b);
        if (out.collided) out.laterDepth = std::max(out.laterDepth, d);
        if (!out.collided && relative < 0.99f * c.closingSpeed) out.collided = true, out.impactDepth = d;
        out.separated = relative <= 0.01f * c.closingSpeed;
        // Head-on, B stays on its own side of A.
        if (c.offset == 0.0f && c.angle == 0.0f && dot(world.position(b.id) - world.position(a.id), approach) * side0 < 0.0f)
            out.swappedSides = true;
    }
    return out;
}

TEST(FeaturesContinuousMoving, BulletsOfEverySizeAndSpeedCollideInsteadOfPassing) {
    const float sizes[] = {0.02f, 0.05f, 0.2f, 1.0f};
    const float speeds[] = {100.0f, 400.0f, 1000.0f};
    const float angles[] = {0.0f, 0.5f, 1.2f};  // radians between the paths
    int cases = 0;
    for (Kind kindA : {Kind::Circle, Kind::Box})
        for (Kind kindB : {Kind::Circle, Kind::Box})
            for (float sizeA : sizes)
                for (float sizeB : {0.02f, 1.0f, sizeA})
                    for (float speed : speeds)
                        for (float angle : angles)
                            for (float offset : {0.0f, 0.3f})
                                for (bool bulletB : {true, false}) {
                                    const Case c{kindA, kindB, sizeA, sizeB, speed, angle, offset, bulletB};
                                    const Outcome o = collide(c);
                                    ++cases;
                                    EXPECT_TRUE(o.collided) << describe(c);
                                    // Paths through one point meet centre to centre: for two circles, or for
                                    // anything head-on, the normal is the approach (boxes at an angle meet
                                    // face first and may slide on).
                                    const bool circles = kindA == Kind::Circle && kindB == Kind::Circle;
                                    if (offset == 0.0f && (angle == 0.0f || circles)) {
                                        EXPECT_TRUE(o.separated) << describe(c);
                                    }
                                    EXPECT_LT(o.momentumError, 1e-5f) << describe(c);
                                    // Within Box2D's linear slop right after the impact; later the contact holds
                                    // them (a spinning box may press a corner in), never a quarter of the smaller.
                                    EXPECT_LT(o.impactDepth, 0.005f) << describe(c) << ": " << o.impactDepth << " m deep";
                                    EXPECT_LT(o.laterDepth, 0.25f * std::min(sizeA, sizeB)) << describe(c) << ": " << o.laterDepth << " m deep";
                                    EXPECT_FALSE(o.swappedSides) << describe(c);
                                }
    EXPECT_EQ(cases, 2 * 2 * 4 * 3 * 3 * 3 * 2 * 2);
}

TEST(FeaturesContinuousMoving, WithoutContinuousCollisionTwoBulletsPassThroughEachOther) {
    // The counterfactual of the matrix: the two 0.05 m bullets at 400 m/s, sweeping off.
    World world({.gravity = {0.0f, 0.0f}, .enableContinuous = false});
    Piece a{Kind::Circle, 0.05f}, b{Kind::Circle, 0.05f};
    addPiece(world, a, {-1.0f, 0.0f}, {200.0f, 0.0f}, true);
    addPiece(world, b, {1.0f, 0.0f}, {-200.0f, 0.0f}, true);
    for (int i = 0; i < 10; ++i) world.step(dt);
    EXPECT_EQ(world.linearVelocity(a.id).x, 200.0f);  // untouched
    EXPECT_GT(world.position(a.id).x, world.position(b.id).x);
}

TEST(FeaturesContinuousMoving, AFastBodyHitsABulletAtRest) {
    // The bullet need not be the fast one: a 0.2 m box at 600 m/s (not a bullet) meets a 0.05 m
    // bullet standing in its path. Equal masses, e = 1: the box stops and the bullet takes its
    // velocity (Hecker's impulse head-on: v'A = 0, v'B = vA).
    World world({.gravity = {0.0f, 0.0f}});
    const BodyId box = world.createBody({.type = BodyType::Dynamic, .position = {-3.0f, 0.0f}, .linearVelocity = {600.0f, 0.0f}});
    world.createShape(box, {.density = 1.0f, .restitution = 1.0f}, makeBox(0.1f, 0.1f));
    const BodyId bullet = world.createBody({.type = BodyType::Dynamic, .bullet = true});
    world.createShape(bullet, {.density = 0.04f / (0.025f * 0.025f * pi), .restitution = 1.0f}, Circle{.radius = 0.025f});
    ASSERT_NEAR(world.mass(box), world.mass(bullet), 1e-5f);
    for (int i = 0; i < 3; ++i) world.step(dt);
    EXPECT_NEAR(world.linearVelocity(box).x, 0.0f, 0.5f);
    EXPECT_NEAR(world.linearVelocity(bullet).x, 600.0f, 0.5f);
    EXPECT_GT(world.position(bullet).x, world.position(box).x + 0.125f);
}

// Sixteen 0.04 m bullets on a ring of radius 2 fired at 500 m/s through its centre: they meet
// there within one step, bounce (e = 1) from each other many times, and fly out again.
World ringOfBullets(std::vector<BodyId>& ids) {
    World world({.gravity = {0.0f, 0.0f}});
    for (int k = 0; k < 16; ++k) {
        const float a = 2.0f * pi * static_cast<float>(k) / 16.0f;
        const Vec2 u{std::cos(a), std::sin(a)};
        ids.push_back(world.createBody({.type = BodyType::Dynamic, .position = 2.0f * u, .linearVelocity = -500.0f * u, .bullet = true}));
        world.createShape(ids.back(), {.restitution = 1.0f}, Circle{.radius = 0.02f});
    }
    return world;
}

TEST(FeaturesContinuousMoving, ARingOfBulletsCollidesInTheCentreAndIsDeterministic) {
    std::vector<BodyId> first, second;
    World a = ringOfBullets(first), b = ringOfBullets(second);
    float worstOverlap = 0.0f;
    for (int step = 0; step < 30; ++step) {
        a.step(dt);
        b.step(dt);
        for (size_t i = 0; i < first.size(); ++i)
            for (size_t j = i + 1; j < first.size(); ++j)
                worstOverlap = std::max(worstOverlap, 0.04f - distance(a.position(first[i]), a.position(first[j])));
    }
    Vec2 momentum{};
    for (size_t i = 0; i < first.size(); ++i) {
        EXPECT_EQ(a.position(first[i]), b.position(second[i]));  // bit for bit
        EXPECT_EQ(a.linearVelocity(first[i]), b.linearVelocity(second[i]));
        momentum += a.mass(first[i]) * a.linearVelocity(first[i]);
        // Every one was hit: none still flies its first path at its first speed.
        const float a0 = 2.0f * pi * static_cast<float>(i) / 16.0f;
        EXPECT_GT(distance(a.linearVelocity(first[i]), -500.0f * Vec2{std::cos(a0), std::sin(a0)}), 1.0f) << i;
    }
    EXPECT_LT(worstOverlap, 0.005f);
    EXPECT_LT(length(momentum), 1e-5f * a.mass(first[0]) * 500.0f * 16.0f);
}

}  // namespace
}  // namespace perpdot
