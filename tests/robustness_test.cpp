// API misuse and numerical robustness: stale ids, destroying bodies in the middle of things,
// changing the world from inside step(), bodies that go non-finite, speed clamps, and a stack
// 10 km from the origin. Misuse must give perpdot::Error or defined behaviour, never UB
// (the ASan + UBSan build runs these too).
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "perpdot/error.hpp"
#include "perpdot/world.hpp"

namespace perpdot {
namespace {

constexpr float dt = 1.0f / 60.0f;

BodyId addBox(World& world, Vec2 position, BodyType type = BodyType::Dynamic, float hx = 0.5f, float hy = 0.5f) {
    const BodyId body = world.createBody({.type = type, .position = position});
    world.createShape(body, {}, makeBox(hx, hy));
    return body;
}

bool allFinite(const World& world) {
    for (BodyId b : world.bodies()) {
        const Vec2 p = world.position(b), v = world.linearVelocity(b);
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(world.angle(b)) || !std::isfinite(v.x) ||
            !std::isfinite(v.y) || !std::isfinite(world.angularVelocity(b)))
            return false;
    }
    return true;
}

TEST(ApiMisuse, StaleIdsAreErrorsEvenWhenTheSlotIsReused) {
    World world;
    const BodyId old = addBox(world, {0, 0});
    const ShapeId oldShape = world.shapes(old)[0];
    world.destroyBody(old);
    const BodyId reused = addBox(world, {1, 0});
    ASSERT_EQ(reused.index, old.index);  // the slot is reused with a new generation
    EXPECT_FALSE(world.isValid(old));
    EXPECT_FALSE(world.isValid(oldShape));
    EXPECT_THROW(world.position(old), Error);
    EXPECT_THROW(world.setLinearVelocity(old, {1, 0}), Error);
    EXPECT_THROW(world.applyForceToCenter(old, {1, 0}), Error);
    EXPECT_THROW(world.createShape(old, {}, Circle{}), Error);
    EXPECT_THROW(world.destroyBody(old), Error);
    EXPECT_THROW(world.friction(oldShape), Error);
    EXPECT_THROW(world.destroyShape(oldShape), Error);
    EXPECT_THROW(world.position(BodyId{}), Error);            // null id
    EXPECT_THROW(world.position(BodyId{12345, 0}), Error);    // never issued
    EXPECT_EQ(world.position(reused), (Vec2{1, 0}));           // the new body is untouched
}

TEST(ApiMisuse, DestroyingABodyInAStackLeavesAConsistentWorld) {
    World world;
    addBox(world, {0, -0.5f}, BodyType::Static, 10.0f, 0.5f);
    std::vector<BodyId> stack;
    for (int i = 0; i < 5; ++i) stack.push_back(addBox(world, {0, 0.5f + static_cast<float>(i)}));
    for (int i = 0; i < 120; ++i) world.step(dt);
    ASSERT_GE(world.contactCount(), 5);
    world.destroyBody(stack[2]);  // it has contacts above and below
    for (const ContactData& c : world.contacts()) {
        EXPECT_TRUE(world.isValid(c.shapeA));
        EXPECT_TRUE(world.isValid(c.shapeB));
    }
    EXPECT_TRUE(world.isAwake(stack[3]));  // losing its support woke the boxes above
    for (int i = 0; i < 120; ++i) world.step(dt);
    EXPECT_TRUE(allFinite(world));
    // The two boxes above fell one box height onto the lower part of the stack.
    const float gap = world.position(stack[1]).y - world.position(stack[0]).y;  // 1 m plus the skins
    EXPECT_NEAR(world.position(stack[3]).y, world.position(stack[1]).y + gap, 0.02f);
    EXPECT_NEAR(world.position(stack[4]).y, world.position(stack[1]).y + 2.0f * gap, 0.03f);
}

TEST(ApiMisuse, DestroyingABodyWithJointsAndContactsInvalidatesItsJoints) {
    World world;
    addBox(world, {0, -0.5f}, BodyType::Static, 10.0f, 0.5f);
    const BodyId a = addBox(world, {0, 0.5f}), b = addBox(world, {1.1f, 0.5f}), c = addBox(world, {2.2f, 0.5f});
    const JointId ab = world.createJoint(RevoluteJointDef{.bodyA = a, .bodyB = b, .localAnchorA = {0.55f, 0}, .localAnchorB = {-0.55f, 0}});
    const JointId bc = world.createJoint(RevoluteJointDef{.bodyA = b, .bodyB = c, .localAnchorA = {0.55f, 0}, .localAnchorB = {-0.55f, 0}});
    for (int i = 0; i < 30; ++i) world.step(dt);
    ASSERT_GE(world.contactCount(), 3);  // all three rest on the ground
    world.destroyBody(b);
    EXPECT_FALSE(world.isValid(ab));
    EXPECT_FALSE(world.isValid(bc));
    EXPECT_THROW(world.jointType(ab), Error);
    EXPECT_THROW(world.destroyJoint(bc), Error);
    EXPECT_TRUE(world.joints().empty());
    for (int i = 0; i < 60; ++i) world.step(dt);
    EXPECT_TRUE(allFinite(world));
    EXPECT_NEAR(world.position(a).y, world.position(c).y, 0.01f);  // both still resting
}

TEST(ApiMisuse, EveryMutationInsideStepIsRefused) {
    World world;
    const BodyId ground = world.createBody({.position = {0, -0.5f}});
    world.createShape(ground, {.enablePreSolveEvents = true}, makeBox(10.0f, 0.5f));
    const BodyId box = addBox(world, {0, 0.49f});
    const BodyId other = addBox(world, {5, 0.49f});
    const ShapeId shape = world.shapes(box)[0];
    std::vector<std::string> refused;
    int calls = 0;
    world.setPreSolve([&](ShapeId, ShapeId, const ContactData&) {
        ++calls;
        const auto attempt = [&](auto&& mutate) {
            try {
                mutate();
            } catch (const Error& e) {
                refused.push_back(e.what());
            }
        };
        attempt([&] { world.createBody({}); });
        attempt([&] { world.destroyBody(other); });
        attempt([&] { world.createShape(other, {}, Circle{}); });
        attempt([&] { world.destroyShape(shape); });
        attempt([&] { world.setTransform(other, {1, 1}, 0); });
        attempt([&] { world.setLinearVelocity(other, {1, 0}); });
        attempt([&] { world.setAngularVelocity(other, 1); });
        attempt([&] { world.setAwake(other, false); });
        attempt([&] { world.applyForceToCenter(other, {1, 0}); });
        attempt([&] { world.applyLinearImpulseToCenter(other, {1, 0}); });
        attempt([&] { world.applyTorque(other, 1); });
        attempt([&] { world.applyAngularImpulse(other, 1); });
        attempt([&] { world.setGravityScale(other, 2); });
        attempt([&] { world.setLinearDamping(other, 1); });
        attempt([&] { world.setAngularDamping(other, 1); });
        attempt([&] { world.setFriction(shape, 0.1f); });
        attempt([&] { world.setRestitution(shape, 0.1f); });
        attempt([&] { world.setDensity(shape, 2); });
        attempt([&] { world.setGravity({0, 0}); });
        attempt([&] { world.setSubsteps(2); });
        attempt([&] { world.restore(world.snapshot()); });
        attempt([&] { world.setPreSolve({}); });
        return true;
    });
    for (int i = 0; i < 5 && calls == 0; ++i) world.step(dt);
    ASSERT_GT(calls, 0);
    EXPECT_EQ(refused.size(), 22u * static_cast<size_t>(calls));
    for (const std::string& message : refused) EXPECT_NE(message.find("during step()"), std::string::npos) << message;
    world.setPreSolve({});
    for (int i = 0; i < 5; ++i) world.step(dt);  // and the world is unlocked afterwards
    EXPECT_NO_THROW(world.createBody({}));
    EXPECT_TRUE(allFinite(world));
}

TEST(ApiMisuse, InvalidDefinitionsAreRefused) {
    World world;
    const float nan = std::nanf("");
    const float inf = INFINITY;
    EXPECT_THROW(world.createBody({.position = {nan, 0}}), Error);
    EXPECT_THROW(world.createBody({.angle = inf}), Error);
    EXPECT_THROW(world.createBody({.linearDamping = -1}), Error);
    const BodyId body = world.createBody({.type = BodyType::Dynamic});
    EXPECT_THROW(world.createShape(body, {.density = -1}, Circle{}), Error);
    EXPECT_THROW(world.createShape(body, {.density = nan}, Circle{}), Error);
    EXPECT_THROW(world.createShape(body, {}, Circle{{0, 0}, 0}), Error);
    EXPECT_THROW(world.createShape(body, {}, Circle{{inf, 0}, 1}), Error);
    Polygon bowTie;
    bowTie.count = 4;
    bowTie.vertices = {Vec2{0, 0}, Vec2{1, 1}, Vec2{0, 1}, Vec2{1, 0}};
    EXPECT_THROW(world.createShape(body, {}, bowTie), Error);
    Polygon tooMany;
    tooMany.count = 9;  // more than the array holds: checked, not read past the end
    EXPECT_THROW(world.createShape(body, {}, tooMany), Error);
    EXPECT_THROW(world.createShape(body, {}, Segment{{0, 0}, {0, 0}}), Error);
    EXPECT_THROW(world.createShape(body, {}, Chain{{{0, 0}}, false}), Error);
    EXPECT_THROW(world.setLinearVelocity(body, {nan, 0}), Error);
    EXPECT_THROW(world.applyForceToCenter(body, {0, inf}), Error);
    EXPECT_THROW(world.setGravity({nan, 0}), Error);
    EXPECT_THROW(world.setSubsteps(0), Error);
    EXPECT_TRUE(world.shapes(body).empty());
    world.step(dt);
    EXPECT_THROW(world.step(-1.0f), Error);  // refused, like a NaN or infinite step
    EXPECT_THROW(world.step(nan), Error);
    EXPECT_TRUE(allFinite(world));
}

// A shape so dense that the body's mass overflows makes its state NaN on the next step: the body
// is frozen where it was, counted in stats(), and its neighbours never see the NaN.
TEST(Numerics, ABodyThatGoesNonFiniteIsFrozenAndReported) {
    World world;
    addBox(world, {0, -0.5f}, BodyType::Static, 10.0f, 0.5f);
    const BodyId healthy = addBox(world, {2, 0.5f});
    const BodyId doomed = world.createBody({.type = BodyType::Dynamic, .position = {0, 3}});
    world.createShape(doomed, {}, Circle{{0, 0}, 1.0f});
    // Each torque is finite; their sum overflows to infinity, and ω with it.
    world.applyTorque(doomed, 3.0e38f);
    world.applyTorque(doomed, 3.0e38f);
    EXPECT_EQ(world.stats().frozenBodies, 0);
    for (int i = 0; i < 60; ++i) world.step(dt);
    EXPECT_GE(world.stats().frozenBodies, 1);
    EXPECT_EQ(world.position(doomed), (Vec2{0, 3}));
    EXPECT_EQ(world.linearVelocity(doomed), (Vec2{0, 0}));
    EXPECT_TRUE(std::isfinite(world.position(healthy).y));
    EXPECT_NEAR(world.position(healthy).y, 0.5f, 0.02f);
}

TEST(Numerics, ShapesWhoseMassOverflowsOrThatAreSliversAreRefused) {
    World world;
    const BodyId body = world.createBody({.type = BodyType::Dynamic});
    // ρ = 3e38 on a 10 m disc: m = ρπr² is not a float.
    EXPECT_THROW(world.createShape(body, {.density = 3.0e38f}, Circle{{0, 0}, 10.0f}), Error);
    const ShapeId disc = world.createShape(body, {}, Circle{{0, 0}, 10.0f});
    EXPECT_THROW(world.setDensity(disc, 3.0e38f), Error);
    EXPECT_EQ(world.density(disc), 1.0f);
    // A 100 m sliver 1 mm thick: its apex is closer than the linear slop to its base line.
    const Vec2 sliver[3] = {{0, 0}, {100, 0}, {50, 0.001f}};
    EXPECT_THROW(makePolygon(sliver), Error);
}

TEST(Numerics, ShapeCoordinatesBeyondTheHugeLimitAreRefused) {
    // A fuzzed snapshot held a segment reaching 7e19 m, which made b2TimeOfImpact assert
    // (tests/fuzz/findings/ccd-toi-assert-huge-segment.bin): every shape must stay within ±1e5 m.
    World world;
    const BodyId ground = world.createBody({});
    const float huge = maxShapeCoordinate, beyond = 2.0f * maxShapeCoordinate;
    EXPECT_NO_THROW(world.createShape(ground, {}, Segment{{-huge, 0}, {huge, 0}}));
    EXPECT_THROW(world.createShape(ground, {}, Segment{{0, 0}, {0, beyond}}), Error);
    EXPECT_THROW(world.createShape(ground, {}, Chain{{{0, 0}, {1, 0}, {beyond, 1}}}), Error);
    EXPECT_THROW(world.createShape(ground, {}, Circle{{beyond, 0}, 1.0f}), Error);
    const Vec2 far[3] = {{beyond, 0}, {beyond + 1, 0}, {beyond, 1}};
    EXPECT_THROW(makePolygon(far), Error);
    // Radii too: a fuzzed snapshot held a 1e24 m circle, whose r² overflowed in continuous
    // collision and left NaN bodies unfrozen (tests/fuzz/findings/snapshot/huge-radius-nan.bin).
    const BodyId disc = world.createBody({.type = BodyType::Dynamic});
    EXPECT_NO_THROW(world.createShape(disc, {.density = 0.0f}, Circle{{0, 0}, huge}));
    EXPECT_THROW(world.createShape(disc, {.density = 0.0f}, Circle{{0, 0}, beyond}), Error);
    EXPECT_THROW(world.createShape(disc, {.density = 0.0f}, Capsule{{0, 0}, {1, 0}, beyond}), Error);
    const Vec2 triangle[3] = {{0, 0}, {1, 0}, {0, 1}};
    EXPECT_NO_THROW(makePolygon(triangle, huge));
    EXPECT_THROW(makePolygon(triangle, beyond), Error);
}

TEST(Numerics, BadWorldSettingsAreRefusedByName) {
    // Each setting names itself in the error; NaN, infinite and negative values are refused.
    const auto refuses = [](const WorldDef& def, const std::string& name) {
        try {
            World world(def);
            ADD_FAILURE() << name << " was accepted";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("WorldDef." + name), std::string::npos) << e.what();
        }
    };
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    refuses({.contactHertz = -1.0f}, "contactHertz");
    refuses({.contactDampingRatio = nan}, "contactDampingRatio");
    refuses({.jointHertz = inf}, "jointHertz");
    refuses({.jointDampingRatio = -0.5f}, "jointDampingRatio");
    refuses({.contactPushMaxVelocity = -3.0f}, "contactPushMaxVelocity");
    refuses({.restitutionThreshold = nan}, "restitutionThreshold");
    refuses({.maxLinearSpeed = 0.0f}, "maxLinearSpeed");
    refuses({.hitEventThreshold = -1.0f}, "hitEventThreshold");
    refuses({.contactReuseDistance = -0.05f}, "contactReuseDistance");
    refuses({.substeps = 0}, "substeps");
    // The edges are allowed: rigid rows (0 Hz), no threshold, no reuse.
    EXPECT_NO_THROW(World(WorldDef{.contactHertz = 0.0f, .jointHertz = 0.0f, .restitutionThreshold = 0.0f, .contactReuseDistance = 0.0f}));
}

