#include "box2d_overlay.hpp"

#include <algorithm>

namespace perpdot::demo {
namespace {

constexpr Color box2dColor{255, 255, 255, 200};
constexpr int recordAhead = 600;  // steps recorded beyond the current one each time

Polygon scenePolygon(const SceneShape& s) {
    return s.kind == SceneShape::Kind::Box ? makeBox(s.halfExtents.x, s.halfExtents.y, s.center, s.angle)
                                           : makePolygon(s.vertices, s.radius);
}

}  // namespace

void drawSceneShape(DebugDraw& draw, const SceneShape& s, const Transform& xf, Color color) {
    switch (s.kind) {
        case SceneShape::Kind::Circle:
            draw.drawCircle(transformPoint(xf, s.center), s.radius, color);
            draw.drawSegment(transformPoint(xf, s.center), transformPoint(xf, s.center + Vec2{s.radius, 0.0f}), color);
            break;
        case SceneShape::Kind::Box:
        case SceneShape::Kind::Polygon: {
            const Polygon p = scenePolygon(s);
            Vec2 vertices[maxPolygonVertices];
            for (int i = 0; i < p.count; ++i) vertices[i] = transformPoint(xf, p.vertices[i]);
            draw.drawPolygon(std::span<const Vec2>(vertices, p.count), color);
            break;
        }
        case SceneShape::Kind::Segment: draw.drawSegment(transformPoint(xf, s.v1), transformPoint(xf, s.v2), color); break;
        case SceneShape::Kind::Capsule: {
            // outline: the two cap circles and the two sides
            const Vec2 c1 = transformPoint(xf, s.v1), c2 = transformPoint(xf, s.v2);
            const Vec2 side = s.radius * perp(normalize(c2 - c1));
            draw.drawCircle(c1, s.radius, color);
            draw.drawCircle(c2, s.radius, color);
            draw.drawSegment(c1 + side, c2 + side, color);
            draw.drawSegment(c1 - side, c2 - side, color);
            break;
        }
        case SceneShape::Kind::Chain: {
            const size_t n = s.vertices.size();
            for (size_t i = 0; n >= 2 && i < (s.loop ? n : n - 1); ++i) {
                draw.drawSegment(transformPoint(xf, s.vertices[i]), transformPoint(xf, s.vertices[(i + 1) % n]), color);
            }
            break;
        }
    }
}

void Box2DOverlay::update(const SceneWorld& sim) {
    const bool anyMoving = std::any_of(sim.scene.bodies.begin(), sim.scene.bodies.end(),
                                       [](const SceneBody& b) { return b.type != BodyType::Static; });
    if (!anyMoving) return;
    if (sim.stepIndex >= trajectory_.frameCount()) {
        trajectory_ = crosscheck::record(sim.scene, crosscheck::Engine::Box2D, sim.stepIndex + recordAhead);
    }
    frame_ = sim.stepIndex;
    maxError_ = 0.0f;
    worstBody_.clear();
    int moving = 0;  // the trajectory lists the non-static bodies in scene order
    for (size_t i = 0; i < sim.scene.bodies.size(); ++i) {
        if (sim.scene.bodies[i].type == BodyType::Static) continue;
        const float error = distance(sim.world.position(sim.bodies[i]), trajectory_.at(frame_, moving++).position);
        if (error > maxError_ || worstBody_.empty()) {
            maxError_ = error;
            worstBody_ = sim.scene.bodies[i].name;
        }
    }
}

void Box2DOverlay::draw(DebugDraw& draw, const SceneWorld& sim) const {
    if (frame_ >= trajectory_.frameCount()) return;
    int moving = 0;
    for (const SceneBody& body : sim.scene.bodies) {
        if (body.type == BodyType::Static) continue;
        const crosscheck::BodyState& state = trajectory_.at(frame_, moving++);
        const Transform xf{state.position, Rot::fromAngle(state.angle)};
        for (const SceneShape& shape : body.shapes) drawSceneShape(draw, shape, xf, box2dColor);
    }
}

}  // namespace perpdot::demo
