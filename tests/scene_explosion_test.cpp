// The scene format's explosion action: World::explode at a point, once per step of its range —
// read and written back, refused with a JSON path when malformed, the same impulses as calling
// World::explode directly, and refused by the cross-check (Box2D 2.4 has no explosion).
#include <gtest/gtest.h>

#include <string>

#include "perpdot/crosscheck.hpp"
#include "perpdot/error.hpp"
#include "perpdot/scene.hpp"

namespace perpdot {
namespace {

// Two balls at rest on the ground without gravity: one 1 m right of the blast, one 5 m away.
std::string ballsAndBlast(const std::string& action) {
    return R"({"format": "perpdot-scene/1", "name": "blast", "gravity": [0, 0], "steps": 3,
      "bodies": [
        {"name": "near", "type": "dynamic", "position": [1, 0], "shapes": [{"type": "circle", "radius": 0.25}]},
        {"name": "far", "type": "dynamic", "position": [5, 0], "shapes": [{"type": "circle", "radius": 0.25}]}],
      "actions": [)" + action + "]}";
}

const std::string blast = R"({"type": "explosion", "point": [0, 0], "radius": 3, "value": 6, "first_step": 1})";

TEST(SceneExplosion, ReadsAndWritesBack) {
    const Scene s = parseScene(ballsAndBlast(blast));
    ASSERT_EQ(s.actions.size(), 1u);
    const SceneAction& a = s.actions[0];
    EXPECT_EQ(a.kind, SceneAction::Kind::Explosion);
    EXPECT_TRUE(a.body.empty());
    EXPECT_EQ(a.point, (Vec2{0.0f, 0.0f}));
    EXPECT_EQ(a.radius, 3.0f);
    EXPECT_EQ(a.scalar, 6.0f);
    EXPECT_FALSE(a.blockedByStatic);
    EXPECT_EQ(a.firstStep, 1);
    EXPECT_EQ(a.lastStep, 1);
    EXPECT_EQ(parseScene(toJson(s)), s);
    Scene blocked = parseScene(ballsAndBlast(R"({"type": "explosion", "point": [0, 0], "radius": 3, "value": 6, "blocked_by_static": true})"));
    EXPECT_TRUE(blocked.actions[0].blockedByStatic);
    EXPECT_EQ(parseScene(toJson(blocked)), blocked);
}

// Each bad explosion is refused with an Error naming the JSON path of what is wrong.
TEST(SceneExplosion, BadExplosionsNameTheirJsonPath) {
    const std::pair<std::string, std::string> cases[] = {
        {R"({"type": "explosion", "point": [0, 0], "radius": 0, "value": 6})", "actions[0].radius"},
        {R"({"type": "explosion", "point": [0, 0], "radius": -1, "value": 6})", "actions[0].radius"},
        {R"({"type": "explosion", "point": [0, 0], "radius": 3, "value": -6})", "actions[0].value"},
        {R"({"type": "explosion", "point": [0, 0], "radius": 3})", "actions[0].value"},
        {R"({"type": "explosion", "radius": 3, "value": 6})", "actions[0].point"},
        {R"({"type": "explosion", "point": [0, 1e39], "radius": 3, "value": 6})", "actions[0].point"},
        {R"({"type": "explosion", "point": [0, 0], "radius": 3, "value": 6, "body": "near"})", "actions[0].body"},
        {R"({"type": "explosion", "point": [0, 0], "radius": 3, "value": 6, "falloff": 2})", "actions[0].falloff"},
    };
    for (const auto& [action, path] : cases) {
        try {
            (void)parseScene(ballsAndBlast(action));
            ADD_FAILURE() << "accepted " << action;
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << action << ": " << e.what();
        }
    }
    Scene s = parseScene(ballsAndBlast(blast));
    s.actions[0].radius = 0.0f;  // a scene built in C++ is checked by buildWorld
    EXPECT_THROW((void)buildWorld(s), Error);
}

// The near ball flies away from the centre with what World::explode gives it, at the step the
// action names; the ball beyond the radius does not move.
TEST(SceneExplosion, PushesWhatIsInReachAsWorldExplodeDoes) {
    SceneWorld scripted = buildWorld(parseScene(ballsAndBlast(blast)));
    SceneWorld direct = buildWorld(parseScene(ballsAndBlast("")));
    scripted.step();
    direct.step();
    EXPECT_EQ(scripted.world.linearVelocity(scripted.bodies[0]), (Vec2{0.0f, 0.0f})) << "step 0: not yet";
    scripted.step();
    direct.world.explode({.position = {0.0f, 0.0f}, .radius = 3.0f, .impulse = 6.0f});
    direct.step();
    const Vec2 v = scripted.world.linearVelocity(scripted.bodies[0]);
    EXPECT_GT(v.x, 0.0f);
    EXPECT_EQ(v, direct.world.linearVelocity(direct.bodies[0])) << "bit for bit what World::explode does";
    EXPECT_EQ(scripted.world.linearVelocity(scripted.bodies[1]), (Vec2{0.0f, 0.0f})) << "5 m away, outside 3 m";
}

TEST(SceneExplosion, TheCrossCheckRefusesItBox2DHasNone) {
    const Scene s = parseScene(ballsAndBlast(blast));
    try {
        (void)crosscheck::record(s, crosscheck::Engine::Box2D, 2);
        ADD_FAILURE() << "Box2D ran an explosion";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("actions[0]: Box2D 2.4 has no explosion"), std::string::npos) << e.what();
    }
    EXPECT_THROW((void)crosscheck::run(s), Error);
}

}  // namespace
}  // namespace perpdot
