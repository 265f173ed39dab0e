// Support loads and rest sinks (src/core/solver/support_sinks.hpp): a pile solved row by row keeps
// the height it was built at. The `perpdot stress` cases pile20 and large_pile check whole piles
// for 60 s and 10 s; these check each half on its own.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "perpdot/world.hpp"
#include "physics_scenes.hpp"

namespace perpdot {
namespace {

using test::dt;

// A box of density `ratio` on a 1 m box of density 1 on the ground, kept out of the direct contact
// groups by a slack distance joint between them (contact_groups.hpp: a group with a jointed body
// is solved row by row; at its rest length and 1e-3 Hz the joint pulls with nothing).
struct LoadedPair {
    World world{WorldDef{.enableSleep = false}};
    BodyId light, heavy;
    explicit LoadedPair(float ratio) {
        test::addGround(world);
        light = test::addBox(world, {0.0f, 0.5f}, 0.5f, 0.5f);
        heavy = test::addBox(world, {0.0f, 1.5f}, 0.5f, 0.5f, test::material(ratio));
        world.createJoint(DistanceJointDef{.bodyA = light, .bodyB = heavy, .length = 1.0f, .hertz = 1e-3f, .collideConnected = true});
    }
    float apart() const { return world.position(heavy).y - world.position(light).y; }
};

// Row by row, the row under a 30 : 1 load rests at C = −λ K_ii / (hs ω²): about 1 cm into the light
// box. Offset by its rest sink, it rests on the light box's true surface once the low-passed sink
// has settled (time constant 1/3 s; jointed, the pair is not seeded and starts from no sink: 6 mm
// deep at first).
TEST(SupportSinks, AHeavyLoadSolvedRowByRowRestsOnItsTrueSurface) {
    LoadedPair pair(30.0f);
    float deepestAtFirst = 0.0f;
    for (int step = 0; step < 180; ++step) {
        pair.world.step(dt);
        deepestAtFirst = std::max(deepestAtFirst, 1.0f - pair.apart());
    }
    EXPECT_GT(deepestAtFirst, 2e-3f) << "the unseeded start should sink before the offset settles";
    for (int step = 180; step < 600; ++step) {
        pair.world.step(dt);
        ASSERT_NEAR(pair.apart(), 1.0f, 2e-4f) << "step " << step;
    }
    EXPECT_LT(std::fabs(pair.world.angle(pair.heavy)), 1e-3f);
}

// Without gravity there is no up and no support: two boxes pressed together by nothing keep their
// positions, and no row is offset.
TEST(SupportSinks, WithoutGravityNothingIsOffset) {
    World world(WorldDef{.gravity = {0.0f, 0.0f}, .enableSleep = false});
    const BodyId lower = test::addBox(world, {0.0f, 0.5f}, 0.5f, 0.5f);
    const BodyId upper = test::addBox(world, {0.0f, 1.5f}, 0.5f, 0.5f);
    test::run(world, 120);
    EXPECT_FLOAT_EQ(world.position(upper).y - world.position(lower).y, 1.0f);
    EXPECT_FLOAT_EQ(world.linearVelocity(upper).y, 0.0f);
}

// The load path: placed touching, a 20-row pyramid carries its top from the first step. Its top
// box ends the step at rest; without the seeded loads it fell at g h = 0.17 m/s (support reached
// it only after about four steps).
TEST(SupportSinks, APilePlacedTouchingCarriesItsTopFromTheFirstStep) {
    World world(WorldDef{.enableSleep = false});
    test::addGround(world);
    const std::vector<BodyId> boxes = test::addPyramid(world, 20);
    world.step(dt);
    EXPECT_LT(std::fabs(world.linearVelocity(boxes.back()).y), 0.02f);
    for (int step = 1; step < 10; ++step) {
        world.step(dt);
        EXPECT_NEAR(world.position(boxes.back()).y, 19.5f, 0.002f) << "step " << step;
    }
}

// The lever rule: a box placed off centre on two others, its centre 0.25 m right of their joint,
// meets them at points 0.5 and 0.25 m left of its centre and 0.25 and 0.5 m right. Seeded with
// Σλ = L, Σλx = 0 (least squares: 0.17, 0.22 | 0.22, 0.39 of L), the right box carries 61 % from
// the first step, and the top box neither falls nor turns.
TEST(SupportSinks, AnOffCentreBoxIsSeededByTheLeverRule) {
    World world(WorldDef{.enableSleep = false});
    test::addGround(world);
    const BodyId left = test::addBox(world, {-0.5f, 0.5f}, 0.5f, 0.5f);
    test::addBox(world, {0.5f, 0.5f}, 0.5f, 0.5f);
    const BodyId top = test::addBox(world, {0.25f, 1.5f}, 0.5f, 0.5f);
    world.step(dt);
    float onLeft = 0.0f, onRight = 0.0f;
    for (const ContactData& c : world.contacts()) {
        const BodyId a = world.shapeBody(c.shapeA), b = world.shapeBody(c.shapeB);
        const bool withTop = a == top || b == top;
        const BodyId other = a == top ? b : a;
        if (!withTop) continue;
        for (int i = 0; i < c.pointCount; ++i) (other == left ? onLeft : onRight) += c.points[i].normalImpulse;
    }
    ASSERT_GT(onLeft + onRight, 0.0f);
    EXPECT_GT(onRight, 1.2f * onLeft);
    EXPECT_LT(std::fabs(world.linearVelocity(top).y), 0.02f);
    EXPECT_LT(std::fabs(world.angularVelocity(top)), 0.02f);
}

}  // namespace
}  // namespace perpdot