TEST(Numerics, LinearSpeedIsClampedToTheWorldLimit) {
    World world({.gravity = {0, 0}, .maxLinearSpeed = 100.0f});
    const BodyId fast = world.createBody({.type = BodyType::Dynamic, .linearVelocity = {300, 400}});
    world.createShape(fast, {}, Circle{});
    const BodyId huge = world.createBody({.type = BodyType::Dynamic, .position = {0, 10}, .linearVelocity = {-3e20f, 0}});
    world.createShape(huge, {}, Circle{});
    world.step(dt);
    // Clamped along its own direction (3, 4)/5, however large the speed, even when its square overflows.
    EXPECT_NEAR(world.linearVelocity(fast).x, 60.0f, 1e-3f);
    EXPECT_NEAR(world.linearVelocity(fast).y, 80.0f, 1e-3f);
    EXPECT_NEAR(world.linearVelocity(huge).x, -100.0f, 1e-3f);
    EXPECT_NEAR(world.position(fast).x, 60.0f * dt, 1e-3f);
}

TEST(Numerics, BouncesStayWithinTheSpeedLimits) {
    // Restitution runs after the substeps' clamp: a spinning plank's tip bounces at ω r, which
    // could hand the body more than the limit (a fuzzed snapshot reached 2e16 m/s this way).
    World world({.maxLinearSpeed = 5.0f});
    const BodyId ground = world.createBody({});
    world.createShape(ground, {}, Segment{{-50, 0}, {50, 0}});
    const BodyId plank = world.createBody({.type = BodyType::Dynamic, .position = {0, 6}, .angle = 0.3f,
                                           .linearVelocity = {0, -4}, .angularVelocity = 20.0f});
    world.createShape(plank, {.restitution = 1.0f}, makeBox(5.0f, 0.1f));
    float fastest = 0.0f;
    for (int i = 0; i < 120; ++i) {
        world.step(dt);
        fastest = std::max(fastest, length(world.linearVelocity(plank)));
        ASSERT_LE(length(world.linearVelocity(plank)), 5.0f * (1.0f + 1e-5f)) << "step " << i;
    }
    EXPECT_GT(fastest, 4.9f);  // it did reach the limit
}

