// Scenes of the joints that couple two motions: a gear train with a rack (gear joints) and an
// Atwood machine (pulley joint).
#include <string>

#include "scene/builtin_registry.hpp"
#include "scene/scene_builders.hpp"

namespace perpdot {
namespace {

// Gear parts never touch each other: the gear joints are their teeth.
SceneShape gearPart(SceneShape shape) {
    shape.filter.group = -1;
    return shape;
}

// A 1 m wheel carrying a 0.3 m lead weight off its centre drives a 1.5 m wheel (meshing:
// θ1 + 1.5 θ2 constant) which drives a vertical rack of 1 kg/m² (θ2 + x/1.5 constant): the train
// swings like a pendulum whose inertia includes every gear.
Scene gears() {
    Scene s;
    addBody(s, {.name = "frame", .type = BodyType::Static});
    SceneShape lead = gearPart(circleShape(0.3f, {0.7f, 0.0f}));
    lead.density = 20.0f;
    addBody(s, {.name = "small", .position = {-1.0f, 5.0f}, .shapes = {gearPart(circleShape(1.0f)), lead}});
    addBody(s, {.name = "large", .position = {1.5f, 5.0f}, .shapes = {gearPart(circleShape(1.5f))}});
    addBody(s, {.name = "rack", .position = {3.2f, 5.0f}, .shapes = {gearPart(boxShape(0.2f, 2.0f))}});
    s.joints.push_back({.type = JointType::Revolute, .bodyA = "frame", .bodyB = "small", .anchor = Vec2{-1.0f, 5.0f}});
    s.joints.push_back({.type = JointType::Revolute, .bodyA = "frame", .bodyB = "large", .anchor = Vec2{1.5f, 5.0f}});
    s.joints.push_back({.type = JointType::Prismatic, .bodyA = "frame", .bodyB = "rack", .anchor = Vec2{3.2f, 5.0f},
                        .axis = {0.0f, 1.0f}});
    s.joints.push_back({.type = JointType::Gear, .bodyA = "small", .bodyB = "large", .jointA = 0, .jointB = 1, .ratio = 1.5f});
    s.joints.push_back({.type = JointType::Gear, .bodyA = "large", .bodyB = "rack", .jointA = 1, .jointB = 2,
                        .ratio = 1.0f / 1.5f});
    return s;
}

// An Atwood machine: 2 kg and 1 kg boxes on one rope over two pulleys 4 m apart; the heavy side
// falls at g (m1 − m2)/(m1 + m2) = 3.33 m/s².
Scene pulley() {
    Scene s;
    addBody(s, {.name = "ceiling", .type = BodyType::Static, .position = {0.0f, 10.0f}, .shapes = {boxShape(3.0f, 0.1f)}});
    SceneShape heavy = boxShape(0.5f, 0.5f);
    heavy.density = 2.0f;
    addBody(s, {.name = "heavy", .position = {-2.0f, 6.0f}, .fixedRotation = true, .shapes = {heavy}});
    addBody(s, {.name = "light", .position = {2.0f, 6.0f}, .fixedRotation = true, .shapes = {boxShape(0.5f, 0.5f)}});
    s.joints.push_back({.type = JointType::Pulley, .bodyA = "heavy", .bodyB = "light",
                        .localAnchorA = Vec2{0.0f, 0.5f}, .localAnchorB = Vec2{0.0f, 0.5f},
                        .groundAnchorA = {-2.0f, 9.9f}, .groundAnchorB = {2.0f, 9.9f}});
    s.steps = 60;  // the heavy box falls 1.7 m in a second, then keeps falling: stop before it leaves
    return s;
}

}  // namespace

std::vector<BuiltinScene> coupledJointScenes() {
    return {
        {"gears", "gear joints: two meshing wheels, one weighted, drive a rack", gears},
        {"pulley", "pulley joint: an Atwood machine, 2 kg against 1 kg", pulley},
    };
}

}  // namespace perpdot
