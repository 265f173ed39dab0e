// Contact groups solved directly (src/core/solver/contact_groups.hpp): a small group with a heavily loaded
// row rests where the contact forces' accelerations put it, C = K F / ω² — g/ω² on the ground, 0
// between bodies — instead of sinking by its load over its own stiffness. The `perpdot stress`
// cases check the centred heavy box and the 50-box column; these check what the suite does not.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/solver/cholesky.hpp"
#include "core/solver/contact_groups.hpp"
#include "perpdot/world.hpp"
#include "physics_scenes.hpp"

namespace perpdot {
namespace {

using test::dt;

constexpr float restGap = 0.001f;  // on static ground: 0.5 mm of Box2D's skin kept by each polygon

// A 1 m box of density 1000 resting off centre (0.45 m: its centre of mass still over the light
// box) on a 1 m box of density 1, 10 s.
TEST(ContactGroups, HeavyBoxOffCentreOnALightOneStands) {
    World world({.enableSleep = false});
    test::addGround(world);
    const BodyId light = test::addBox(world, {0.0f, 0.5f}, 0.5f, 0.5f);
    const BodyId heavy = test::addBox(world, {0.45f, 1.5f}, 0.5f, 0.5f, test::material(1000.0f));
    test::run(world, 600);
    EXPECT_LT(1.0f - (world.position(heavy).y - world.position(light).y), 0.005f) << "sank into the light box";
    EXPECT_LT(std::fabs(world.angle(heavy)), 0.01f);
    EXPECT_LT(std::fabs(world.angle(light)), 0.01f);
    EXPECT_NEAR(world.position(heavy).x, 0.45f, 0.01f);
}

// Four ground rows and three freedoms: the light box straddles two static tiles, and K is singular
// but for its compliance. The 300 : 1 load must neither sink nor launch anything.
TEST(ContactGroups, HeavyLoadOnABoxStraddlingTwoTilesStands) {
    World world({.enableSleep = false});
    const BodyId tiles = world.createBody(test::bodyAt({0.0f, 0.0f}, BodyType::Static));
    world.createShape(tiles, {}, makeBox(0.5f, 0.5f, {-0.5f, -0.5f}, 0.0f));
    world.createShape(tiles, {}, makeBox(0.5f, 0.5f, {0.5f, -0.5f}, 0.0f));
    const BodyId light = test::addBox(world, {0.0f, 0.5f}, 0.5f, 0.5f);
    const BodyId heavy = test::addBox(world, {0.0f, 1.5f}, 0.5f, 0.5f, test::material(300.0f));
    test::run(world, 10);  // the first step falls freely onto the contacts
    for (int step = 10; step < 600; ++step) {
        world.step(dt);
        ASSERT_LT(length(world.linearVelocity(heavy)), 0.01f) << "step " << step;
        ASSERT_LT(length(world.linearVelocity(light)), 0.01f) << "step " << step;
    }
    EXPECT_NEAR(world.position(light).y, 0.5f, 0.002f);
    EXPECT_NEAR(world.position(heavy).y - world.position(light).y, 1.0f, 0.002f);
}

// Ten boxes: the boxes rest on each other's true surfaces and the lowest on the ground's rest gap,
// the column one rest gap taller than built (rows solved one by one, its lowest interface alone
// sank 2.5 mm).
TEST(ContactGroups, ColumnRestsOnItsTrueSurfaces) {
    World world({.enableSleep = false});
    test::addGround(world);
    BodyId top;
    for (int i = 0; i < 10; ++i) top = test::addBox(world, {0.0f, 0.5f + static_cast<float>(i)}, 0.5f, 0.5f);
    test::run(world, 300);
    EXPECT_NEAR(world.position(top).y, 9.5f + restGap, 0.0005f);
}

// Fallen dominoes lying on each other: a group whose rows keep changing sides of the
// complementarity problem. It comes to rest, and the bodies fall asleep.
TEST(ContactGroups, FallenDominoesComeToRestAndSleep) {
    World world;
    test::addGround(world);
    std::vector<BodyId> dominoes;
    for (int i = 0; i < 10; ++i) dominoes.push_back(test::addBox(world, {1.2f * static_cast<float>(i), 1.0f}, 0.1f, 1.0f));
    world.setAngularVelocity(dominoes[0], -2.0f);
    test::run(world, 900);
    EXPECT_GT(std::fabs(world.angle(dominoes.back())), 1.0f) << "the last domino did not fall";
    for (const BodyId d : dominoes) EXPECT_FALSE(world.isAwake(d));
}

// The factor cost of a group whose constraints, in order, join these slot pairs (0: the static
// slot, which moves nothing) with two rows each, as findContactGroups counts it.
int64_t factorCost(const std::vector<std::array<int, 2>>& pairs) {
    std::vector<int> firstRow(pairs.size() + 2, -1), first;
    for (const auto [a, b] : pairs) {
        const int row = static_cast<int>(first.size());
        const int f = envelopeFirst(firstRow, row, a > 0 ? a : -1, b > 0 ? b : -1);
        first.insert(first.end(), 2, f);
    }
    return envelopeCost(first.data(), static_cast<int>(first.size()));
}

// A 100-box column is 200 rows, each reaching back to the rows of the interface below: a band
// of 4 rows, solved directly. A plank on 50 boxes is 200 rows too, but every plank row shares the
// plank with all the others before it: left row by row, while a plank on 32 boxes (128 rows) is
// solved directly whatever its envelope.
TEST(ContactGroups, AdmitsALongGroupOnlyInABand) {
    std::vector<std::array<int, 2>> column{{0, 1}};
    for (int box = 1; box < 100; ++box) column.push_back({box, box + 1});
    EXPECT_EQ(factorCost(column), 1 + 4 + 99 * (9 + 16));  // profiles 1, 2, then 3, 4 at each interface
    EXPECT_TRUE(admitted(200, factorCost(column)));

    auto plankOn = [](int boxes) {  // the plank is slot 1, the boxes 2 ..
        std::vector<std::array<int, 2>> pairs;
        for (int box = 2; box < boxes + 2; ++box) {
            pairs.push_back({0, box});
            pairs.push_back({box, 1});
        }
        return pairs;
    };
    EXPECT_FALSE(admitted(200, factorCost(plankOn(50))));
    EXPECT_TRUE(admitted(128, factorCost(plankOn(32))));
}

// A 0.1 kg arm (1 m by 0.1 m) held at its end by `Def` to static ground, in zero gravity, and a
// 5 kg ball (50 times its mass) resting on it 0.9 m out; after one step (the contact found) the ball
// strikes at 10 m/s. The hit makes the arm's group take the joint's rows into its K: the blow meets
// the ground through the joint in one solve. Returns the arm's angle at every step after and the
// ball's speed at the end, and fails if the two bodies' kinetic energy ever passes the ball's 250 J.
struct Struck {
    std::vector<float> angles;
    float ballSpeed;
};
template <class Def>
Struck strikeAnchoredArm(Def def) {
    World world({.gravity = {0.0f, 0.0f}, .enableSleep = false});
    const BodyId ground = world.createBody(test::bodyAt({0.0f, 0.0f}, BodyType::Static));
    const BodyId arm = test::addBox(world, {0.5f, 0.0f}, 0.5f, 0.05f, test::material(1.0f));
    const BodyId ball = test::addDisc(world, {0.9f, 0.15f}, 0.1f, test::material(5.0f / (3.14159265f * 0.01f)));
    def.bodyA = ground, def.bodyB = arm, def.localAnchorB = {-0.5f, 0.0f};
    world.createJoint(def);
    world.step(dt);
    world.setLinearVelocity(ball, {0.0f, -10.0f});
    auto energy = [&] {
        float e = 0.0f;
        for (const BodyId body : {arm, ball})
            e += 0.5f * world.mass(body) * dot(world.linearVelocity(body), world.linearVelocity(body));
        return e + 0.5f * world.rotationalInertia(arm) * world.angularVelocity(arm) * world.angularVelocity(arm);
    };
    const float struck = energy();
    std::vector<float> angles;
    for (int step = 0; step < 60; ++step) {
        world.step(dt);
        angles.push_back(world.angle(arm));
        EXPECT_LE(energy(), struck * 1.0001f) << "step " << step;
    }
    return {angles, length(world.linearVelocity(ball))};
}

// Welded, the arm bends less than 0.01 rad (row by row, the blow bends it by a third of a radian);
// the joint's soft rows give back a little of it (the ball leaves at about 1.2 m/s).
TEST(ContactGroups, StruckWeldedArmStaysStraight) {
    const Struck struck = strikeAnchoredArm(WeldJointDef{});
    for (const float angle : struck.angles) EXPECT_LT(std::fabs(angle), 0.01f);
    EXPECT_LT(struck.ballSpeed, 2.0f);
}

// Hinged with a ±0.05 rad limit, the arm turns onto its limit and stops the ball there.
TEST(ContactGroups, StruckHingedArmHoldsItsLimit) {
    RevoluteJointDef hinge;
    hinge.enableLimit = true, hinge.lowerAngle = -0.05f, hinge.upperAngle = 0.05f;
    const Struck struck = strikeAnchoredArm(hinge);
    for (const float angle : struck.angles) EXPECT_GT(angle, -0.05f - 0.005f);
    EXPECT_LT(struck.angles.front(), -0.04f);
    EXPECT_LT(struck.ballSpeed, 0.1f);
}

}  // namespace
}  // namespace perpdot