TEST(Numerics, AnImpactWhoseImpulseOverflowsFreezesItsPairInsteadOfSpreadingNaN) {
    // A bullet meets a kinematic box inside continuous collision's moving impacts; a restitution
    // near FLT_MAX makes the target speed, then the impulse, infinite, and the kinematic body's
    // 0·∞ NaN (a fuzzed snapshot did this, and its world could no longer be saved and restored).
    World world({.gravity = {0, 0}});
    const BodyId wall = world.createBody({.type = BodyType::Kinematic});
    world.createShape(wall, {}, makeBox(1.0f, 1.0f));
    const BodyId bullet = world.createBody({.type = BodyType::Dynamic, .position = {-6, 0}, .linearVelocity = {600, 0}, .bullet = true});
    world.createShape(bullet, {.restitution = 3.0e38f}, Circle{{0, 0}, 0.1f});
    for (int i = 0; i < 3; ++i) world.step(dt);
    for (BodyId b : {wall, bullet}) {
        EXPECT_TRUE(isFinite(world.position(b)) && std::isfinite(world.angle(b)) && isFinite(world.linearVelocity(b)));
        EXPECT_FALSE(world.isAwake(b));
    }
    EXPECT_EQ(world.stats().frozenBodies, 2);
    EXPECT_LT(world.position(bullet).x, -0.9f);  // stopped where it met the box, not through it
    World restored;
    restored.restore(world.snapshot());  // a world's own snapshot always loads back
    EXPECT_EQ(restored.snapshot(), world.snapshot());
}

