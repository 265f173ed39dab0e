// World::explode against the closed form of ExplosionDef: J = impulse·(1 − d/radius) at the
// shape's surface point nearest the centre, away from the centre; nothing beyond the radius or
// behind static geometry when blocking is on; an off-centre point spins the body by perpDot(r, J).
#include <gtest/gtest.h>

#include <cmath>

#include "perpdot/error.hpp"
#include "perpdot/world.hpp"
#include "physics_scenes.hpp"

namespace perpdot {
namespace {

WorldDef weightless() {
    WorldDef def;
    def.gravity = {0.0f, 0.0f};
    return def;
}

// A disc whose surface is d = 3 − 0.5 = 2.5 m from the centre takes 10·(1 − 2.5/5) = 5 N·s
// straight away from it, and no spin (its lever arm is along J).
TEST(Explosion, GivesAClosedFormImpulseWithLinearFalloff) {
    World world(weightless());
    const BodyId disc = test::addDisc(world, {3.0f, 0.0f}, 0.5f);
    const int pushed = world.explode({.position = {0.0f, 0.0f}, .radius = 5.0f, .impulse = 10.0f});
    EXPECT_EQ(pushed, 1);
    const float m = world.mass(disc);
    EXPECT_NEAR(m * world.linearVelocity(disc).x, 5.0f, 5e-5f);
    EXPECT_NEAR(world.linearVelocity(disc).y, 0.0f, 1e-6f);
    EXPECT_NEAR(world.angularVelocity(disc), 0.0f, 1e-6f);
    EXPECT_TRUE(world.isAwake(disc));
}

TEST(Explosion, ReachesNothingBeyondItsRadius) {
    World world(weightless());
    const BodyId far = test::addBox(world, {6.0f, 0.0f}, 0.5f, 0.5f);  // surface 5.5 m away
    const BodyId near = test::addBox(world, {-4.0f, 0.0f}, 0.5f, 0.5f);  // 3.5 m
    EXPECT_EQ(world.explode({.position = {0.0f, 0.0f}, .radius = 5.0f, .impulse = 10.0f}), 1);
    EXPECT_EQ(world.linearVelocity(far), (Vec2{0.0f, 0.0f}));
    EXPECT_LT(world.linearVelocity(near).x, 0.0f);  // pushed away, to the left
}

// A wall between the centre and a box: with blocking the box takes nothing, without it the same
// impulse as in the open.
TEST(Explosion, StaticGeometryBlocksItWhenAsked) {
    for (const bool blocked : {true, false}) {
        World world(weightless());
        const BodyId wall = world.createBody(test::bodyAt({1.5f, 0.0f}, BodyType::Static));
        world.createShape(wall, {}, makeBox(0.1f, 2.0f));
        const BodyId box = test::addBox(world, {3.0f, 0.0f}, 0.5f, 0.5f);
        world.explode({.position = {0.0f, 0.0f}, .radius = 5.0f, .impulse = 10.0f, .blockedByStatic = blocked});
        if (blocked) {
            EXPECT_EQ(world.linearVelocity(box), (Vec2{0.0f, 0.0f}));
        } else {
            EXPECT_NEAR(world.mass(box) * world.linearVelocity(box).x, 10.0f * (1.0f - 2.5f / 5.0f), 5e-5f);
        }
    }
}

// Centre below and to the left of a box's corner: J acts at the corner, off the line through the
// centre of mass, so the box spins by perpDot(p − c, J)/I, and the linear momentum is J.
TEST(Explosion, AnOffCentreHitSpinsTheBody) {
    World world(weightless());
    const BodyId box = test::addBox(world, {2.0f, 2.0f}, 0.5f, 0.5f);
    const Vec2 centre{0.5f, 1.0f};
    const Vec2 corner{1.5f, 1.5f};  // the box's nearest point to the centre
    EXPECT_EQ(world.explode({.position = centre, .radius = 4.0f, .impulse = 8.0f}), 1);
    const float d = length(corner - centre);
    const Vec2 J = 8.0f * (1.0f - d / 4.0f) * normalize(corner - centre);
    const Vec2 p = world.mass(box) * world.linearVelocity(box);
    EXPECT_NEAR(p.x, J.x, 1e-4f);
    EXPECT_NEAR(p.y, J.y, 1e-4f);
    const float L = world.rotationalInertia(box) * world.angularVelocity(box);
    EXPECT_NEAR(L, perpDot(corner - world.worldCenter(box), J), 1e-4f);
    EXPECT_NE(L, 0.0f);
}

TEST(Explosion, LeavesStaticKinematicSensorAndFilteredShapesAlone) {
    World world(weightless());
    const BodyId kinematic = world.createBody(test::bodyAt({1.0f, 0.0f}, BodyType::Kinematic));
    world.createShape(kinematic, {}, makeBox(0.5f, 0.5f));
    ShapeDef sensor;
    sensor.sensor = true;
    const BodyId sensing = world.createBody(test::bodyAt({-1.0f, 0.0f}));
    world.createShape(sensing, sensor, Circle{{}, 0.5f});
    ShapeDef other;
    other.filter.category = 0x2;
    const BodyId filtered = test::addBox(world, {0.0f, 2.0f}, 0.5f, 0.5f, other);
    Filter onlyFirst;
    onlyFirst.mask = 0x1;
    EXPECT_EQ(world.explode({.position = {0.0f, 0.0f}, .radius = 5.0f, .impulse = 10.0f, .filter = onlyFirst}), 0);
    EXPECT_EQ(world.linearVelocity(filtered), (Vec2{0.0f, 0.0f}));
    EXPECT_EQ(world.linearVelocity(sensing), (Vec2{0.0f, 0.0f}));
    EXPECT_EQ(world.linearVelocity(kinematic), (Vec2{0.0f, 0.0f}));
}

TEST(Explosion, RefusesBadDefinitions) {
    World world;
    const float nan = std::nanf("");
    EXPECT_THROW(world.explode({.position = {nan, 0.0f}}), Error);
    EXPECT_THROW(world.explode({.radius = 0.0f}), Error);
    EXPECT_THROW(world.explode({.radius = INFINITY}), Error);
    EXPECT_THROW(world.explode({.impulse = -1.0f}), Error);
    EXPECT_THROW(world.explode({.impulse = nan}), Error);
}

}  // namespace
}  // namespace perpdot
