#include "scene/scene_builders.hpp"

#include <utility>

#include "scene/scene_limits.hpp"

namespace perpdot {

SceneShape boxShape(float hx, float hy, Vec2 center, float angle) {
    SceneShape s;
    s.kind = SceneShape::Kind::Box;
    s.halfExtents = {hx, hy};
    s.center = center;
    s.angle = angle;
    return s;
}

SceneShape circleShape(float radius, Vec2 center) {
    SceneShape s;
    s.kind = SceneShape::Kind::Circle;
    s.radius = radius;
    s.center = center;
    return s;
}

SceneShape segmentShape(Vec2 v1, Vec2 v2) {
    SceneShape s;
    s.kind = SceneShape::Kind::Segment;
    s.v1 = v1;
    s.v2 = v2;
    return s;
}

SceneShape polygonShape(std::vector<Vec2> vertices, float radius) {
    SceneShape s;
    s.kind = SceneShape::Kind::Polygon;
    s.vertices = std::move(vertices);
    s.radius = radius;
    return s;
}

SceneShape capsuleShape(Vec2 center1, Vec2 center2, float radius) {
    SceneShape s;
    s.kind = SceneShape::Kind::Capsule;
    s.v1 = center1;
    s.v2 = center2;
    s.radius = radius;
    return s;
}

SceneBody& addBody(Scene& scene, SceneBody body) {
    if (body.name.empty()) body.name = defaultBodyName(scene.bodies.size());
    scene.bodies.push_back(std::move(body));
    return scene.bodies.back();
}

SceneBody& addGround(Scene& scene, float halfWidth, float top) {
    return addBody(scene, {.name = "ground", .type = BodyType::Static, .position = {0.0f, top - 1.0f},
                           .shapes = {boxShape(halfWidth, 1.0f)}});
}

SceneBody& addBin(Scene& scene, int halfSpan, int wallBoxes) {
    SceneBody& bin = addBody(scene, {.name = "ground", .type = BodyType::Static});
    for (int i = -halfSpan; i <= halfSpan; ++i) bin.shapes.push_back(boxShape(0.55f, 0.5f, {float(i), 0.0f}));
    for (const float side : {-1.0f, 1.0f})
        for (int i = 1; i <= wallBoxes; ++i) bin.shapes.push_back(boxShape(0.5f, 0.55f, {side * float(halfSpan), float(i)}));
    return bin;
}

void addPyramid(Scene& scene, int baseCount, float h, float leftX, float baseY, bool allowSleep) {
    SceneBody box{.allowSleep = allowSleep, .shapes = {boxShape(h, h)}};
    for (int row = 0; row < baseCount; ++row) {
        // row i holds baseCount - i boxes, shifted right by i half-boxes
        const float y = baseY + (2.0f * row + 1.0f) * h;
        for (int column = row; column < baseCount; ++column) {
            box.position = {leftX + (row + 1.0f) * h + 2.0f * (column - row) * h, y};
            addBody(scene, box);
        }
    }
}

}  // namespace perpdot