TEST(Numerics, AngularSpeedIsClampedToAnEighthOfATurnPerSubstep) {
    World world({.gravity = {0, 0}, .substeps = 4});
    const BodyId spinner = world.createBody({.type = BodyType::Dynamic, .angularVelocity = 1.0e4f});
    world.createShape(spinner, {}, makeBox(1.0f, 0.2f));
    world.step(dt);
    const float maxOmega = 0.25f * pi * 4.0f / dt;  // π/4 per substep
    EXPECT_NEAR(world.angularVelocity(spinner), maxOmega, 1e-2f);
    EXPECT_NEAR(world.angle(spinner), pi, 1e-3f);
}

// The solver works on position deltas, so a stack far from the origin settles like the same stack
// at the origin: float spacing at 10 km is ~1 mm, below the 5 mm linear slop.
std::vector<Vec2> settledStackOffsets(Vec2 origin) {
    World world;
    addBox(world, origin + Vec2{0, -0.5f}, BodyType::Static, 20.0f, 0.5f);
    std::vector<BodyId> stack;
    for (int i = 0; i < 10; ++i) stack.push_back(addBox(world, origin + Vec2{0, 0.5f + 1.0f * static_cast<float>(i)}));
    for (int i = 0; i < 300; ++i) world.step(dt);
    std::vector<Vec2> offsets;
    for (BodyId b : stack) {
        offsets.push_back(world.position(b) - origin);
        EXPECT_NEAR(world.angle(b), 0.0f, 0.01f);
        EXPECT_LT(length(world.linearVelocity(b)), 0.05f);
    }
    return offsets;
}

TEST(Numerics, AStack10KmFromTheOriginStaysStanding) {
    const std::vector<Vec2> home = settledStackOffsets({0, 0});
    for (int i = 0; i < 10; ++i) {
        // Standing: leaning less than 5 cm, each 1 m box resting on the one below (skins of ~1 cm).
        EXPECT_NEAR(home[i].x, 0.0f, 0.05f);
        EXPECT_GT(home[i].y, 0.5f + 0.99f * static_cast<float>(i));
        EXPECT_LT(home[i].y, 0.5f + 1.03f * static_cast<float>(i) + 0.02f);
    }
    for (const Vec2 origin : {Vec2{10000, 0}, Vec2{-7071, 7071}, Vec2{0, -10000}}) {
        const std::vector<Vec2> far = settledStackOffsets(origin);
        for (int i = 0; i < 10; ++i) {
            EXPECT_NEAR(far[i].x, home[i].x, 0.05f) << "origin " << origin.x << "," << origin.y << " box " << i;
            EXPECT_NEAR(far[i].y, home[i].y, 0.02f) << "origin " << origin.x << "," << origin.y << " box " << i;
        }
    }
}

}  // namespace
}  // namespace perpdot
