// The runtime API a ported Box2D game leans on: step semantics (step(0), bad time steps, step from
// a callback), handles that carry their World, bodies and shapes changed between steps, and the
// game's own collision rule. Each test checks what the change does to the motion or the contacts.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "perpdot/error.hpp"
#include "perpdot/scene.hpp"
#include "perpdot/state_hash.hpp"
#include "perpdot/world.hpp"
#include "physics_scenes.hpp"

namespace perpdot {
namespace {

using test::addBox;
using test::addGround;
using test::bodyAt;
using test::dt;
using test::run;

// The message of the perpdot::Error that f() throws ("" and a test failure if none).
template <class F>
std::string errorOf(F&& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    ADD_FAILURE() << "no perpdot::Error";
    return "";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// How far a body falls from rest in n steps of h under g, integrated as the step does (v first):
// Σ g h·k h for k = 1..n = g h² n(n + 1)/2.
float fallIn(int n, float h = dt, float g = 10.0f) { return g * h * h * static_cast<float>(n * (n + 1)) / 2.0f; }

// A 1 m box (1 kg) lying on the ground at rest: its centre at y = 0.5.
struct Resting {
    World world;
    BodyId ground = addGround(world);
    BodyId box = addBox(world, {0.0f, 0.5f}, 0.5f, 0.5f);
    ShapeId groundShape = world.shapes(ground).front();
    ShapeId boxShape = world.shapes(box).front();
};

// --- step semantics ---

TEST(RuntimeStep, StepZeroUpdatesContactsAndEventsWithoutMovingAnything) {
    Resting s;
    const Vec2 p = s.world.position(s.box);
    const uint64_t before = stateHash(s.world);
    s.world.step(0.0f);  // the pair is found and collided: a begin event, no motion
    EXPECT_EQ(stateHash(s.world), before);
    ASSERT_EQ(s.world.contactEvents().beginEvents.size(), 1u);
    EXPECT_EQ(s.world.contactCount(), 1);
    s.world.step(0.0f);  // nothing new: the last call's events are gone
    EXPECT_TRUE(s.world.contactEvents().beginEvents.empty());
    EXPECT_EQ(s.world.contactCount(), 1);

    // Moved away, the next step(0) ends the contact; the body stays where it was put.
    s.world.setTransform(s.box, {0.0f, 5.0f}, 0.0f);
    s.world.step(0.0f);
    EXPECT_EQ(s.world.contactEvents().endEvents.size(), 1u);
    EXPECT_EQ(s.world.contactCount(), 0);
    EXPECT_EQ(s.world.position(s.box).y, 5.0f);
    EXPECT_EQ(s.world.position(s.box).x, p.x);
    EXPECT_EQ(s.world.linearVelocity(s.box).y, 0.0f);
}

TEST(RuntimeStep, StepZeroClearsTheLastStepsEvents) {
    Resting s;
    s.world.step(dt);
    ASSERT_EQ(s.world.contactEvents().beginEvents.size(), 1u);
    s.world.step(0.0f);  // a paused game: the begin event is not seen twice
    EXPECT_TRUE(s.world.contactEvents().beginEvents.empty());
}

TEST(RuntimeStep, NegativeNaNAndInfiniteTimeStepsAreErrorsThatChangeNothing) {
    Resting s;
    run(s.world, 10);
    const uint64_t before = stateHash(s.world);
    const float bad[] = {-1.0f, std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()};
    const char* shown[] = {"-1", "nan", "inf"};
    for (int i = 0; i < 3; ++i) {
        const std::string message = errorOf([&] { s.world.step(bad[i]); });
        EXPECT_TRUE(contains(message, "World::step")) << message;
        EXPECT_TRUE(contains(message, shown[i])) << message;
    }
    EXPECT_EQ(stateHash(s.world), before);
    s.world.step(dt);  // still usable
}

TEST(RuntimeStep, StepFromAPreSolveCallbackIsAnError) {
    Resting s;
    s.world.enablePreSolveEvents(s.boxShape, true);
    int calls = 0;
    s.world.setPreSolve([&](ShapeId, ShapeId, const ContactData&) {
        ++calls;
        s.world.step(dt);
        return true;
    });
    const std::string message = errorOf([&] { s.world.step(dt); });
    EXPECT_EQ(calls, 1);
    EXPECT_TRUE(contains(message, "World::step: called during step()")) << message;
    s.world.setPreSolve({});
    s.world.step(dt);  // the world stays usable
    EXPECT_NEAR(s.world.position(s.box).y, 0.5f, 0.01f);
}

// --- handles carry their World ---

TEST(RuntimeHandles, AHandleFromAnotherWorldIsRefusedByName) {
    World a, b;
    const BodyId bodyA = addBox(a, {0.0f, 1.0f}, 0.5f, 0.5f);
    const BodyId bodyB = addBox(b, {0.0f, 1.0f}, 0.5f, 0.5f);
    ASSERT_EQ(bodyA.index, bodyB.index);
    ASSERT_EQ(bodyA.generation, bodyB.generation);
    EXPECT_NE(bodyA, bodyB);
    EXPECT_FALSE(b.isValid(bodyA));
    EXPECT_FALSE(b.isValid(a.shapes(bodyA).front()));
    EXPECT_EQ(errorOf([&] { b.setTransform(bodyA, {}, 0.0f); }),
              "World::setTransform: BodyId {index 0, generation 0} from another World");
    EXPECT_EQ(errorOf([&] { b.friction(a.shapes(bodyA).front()); }),
              "World::friction: ShapeId {index 0, generation 0} from another World");
    const BodyId anchorA = addBox(a, {2.0f, 1.0f}, 0.5f, 0.5f);
    const JointId joint = a.createJoint(RevoluteJointDef{.bodyA = bodyA, .bodyB = anchorA});
    EXPECT_FALSE(b.isValid(joint));
    EXPECT_TRUE(contains(errorOf([&] { b.destroyJoint(joint); }), "World::destroyJoint: JointId {index 0, generation 0} from another World"));
    EXPECT_TRUE(contains(errorOf([&] { b.createJoint(RevoluteJointDef{.bodyA = bodyA, .bodyB = bodyB}); }), "from another World"));
}

TEST(RuntimeHandles, StaleAndNullHandlesNameTheCall) {
    World world;
    const BodyId body = addBox(world, {0.0f, 1.0f}, 0.5f, 0.5f);
    world.destroyBody(body);
    EXPECT_EQ(errorOf([&] { world.setTransform(body, {}, 0.0f); }), "World::setTransform: stale BodyId {index 0, generation 0}");
    EXPECT_EQ(errorOf([&] { world.position(BodyId{}); }), "World::position: null BodyId {index -1, generation 0}");
}

TEST(RuntimeHandles, MovesAndRestoresKeepTheWorldsIdentity) {
    World a;
    const BodyId box = addBox(a, {0.0f, 1.0f}, 0.5f, 0.5f);
    const ShapeId shape = a.shapes(box).front();
    const std::vector<uint8_t> bytes = a.snapshot();
    a.destroyBody(box);
    EXPECT_FALSE(a.isValid(box));
    a.restore(bytes);  // the handles valid at the snapshot are valid again
    EXPECT_TRUE(a.isValid(box));
    EXPECT_TRUE(a.isValid(shape));
    EXPECT_EQ(a.shapeBody(shape), box);

    World moved = std::move(a);  // a World keeps its identity when moved
    EXPECT_TRUE(moved.isValid(box));
    EXPECT_EQ(moved.position(box).y, 1.0f);

    // Another World restored from the snapshot takes the snapshotted World's identity on: the
    // handles valid at the snapshot are valid there, and so are its own; a third World's are not.
    World other, third;
    const BodyId own = addBox(other, {3.0f, 1.0f}, 0.5f, 0.5f);
    const BodyId stranger = addBox(third, {3.0f, 1.0f}, 0.5f, 0.5f);
    other.restore(bytes);
    EXPECT_TRUE(other.isValid(box));
    EXPECT_EQ(other.position(box).y, 1.0f);
    EXPECT_TRUE(other.isValid(own));  // the same slot: the restored box
    EXPECT_FALSE(other.isValid(stranger));
    EXPECT_EQ(other.bodies().front(), box);  // new handles carry the snapshotted World's identity
    EXPECT_EQ(other.snapshot(), bytes);
}

// --- bodies at run time ---

TEST(RuntimeBodies, ABodyMadeStaticStopsAndHoldsAnotherThenFallsWhenMadeDynamic) {
    World world;
    addGround(world);
    const BodyId plank = addBox(world, {0.0f, 10.0f}, 2.0f, 0.25f);  // 4 m × 0.5 m of ρ = 1: 2 kg
    run(world, 30);
    world.setType(plank, BodyType::Static);
    EXPECT_EQ(world.mass(plank), 0.0f);
    EXPECT_EQ(world.linearVelocity(plank).y, 0.0f);
    const Vec2 held = world.position(plank);
    const BodyId box = addBox(world, {0.0f, held.y + 1.0f}, 0.5f, 0.5f);
    run(world, 120);
    EXPECT_EQ(world.position(plank).y, held.y);  // static: not moved by the box
    EXPECT_NEAR(world.position(box).y, held.y + 0.25f + 0.5f, 0.01f);  // resting on it
    EXPECT_NEAR(world.linearVelocity(box).y, 0.0f, 1e-3f);

    world.setType(plank, BodyType::Dynamic);
    EXPECT_FLOAT_EQ(world.mass(plank), 4.0f * 0.5f);  // ρ·A = 1 · (4 × 0.5)
    run(world, 30);  // free fall for 0.5 s, the box riding on it (its contact found again first)
    EXPECT_NEAR(world.position(plank).y, held.y - fallIn(30), 0.05f);
    EXPECT_NEAR(world.position(box).y - world.position(plank).y, 0.75f, 0.01f);
}

TEST(RuntimeBodies, AMassOverrideChangesTheAccelerationUnderAKnownForce) {
    World world(WorldDef{.gravity = {0.0f, 0.0f}});
    const BodyId box = addBox(world, {0.0f, 0.0f}, 0.5f, 0.5f);  // 1 kg from its shape
    ASSERT_FLOAT_EQ(world.mass(box), 1.0f);
    world.setMassData(box, MassData{.mass = 4.0f, .center = {0.0f, 0.0f}, .rotationalInertia = 2.0f});
    EXPECT_EQ(world.massData(box).mass, 4.0f);
    const Vec2 force{8.0f, 0.0f};
    world.applyForceToCenter(box, force);
    world.step(dt);
    EXPECT_FLOAT_EQ(world.linearVelocity(box).x, force.x / 4.0f * dt);  // a = F/m
    world.applyTorque(box, 6.0f);
    world.step(dt);
    EXPECT_FLOAT_EQ(world.angularVelocity(box), 6.0f / 2.0f * dt);  // α = τ/I

    world.resetMassData(box);  // back to the shape's 1 kg
    EXPECT_FLOAT_EQ(world.mass(box), 1.0f);
    const float v0 = world.linearVelocity(box).x;
    world.applyForceToCenter(box, force);
    world.step(dt);
    EXPECT_NEAR(world.linearVelocity(box).x - v0, force.x * dt, 1e-6f);
    EXPECT_THROW(world.setMassData(box, MassData{.mass = -1.0f}), Error);
}

TEST(RuntimeBodies, FixedRotationBulletAndSleepCanChangeAfterCreation) {
    Resting s;
    s.world.setAngularVelocity(s.box, 3.0f);
    s.world.setFixedRotation(s.box, true);
    EXPECT_TRUE(s.world.isFixedRotation(s.box));
    EXPECT_EQ(s.world.angularVelocity(s.box), 0.0f);
    EXPECT_EQ(s.world.rotationalInertia(s.box), 0.0f);
    s.world.applyTorque(s.box, 50.0f);
    s.world.step(dt);
    EXPECT_EQ(s.world.angle(s.box), 0.0f);
    s.world.setFixedRotation(s.box, false);
    EXPECT_FLOAT_EQ(s.world.rotationalInertia(s.box), 1.0f / 6.0f);  // m(w² + h²)/12

    s.world.setBullet(s.box, true);
    EXPECT_TRUE(s.world.isBullet(s.box));

    s.world.setAllowSleep(s.box, false);
    EXPECT_FALSE(s.world.allowsSleep(s.box));
    run(s.world, 180);  // three seconds at rest: it would sleep after half a second
    EXPECT_TRUE(s.world.isAwake(s.box));
    s.world.setAllowSleep(s.box, true);
    run(s.world, 120);
    EXPECT_FALSE(s.world.isAwake(s.box));
}

TEST(RuntimeBodies, EachBodyListsItsContactsAndJoints) {
    Resting s;
    const BodyId other = addBox(s.world, {5.0f, 0.5f}, 0.5f, 0.5f);
    run(s.world, 2);
    const std::vector<ContactData> contacts = s.world.bodyContacts(s.box);
    ASSERT_EQ(contacts.size(), 1u);
    EXPECT_TRUE((contacts[0].shapeA == s.boxShape) != (contacts[0].shapeB == s.boxShape));
    EXPECT_EQ(s.world.bodyContacts(s.ground).size(), 2u);
    EXPECT_TRUE(s.world.bodyJoints(s.box).empty());
    const JointId joint = s.world.createJoint(RevoluteJointDef{.bodyA = s.box, .bodyB = other});
    ASSERT_EQ(s.world.bodyJoints(s.box).size(), 1u);
    EXPECT_EQ(s.world.bodyJoints(s.box)[0], joint);
    EXPECT_EQ(s.world.bodyJoints(other)[0], joint);
    EXPECT_TRUE(s.world.bodyJoints(s.ground).empty());
}

TEST(RuntimeBodies, ATargetTransformIsReachedInOneStepAndCarriesWhatRidesOnIt) {
    World world;
    const BodyId mover = world.createBody(bodyAt({0.0f, 0.0f}, BodyType::Kinematic));
    world.createShape(mover, {}, makeBox(0.5f, 0.5f, {0.25f, 0.0f}));
    world.setTargetTransform(mover, {3.0f, 1.0f}, 0.5f, dt);
    world.step(dt);
    EXPECT_NEAR(world.position(mover).x, 3.0f, 1e-5f);
    EXPECT_NEAR(world.position(mover).y, 1.0f, 1e-5f);
    EXPECT_NEAR(world.angle(mover), 0.5f, 1e-6f);

    // A platform led along x at 1.2 m/s: the box on it keeps its place on the platform.
    World ride;
    const BodyId platform = ride.createBody(bodyAt({0.0f, -0.25f}, BodyType::Kinematic));
    ride.createShape(platform, {}, makeBox(3.0f, 0.25f));
    const BodyId box = addBox(ride, {0.0f, 0.5f}, 0.5f, 0.5f);
    run(ride, 30);  // settle
    float offset = 0.0f;  // the box's place on the platform once friction has brought it up to speed
    for (int i = 1; i <= 120; ++i) {
        ride.setTargetTransform(platform, {0.02f * static_cast<float>(i), -0.25f}, 0.0f, dt);
        ride.step(dt);
        if (i == 60) offset = ride.position(box).x - ride.position(platform).x;
    }
    EXPECT_NEAR(ride.position(platform).x, 2.4f, 1e-4f);
    EXPECT_NEAR(ride.position(box).x - ride.position(platform).x, offset, 0.005f);  // it rides along
    EXPECT_GT(ride.position(box).x, 2.0f);  // (friction lets it slip μ g t²/2 = 0.12 m at the start)
    EXPECT_NEAR(ride.linearVelocity(box).x, 1.2f, 0.01f);
}

TEST(RuntimeBodies, ADisabledBodyIsInNoQueryOrContactAndComesBackWhereItWas) {
    Resting s;
    const BodyId flyer = addBox(s.world, {5.0f, 3.0f}, 0.5f, 0.5f);
    const BodyId partner = addBox(s.world, {8.0f, 3.0f}, 0.5f, 0.5f);
    s.world.createJoint(RevoluteJointDef{.bodyA = flyer, .bodyB = partner, .localAnchorA = {1.5f, 0.0f}, .localAnchorB = {-1.5f, 0.0f}});
    run(s.world, 10);
    s.world.setLinearVelocity(s.box, {0.5f, 0.0f});
    const Transform pose = s.world.transform(s.box);
    const Vec2 flyerAt = s.world.position(flyer);
    const Vec2 v = s.world.linearVelocity(s.box);
    s.world.setEnabled(s.box, false);
    EXPECT_FALSE(s.world.isEnabled(s.box));
    EXPECT_EQ(s.world.contactCount(), 0);
    EXPECT_TRUE(s.world.bodyContacts(s.box).empty());
    EXPECT_TRUE(s.world.overlapPoint(s.world.worldCenter(s.box)).empty());
    EXPECT_FALSE(s.world.castRayClosest({0.0f, 3.0f}, {0.0f, -2.9f}).has_value());
    s.world.setEnabled(flyer, false);  // its joint is not solved: the partner falls freely
    s.world.step(dt);
    EXPECT_EQ(s.world.contactEvents().endEvents.size(), 1u);
    run(s.world, 20);
    EXPECT_NEAR(s.world.position(partner).x, 8.0f, 1e-4f);  // free fall, straight down
    EXPECT_NEAR(s.world.linearVelocity(partner).y, -10.0f * 31.0f * dt, 1e-3f);
    run(s.world, 39);
    EXPECT_EQ(s.world.transform(s.box).p, pose.p);  // not moved, not even by gravity
    EXPECT_EQ(s.world.position(flyer), flyerAt);  // where it was disabled

    s.world.setEnabled(s.box, true);
    EXPECT_EQ(s.world.linearVelocity(s.box), v);  // the velocity it had
    EXPECT_TRUE(s.world.isAwake(s.box));
    s.world.step(dt);
    EXPECT_EQ(s.world.contactEvents().beginEvents.size(), 1u);  // back on the ground
    EXPECT_EQ(s.world.overlapPoint(s.world.worldCenter(s.box)).size(), 1u);
}

TEST(RuntimeShapes, ADisabledShapeLeavesTheBroadphaseAndComesBack) {
    Resting s;
    run(s.world, 10);
    s.world.setEnabled(s.groundShape, false);
    EXPECT_FALSE(s.world.isEnabled(s.groundShape));
    EXPECT_EQ(s.world.contactCount(), 0);
    EXPECT_TRUE(s.world.overlapPoint({0.0f, -0.25f}).empty());
    run(s.world, 30);
    EXPECT_NEAR(s.world.position(s.box).y, 0.5f - fallIn(30), 0.01f);  // nothing holds it
    s.world.setTransform(s.box, {0.0f, 0.5f}, 0.0f);
    s.world.setLinearVelocity(s.box, {});
    s.world.setEnabled(s.groundShape, true);
    EXPECT_EQ(s.world.overlapPoint({0.0f, -0.25f}).size(), 1u);
    run(s.world, 60);
    EXPECT_NEAR(s.world.position(s.box).y, 0.5f, 0.01f);
}

// --- the world's origin ---

// A stack and a pendulum run on after the origin moves 1 km away: every body is where the unshifted
// run has it, translated, within float rounding of the new coordinates.
TEST(RuntimeOrigin, AShiftedWorldContinuesLikeTheUnshiftedOneTranslated) {
    auto build = [](World& world) {
        addGround(world);
        for (int i = 0; i < 4; ++i) addBox(world, {0.1f * static_cast<float>(i), 0.5f + static_cast<float>(i)}, 0.5f, 0.5f);
        const BodyId pivot = world.createBody(bodyAt({6.0f, 5.0f}, BodyType::Static));
        const BodyId bob = addBox(world, {8.0f, 5.0f}, 0.25f, 0.25f);
        world.createJoint(RevoluteJointDef{.bodyA = pivot, .bodyB = bob, .localAnchorB = {-2.0f, 0.0f}});
        const BodyId wheelA = addBox(world, {-6.0f, 6.0f}, 0.3f, 0.3f);
        const BodyId wheelB = addBox(world, {-3.0f, 6.0f}, 0.3f, 0.3f);
        world.createJoint(PulleyJointDef{.bodyA = wheelA, .bodyB = wheelB, .groundAnchorA = {-6.0f, 9.0f},
                                         .groundAnchorB = {-3.0f, 9.0f}, .localAnchorA = {}, .localAnchorB = {},
                                         .lengthA = 3.0f, .lengthB = 3.0f});
    };
    World plain, shifted;
    build(plain);
    build(shifted);
    run(plain, 30);
    run(shifted, 30);
    const Vec2 origin{1000.0f, -250.0f};
    shifted.shiftOrigin(origin);
    const std::vector<BodyId> a = plain.bodies(), b = shifted.bodies();
    for (size_t i = 0; i < a.size(); ++i) EXPECT_EQ(shifted.position(b[i]), plain.position(a[i]) - origin);
    run(plain, 90);
    run(shifted, 90);
    for (size_t i = 0; i < a.size(); ++i) {
        const Vec2 d = shifted.position(b[i]) + origin - plain.position(a[i]);
        EXPECT_LT(length(d), 2e-3f) << "body " << i;
        EXPECT_NEAR(shifted.angle(b[i]), plain.angle(a[i]), 2e-3f) << "body " << i;
    }
    EXPECT_EQ(shifted.contactCount(), plain.contactCount());
    const auto [groundA, groundB] = shifted.pulleyGroundAnchors(shifted.joints()[1]);
    EXPECT_EQ(groundA, (Vec2{-6.0f, 9.0f} - origin));
    EXPECT_EQ(groundB, (Vec2{-3.0f, 9.0f} - origin));
    EXPECT_THROW(shifted.shiftOrigin({std::numeric_limits<float>::infinity(), 0.0f}), Error);
}

// --- shapes at run time ---

TEST(RuntimeShapes, AFilterChangeEndsContactsAndStopsCollisionsFromTheNextStep) {
    Resting s;
    run(s.world, 10);
    s.world.setFilter(s.boxShape, Filter{.category = 0x0002, .mask = 0x0002});  // ground: category 1
    EXPECT_EQ(s.world.filter(s.boxShape).mask, 0x0002);
    EXPECT_EQ(s.world.contactCount(), 0);
    s.world.step(dt);
    EXPECT_EQ(s.world.contactEvents().endEvents.size(), 1u);
    run(s.world, 30);  // falls through the ground
    EXPECT_NEAR(s.world.position(s.box).y, 0.5f - fallIn(31), 0.01f);

    // Back to the default filter, overlapping the ground: the pair is found again and pushed apart.
    s.world.setTransform(s.box, {0.0f, 0.4f}, 0.0f);
    s.world.setLinearVelocity(s.box, {});
    s.world.setFilter(s.boxShape, Filter{});
    s.world.step(dt);
    EXPECT_EQ(s.world.contactEvents().beginEvents.size(), 1u);
    run(s.world, 60);
    EXPECT_NEAR(s.world.position(s.box).y, 0.5f, 0.01f);
}

TEST(RuntimeShapes, ASensorToggleTurnsContactsIntoSensorEventsAndBack) {
    Resting s;
    run(s.world, 10);
    s.world.setSensor(s.groundShape, true);
    EXPECT_TRUE(s.world.isSensor(s.groundShape));
    s.world.step(dt);
    EXPECT_EQ(s.world.contactEvents().endEvents.size(), 1u);
    ASSERT_EQ(s.world.sensorEvents().beginEvents.size(), 1u);
    EXPECT_EQ(s.world.sensorEvents().beginEvents[0].visitorShape, s.boxShape);
    run(s.world, 5);
    EXPECT_LT(s.world.linearVelocity(s.box).y, -0.5f);  // nothing holds it: falling
    s.world.setTransform(s.box, {0.0f, 0.45f}, 0.0f);
    s.world.setLinearVelocity(s.box, {});
    s.world.setSensor(s.groundShape, false);
    run(s.world, 60);
    EXPECT_NEAR(s.world.position(s.box).y, 0.5f, 0.01f);  // solid again
    EXPECT_EQ(s.world.contactCount(), 1);
}

TEST(RuntimeShapes, UserDataCanBeReadAndChanged) {
    World world;
    int tag = 0, other = 0;
    const BodyId body = world.createBody(bodyAt({}));
    const ShapeId shape = world.createShape(body, ShapeDef{.userData = &tag}, Circle{{}, 0.5f});
    EXPECT_EQ(world.userData(shape), &tag);
    world.setUserData(shape, &other);
    EXPECT_EQ(world.userData(shape), &other);
    world.setUserData(body, &tag);
    EXPECT_EQ(world.userData(body), &tag);
}

TEST(RuntimeShapes, ADensityChangeChangesTheMass) {
    Resting s;
    s.world.setDensity(s.boxShape, 3.0f);
    EXPECT_FLOAT_EQ(s.world.mass(s.box), 3.0f);
    EXPECT_FLOAT_EQ(s.world.rotationalInertia(s.box), 3.0f / 6.0f);
}

// --- the game's collision rule ---

TEST(RuntimeShouldCollide, TheGamesRuleDecidesWhichNewPairsGetContacts) {
    World world;
    addGround(world);
    int ghost = 0;
    const BodyId solid = addBox(world, {-2.0f, 2.0f}, 0.5f, 0.5f);
    const BodyId phantom = world.createBody(bodyAt({2.0f, 2.0f}));
    world.createShape(phantom, ShapeDef{.userData = &ghost}, makeBox(0.5f, 0.5f));
    int asked = 0;
    world.setShouldCollide([&](ShapeId a, ShapeId b) {
        ++asked;
        return world.userData(a) != &ghost && world.userData(b) != &ghost;
    });
    int phantomTouches = 0;
    for (int i = 0; i < 60; ++i) {
        world.step(dt);
        for (const ContactBeginTouchEvent& e : world.contactEvents().beginEvents)
            phantomTouches += world.shapeBody(e.shapeA) == phantom || world.shapeBody(e.shapeB) == phantom;
    }
    EXPECT_GE(asked, 2);  // each box's pair with the ground, when their boxes first overlap
    EXPECT_EQ(phantomTouches, 0);
    EXPECT_NEAR(world.position(solid).y, 0.5f, 0.01f);
    EXPECT_LT(world.position(phantom).y, -1.0f);  // fell through
    world.setShouldCollide({});
}

// --- snapshots ---

// Every change above is state a snapshot holds: restored, the world replays the same future bit
// for bit as the world that was never saved.
TEST(RuntimeSnapshot, ChangesMadeAtRunTimeSurviveARestoreBitForBit) {
    World world;
    addGround(world);
    const BodyId plank = addBox(world, {0.0f, 4.0f}, 2.0f, 0.25f);
    const BodyId heavy = addBox(world, {-1.0f, 6.0f}, 0.5f, 0.5f);
    const BodyId spinner = addBox(world, {1.0f, 6.0f}, 0.5f, 0.5f);
    const BodyId ghost = addBox(world, {3.0f, 2.0f}, 0.5f, 0.5f);
    const BodyId lift = world.createBody(bodyAt({-4.0f, 1.0f}, BodyType::Kinematic));
    world.createShape(lift, {}, makeBox(1.0f, 0.2f));
    const ShapeId sensorShape = world.createShape(lift, ShapeDef{.sensor = false}, Circle{{0.0f, 1.0f}, 0.5f});
    run(world, 20);
    world.setType(plank, BodyType::Static);
    world.setMassData(heavy, MassData{.mass = 5.0f, .center = {0.1f, 0.0f}, .rotationalInertia = 0.7f});
    world.setFixedRotation(spinner, true);
    world.setBullet(spinner, true);
    world.setAllowSleep(heavy, false);
    world.setFilter(world.shapes(ghost).front(), Filter{.category = 0x0004, .mask = 0x0004});
    world.setSensor(sensorShape, true);
    world.setTargetTransform(lift, {-3.0f, 1.5f}, 0.2f, dt);
    const BodyId parked = addBox(world, {6.0f, 3.0f}, 0.5f, 0.5f);
    const BodyId shelf = addBox(world, {9.0f, 0.5f}, 0.5f, 0.5f);
    run(world, 3);
    world.setEnabled(parked, false);
    world.setEnabled(world.shapes(shelf).front(), false);
    world.shiftOrigin({3.0f, -1.0f});
    run(world, 2);

    const std::vector<uint8_t> saved = world.snapshot();
    run(world, 120);
    const uint64_t future = stateHash(world);
    EXPECT_EQ(world.mass(heavy), 5.0f);
    EXPECT_LT(world.position(ghost).y, -5.0f);  // its filter still lets it through the ground

    World restored;
    restored.restore(saved);
    run(restored, 120);
    EXPECT_EQ(stateHash(restored), future);
    world.restore(saved);
    run(world, 120);
    EXPECT_EQ(stateHash(world), future);
    EXPECT_TRUE(world.isSensor(sensorShape));
    EXPECT_TRUE(world.isFixedRotation(spinner));
    EXPECT_TRUE(world.isBullet(spinner));
    EXPECT_FALSE(world.allowsSleep(heavy));
    EXPECT_EQ(world.bodyType(plank), BodyType::Static);
    EXPECT_FALSE(world.isEnabled(parked));
    EXPECT_FALSE(world.isEnabled(world.shapes(shelf).front()));
    world.setEnabled(parked, true);  // and it comes back from a restored world too
    restored.setEnabled(restored.bodies()[static_cast<size_t>(parked.index)], true);
    run(world, 30);
    run(restored, 30);
    EXPECT_EQ(stateHash(restored), stateHash(world));
}

// --- the scene format ---

// "mass_data" gives a body the mass a game would set with setMassData: the built body falls with it
// on a spring-less slope of gravity alone, but its weight m g is the scene's m.
TEST(RuntimeScene, MassDataIsReadBuiltWrittenAndItsErrorsNamed) {
    const Scene scene = parseScene(R"({"format": "perpdot-scene/1", "bodies": [
        {"name": "crate", "position": [0, 2], "fixed_rotation": true, "bullet": true, "allow_sleep": false,
         "mass_data": {"mass": 7.5, "center": [0.1, 0], "rotational_inertia": 2},
         "shapes": [{"type": "box", "half_extents": [0.5, 0.5], "sensor": true, "filter": {"category": 2, "mask": 4}}]}]})");
    ASSERT_TRUE(scene.bodies[0].massData.has_value());
    EXPECT_EQ(scene.bodies[0].massData->mass, 7.5f);
    EXPECT_TRUE(parseScene(toJson(scene)) == scene);
    SceneWorld built = buildWorld(scene);
    const BodyId crate = built.bodies[0];
    EXPECT_EQ(built.world.mass(crate), 7.5f);
    EXPECT_EQ(built.world.localCenter(crate).x, 0.1f);
    EXPECT_EQ(built.world.rotationalInertia(crate), 0.0f);  // fixed rotation
    EXPECT_TRUE(built.world.isBullet(crate));
    EXPECT_FALSE(built.world.allowsSleep(crate));
    const ShapeId shape = built.world.shapes(crate).front();
    EXPECT_TRUE(built.world.isSensor(shape));
    EXPECT_EQ(built.world.filter(shape).mask, 4);
    // a = F/m under a known force, as the scene's mass says.
    built.world.setGravity({0.0f, 0.0f});
    built.world.applyForceToCenter(crate, {15.0f, 0.0f});
    built.world.step(dt);
    EXPECT_FLOAT_EQ(built.world.linearVelocity(crate).x, 15.0f / 7.5f * dt);

    const auto refused = [](const std::string& massData) {
        try {
            parseScene(R"({"format": "perpdot-scene/1", "bodies": [{"mass_data": )" + massData + "}]}");
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("(accepted)");
    };
    EXPECT_TRUE(contains(refused(R"({"mass": -1})"), "bodies[0].mass_data.mass")) << refused(R"({"mass": -1})");
    EXPECT_TRUE(contains(refused(R"({"inertia": 1})"), "bodies[0].mass_data.inertia: unknown key"));
    EXPECT_TRUE(contains(refused(R"({"center": [0]})"), "bodies[0].mass_data.center"));
}

}  // namespace
}  // namespace perpdot
