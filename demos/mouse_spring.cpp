#include "mouse_spring.hpp"

#include <algorithm>

namespace perpdot::demo {
namespace {

bool containsLocal(const World& world, ShapeId shape, Vec2 p) {
    switch (world.shapeType(shape)) {
        case ShapeType::Circle: {
            const Circle& c = world.circle(shape);
            return lengthSquared(p - c.center) <= c.radius * c.radius;
        }
        case ShapeType::Polygon: {
            // inside a CCW polygon rounded by r: on the inner side of every edge, give or take r
            const Polygon& poly = world.polygon(shape);
            for (int i = 0; i < poly.count; ++i) {
                const Vec2 a = poly.vertices[i], b = poly.vertices[(i + 1) % poly.count];
                if (perpDot(normalize(b - a), p - a) < -poly.radius) return false;
            }
            return true;
        }
        case ShapeType::Capsule: {
            // within r of the core segment c1–c2
            const Capsule& c = world.capsule(shape);
            const Vec2 e = c.center2 - c.center1;
            const float t = std::clamp(dot(p - c.center1, e) / dot(e, e), 0.0f, 1.0f);
            return lengthSquared(p - (c.center1 + t * e)) <= c.radius * c.radius;
        }
        default: return false;  // segments and chains have no inside
    }
}

}  // namespace

std::optional<BodyId> bodyAt(const World& world, Vec2 p) {
    std::optional<BodyId> hit;
    for (BodyId body : world.bodies()) {
        if (world.bodyType(body) != BodyType::Dynamic) continue;
        const Vec2 local = invTransformPoint(world.transform(body), p);
        const std::vector<ShapeId> shapes = world.shapes(body);
        if (std::any_of(shapes.begin(), shapes.end(), [&](ShapeId s) { return containsLocal(world, s, local); })) hit = body;
    }
    return hit;
}

void MouseSpring::grab(const World& world, BodyId body, Vec2 worldPoint) {
    body_ = body;
    localPoint_ = invTransformPoint(world.transform(body), worldPoint);
    target_ = worldPoint;
}

Vec2 MouseSpring::anchor(const World& world) const { return transformPoint(world.transform(*body_), localPoint_); }

void MouseSpring::applyForce(World& world) const {
    if (!active(world)) return;
    const BodyId body = *body_;
    const Vec2 p = anchor(world);
    const Vec2 r = p - world.worldCenter(body);
    const float inertia = world.rotationalInertia(body);
    const float invEffectiveMass = 1.0f / world.mass(body) + (inertia > 0.0f ? lengthSquared(r) / inertia : 0.0f);
    const float effectiveMass = 1.0f / invEffectiveMass;
    const float omega = 2.0f * pi * hertz;
    const float k = effectiveMass * omega * omega;
    const float c = 2.0f * effectiveMass * dampingRatio * omega;
    const Vec2 force = k * (target_ - p) - c * world.pointVelocity(body, p);
    world.applyForce(body, force, p);
}

}  // namespace perpdot::demo
