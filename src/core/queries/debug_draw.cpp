// debugDraw: the World describes its state through the DebugDraw interface, using only the
// public getters, so any viewer (SDL, a test recorder) sees exactly what a user of the API sees.
#include "perpdot/debug_draw.hpp"

#include <algorithm>
#include <vector>

#include "perpdot/world.hpp"

namespace perpdot {
namespace {

// Palette: one colour per body type; sleeping bodies are dimmed towards grey.
constexpr Color staticColor{128, 178, 128};
constexpr Color kinematicColor{120, 140, 230};
constexpr Color dynamicColor{235, 150, 90};
constexpr Color sensorColor{230, 220, 90};
constexpr Color centerColor{240, 240, 240};
constexpr Color velocityColor{90, 220, 230};
constexpr Color aabbColor{200, 90, 200};
constexpr Color contactColor{250, 80, 80};
constexpr Color normalColor{250, 250, 120};
constexpr Color impulseColor{250, 160, 40};
constexpr Color frictionColor{120, 250, 120};
constexpr Color jointColor{120, 200, 200};

// What a velocity arrow shows: the distance the centre of mass covers in this many seconds.
constexpr float velocityArrowSeconds = 0.1f;
// Contact normals are drawn this long (m); the largest normal impulse this frame is drawn this long.
constexpr float normalLength = 0.3f;
constexpr float largestImpulseLength = 0.6f;

Color dimmed(Color c) {
    const auto toGrey = [](uint8_t v) { return static_cast<uint8_t>((v + 128) / 3); };
    return {toGrey(c.r), toGrey(c.g), toGrey(c.b), c.a};
}

Color bodyColor(const World& world, BodyId body, const DebugDrawOptions& options) {
    Color c = dynamicColor;
    switch (world.bodyType(body)) {
        case BodyType::Static: c = staticColor; break;
        case BodyType::Kinematic: c = kinematicColor; break;
        case BodyType::Dynamic: c = dynamicColor; break;
    }
    const bool sleeping = world.bodyType(body) != BodyType::Static && !world.isAwake(body);
    return options.dimSleeping && sleeping ? dimmed(c) : c;
}

void drawShape(const World& world, ShapeId shape, const Transform& xf, Color color, DebugDraw& draw) {
    const bool sensor = world.isSensor(shape);
    if (sensor) color = sensorColor;
    switch (world.shapeType(shape)) {
        case ShapeType::Circle: {
            const Circle& circle = world.circle(shape);
            const Vec2 center = transformPoint(xf, circle.center);
            if (sensor) draw.drawCircle(center, circle.radius, color);
            else draw.drawSolidCircle(center, circle.radius, xf.q, color);
            break;
        }
        case ShapeType::Polygon: {
            const Polygon& polygon = world.polygon(shape);
            Vec2 vertices[maxPolygonVertices];
            for (int i = 0; i < polygon.count; ++i) vertices[i] = transformPoint(xf, polygon.vertices[i]);
            const std::span<const Vec2> span(vertices, polygon.count);
            if (sensor) draw.drawPolygon(span, color);
            else draw.drawSolidPolygon(span, polygon.radius, color);
            break;
        }
        case ShapeType::Capsule: {
            // A 2-vertex polygon rounded by the radius: two half-discs joined by the sides.
            const Capsule& capsule = world.capsule(shape);
            const Vec2 centers[2] = {transformPoint(xf, capsule.center1), transformPoint(xf, capsule.center2)};
            if (sensor) draw.drawPolygon(centers, color);
            else draw.drawSolidPolygon(centers, capsule.radius, color);
            break;
        }
        case ShapeType::Segment: {
            const Segment& segment = world.segment(shape);
            draw.drawSegment(transformPoint(xf, segment.v1), transformPoint(xf, segment.v2), color);
            break;
        }
        case ShapeType::Chain: {
            const Chain& chain = world.chain(shape);
            const size_t n = chain.vertices.size();
            const size_t edges = chain.loop ? n : n - 1;
            for (size_t i = 0; i < edges && n >= 2; ++i) {
                draw.drawSegment(transformPoint(xf, chain.vertices[i]),
                                 transformPoint(xf, chain.vertices[(i + 1) % n]), color);
            }
            break;
        }
    }
}

void drawAABB(const AABB& box, DebugDraw& draw) {
    const Vec2 corners[4] = {box.lower, {box.upper.x, box.lower.y}, box.upper, {box.lower.x, box.upper.y}};
    draw.drawPolygon(corners, aabbColor);
}

// Centre of mass as a point plus the body's axes, so the angle θ is visible too.
void drawCenterOfMass(const World& world, BodyId body, DebugDraw& draw) {
    const Vec2 cm = world.worldCenter(body);
    const Rot q = world.transform(body).q;
    constexpr float axisLength = 0.25f;
    draw.drawSegment(cm, cm + axisLength * rotate(q, {1.0f, 0.0f}), Color{230, 70, 70});
    draw.drawSegment(cm, cm + axisLength * rotate(q, {0.0f, 1.0f}), Color{70, 230, 70});
    draw.drawPoint(cm, 5.0f, centerColor);
}

void drawContacts(const World& world, const DebugDrawOptions& options, DebugDraw& draw) {
    const std::vector<ContactData> contacts = world.contacts();
    float largestImpulse = 0.0f;
    for (const ContactData& c : contacts) {
        for (int i = 0; i < c.pointCount; ++i) largestImpulse = std::max(largestImpulse, c.points[i].normalImpulse);
    }
    const float impulseScale = largestImpulse > 0.0f ? largestImpulseLength / largestImpulse : 0.0f;
    for (const ContactData& c : contacts) {
        const Vec2 tangent = perp(c.normal);  // the friction direction of DESIGN.md
        for (int i = 0; i < c.pointCount; ++i) {
            const ContactPoint& p = c.points[i];
            if (options.contacts) {
                draw.drawPoint(p.point, 6.0f, contactColor);
                draw.drawSegment(p.point, p.point + normalLength * c.normal, normalColor);
            }
            if (options.contactImpulses) {
                draw.drawSegment(p.point, p.point + (impulseScale * p.normalImpulse) * c.normal, impulseColor);
                draw.drawSegment(p.point, p.point + (impulseScale * p.tangentImpulse) * tangent, frictionColor);
            }
        }
    }
}

// Box2D's joint picture: body origin -> anchor A -> anchor B <- body origin; a pulley's ropes run
// from each anchor up to its ground anchor, and the ground anchors are joined.
void drawJoint(const World& world, JointId joint, DebugDraw& draw) {
    const Vec2 pA = world.jointAnchorA(joint);
    const Vec2 pB = world.jointAnchorB(joint);
    if (world.jointType(joint) == JointType::Pulley) {
        const auto [groundA, groundB] = world.pulleyGroundAnchors(joint);
        draw.drawSegment(groundA, pA, jointColor);
        draw.drawSegment(groundB, pB, jointColor);
        draw.drawSegment(groundA, groundB, jointColor);
        draw.drawPoint(pA, 4.0f, jointColor);
        draw.drawPoint(pB, 4.0f, jointColor);
        return;
    }
    const BodyId a = world.jointBodyA(joint);
    const BodyId b = world.jointBodyB(joint);
    if (world.jointType(joint) != JointType::Mouse) draw.drawSegment(world.position(a), pA, jointColor);
    draw.drawSegment(pA, pB, jointColor);
    draw.drawSegment(world.position(b), pB, jointColor);
    draw.drawPoint(pA, 4.0f, jointColor);
    draw.drawPoint(pB, 4.0f, jointColor);
}

}  // namespace

void debugDraw(const World& world, DebugDraw& draw, const DebugDrawOptions& options) {
    const std::vector<BodyId> bodies = world.bodies();
    for (BodyId body : bodies) {
        const Transform xf = world.transform(body);
        const Color color = bodyColor(world, body, options);
        for (ShapeId shape : world.shapes(body)) {
            if (options.shapes) drawShape(world, shape, xf, color, draw);
            if (options.aabbs) drawAABB(world.aabb(shape), draw);
        }
    }
    if (options.joints) {
        for (JointId joint : world.joints()) drawJoint(world, joint, draw);
    }
    for (BodyId body : bodies) {
        if (world.bodyType(body) == BodyType::Static) continue;
        if (options.centerOfMass) drawCenterOfMass(world, body, draw);
        if (options.velocities) {
            const Vec2 cm = world.worldCenter(body);
            draw.drawSegment(cm, cm + velocityArrowSeconds * world.linearVelocity(body), velocityColor);
        }
    }
    if (options.contacts || options.contactImpulses) drawContacts(world, options, draw);
}

}  // namespace perpdot
