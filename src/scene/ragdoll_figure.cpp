#include "scene/ragdoll_figure.hpp"

#include "scene/scene_builders.hpp"

namespace perpdot {

void addRagdoll(Scene& s, Vec2 torso, const std::string& prefix) {
    const float x0 = torso.x, y = torso.y;
    const auto joint = [&](const std::string& a, const std::string& b, Vec2 anchor, float lower, float upper) {
        s.joints.push_back({.type = JointType::Revolute, .bodyA = prefix + a, .bodyB = prefix + b, .anchor = anchor,
                            .enableLimit = true, .lowerAngle = lower, .upperAngle = upper});
    };
    addBody(s, {.name = prefix + "torso", .position = {x0, y}, .shapes = {boxShape(0.25f, 0.5f)}});
    addBody(s, {.name = prefix + "head", .position = {x0, y + 0.8f}, .shapes = {circleShape(0.25f)}});
    joint("torso", "head", {x0, y + 0.55f}, -0.5f, 0.5f);
    for (float side : {-1.0f, 1.0f}) {
        const std::string tag = side < 0 ? "_left" : "_right";
        const float arm = x0 + 0.35f * side, leg = x0 + 0.12f * side;
        addBody(s, {.name = prefix + "upper_arm" + tag, .position = {arm, y + 0.15f}, .shapes = {boxShape(0.1f, 0.3f)}});
        addBody(s, {.name = prefix + "lower_arm" + tag, .position = {arm, y - 0.45f}, .shapes = {boxShape(0.08f, 0.3f)}});
        addBody(s, {.name = prefix + "upper_leg" + tag, .position = {leg, y - 0.85f}, .shapes = {boxShape(0.11f, 0.35f)}});
        addBody(s, {.name = prefix + "lower_leg" + tag, .position = {leg, y - 1.55f}, .shapes = {boxShape(0.09f, 0.35f)}});
        joint("torso", "upper_arm" + tag, {arm, y + 0.45f}, -2.5f, 2.5f);
        // elbows bend one way only, mirrored between the sides
        joint("upper_arm" + tag, "lower_arm" + tag, {arm, y - 0.15f}, side < 0 ? 0.0f : -2.5f, side < 0 ? 2.5f : 0.0f);
        joint("torso", "upper_leg" + tag, {leg, y - 0.5f}, -1.5f, 1.5f);
        joint("upper_leg" + tag, "lower_leg" + tag, {leg, y - 1.2f}, -2.5f, 0.0f);
    }
}

}  // namespace perpdot
