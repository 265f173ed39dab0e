// The cross-check builds Box2D 2.4's own b2World, whose constructors assert (abort the process)
// on definitions perpdot either refuses or accepts: every such scene is refused with a
// perpdot::Error naming what is wrong, whichever engine is asked for (docs/reliability.md).
#include <gtest/gtest.h>

#include <string>

#include "perpdot/crosscheck.hpp"
#include "perpdot/error.hpp"
#include "perpdot/scene.hpp"

namespace perpdot {
namespace {

Scene twoBoxes() {
    Scene s;
    s.name = "refused";
    s.steps = 5;
    SceneShape box;
    box.kind = SceneShape::Kind::Box;
    box.halfExtents = {0.5f, 0.5f};
    s.bodies.push_back({.name = "ground", .type = BodyType::Static, .shapes = {box}});
    s.bodies.push_back({.name = "a", .position = {0.0f, 2.0f}, .shapes = {box}});
    s.bodies.push_back({.name = "b", .position = {2.0f, 2.0f}, .shapes = {box}});
    return s;
}

// Both engines' paths into Box2D refuse it with an Error whose message contains `what`.
void expectRefused(const Scene& scene, const std::string& what) {
    for (const crosscheck::Engine engine : {crosscheck::Engine::Box2D, crosscheck::Engine::Perpdot}) {
        try {
            (void)crosscheck::record(scene, engine, 2);
            ADD_FAILURE() << "accepted: " << what;
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
        }
    }
    EXPECT_THROW((void)crosscheck::run(scene), Error);
}

TEST(CrosscheckRefuses, ALoopChainWhoseClosingEdgeIsShorterThanBox2DsSlop) {
    Scene s = twoBoxes();
    SceneShape loop;
    loop.kind = SceneShape::Kind::Chain;
    loop.loop = true;
    loop.vertices = {{0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 1.0f}, {0.0f, 0.001f}};
    s.bodies[0].shapes = {loop};
    // perpdot runs it ...
    EXPECT_NO_THROW((void)crosscheck::record(s, crosscheck::Engine::Perpdot, 2));
    // ... the cross-check says why Box2D cannot.
    try {
        (void)crosscheck::record(s, crosscheck::Engine::Box2D, 2);
        ADD_FAILURE() << "Box2D built a chain it asserts on";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("bodies[0].shapes[0]: Box2D 2.4 cannot build this chain: vertices 3 and 0"),
                  std::string::npos)
            << e.what();
    }
}

TEST(CrosscheckRefuses, AGearOnAJointThatIsNeitherRevoluteNorPrismatic) {
    Scene s = twoBoxes();
    s.joints.push_back({.type = JointType::Weld, .bodyA = "ground", .bodyB = "a", .anchor = Vec2{0.0f, 2.0f}});
    s.joints.push_back({.type = JointType::Revolute, .bodyA = "ground", .bodyB = "b", .anchor = Vec2{2.0f, 2.0f}});
    s.joints.push_back({.type = JointType::Gear, .bodyA = "a", .bodyB = "b", .jointA = 0, .jointB = 1});
    expectRefused(s, "joints[2]: GearJointDef.jointA must be a revolute or prismatic joint");
}

TEST(CrosscheckRefuses, AJointBetweenABodyAndItself) {
    Scene s = twoBoxes();
    s.joints.push_back({.type = JointType::Revolute, .bodyA = "a", .bodyB = "a", .anchor = Vec2{0.0f, 2.0f}});
    expectRefused(s, "joints[0]: a joint needs two different bodies");
}

TEST(CrosscheckRefuses, ARevoluteLimitWhoseLowerBoundIsAboveTheUpper) {
    Scene s = twoBoxes();
    s.joints.push_back({.type = JointType::Revolute, .bodyA = "ground", .bodyB = "a", .anchor = Vec2{0.0f, 2.0f}, .enableLimit = true,
                        .lowerAngle = 1.0f, .upperAngle = -1.0f});
    expectRefused(s, "joints[0]: RevoluteJointDef: lowerAngle must be <= upperAngle");
}

TEST(CrosscheckRefuses, APulleyWithRatioZero) {
    Scene s = twoBoxes();
    s.joints.push_back({.type = JointType::Pulley, .bodyA = "a", .bodyB = "b", .anchor = Vec2{0.0f, 2.0f}, .anchorB = Vec2{2.0f, 2.0f},
                        .ratio = 0.0f, .groundAnchorA = {0.0f, 5.0f}, .groundAnchorB = {2.0f, 5.0f}});
    expectRefused(s, "joints[0]: PulleyJointDef.ratio must be > 0");
}

// Box2D 2.4 has no breakable joints: a scene with break limits cannot be compared.
TEST(CrosscheckRefuses, BreakableJoints) {
    try {
        (void)crosscheck::run(findScene("breakable_bridge"));
        ADD_FAILURE() << "cross-checked a scene with breakable joints";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("Box2D 2.4 has no breakable joints"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace perpdot
