// debugDraw() reports the world's public state faithfully: every shape at its body's transform,
// colours that tell body types and sleep apart, and each optional layer only when asked for.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "perpdot/debug_draw.hpp"
#include "perpdot/error.hpp"
#include "perpdot/world.hpp"

namespace perpdot {
namespace {

// Remembers every call.
struct Recorder final : DebugDraw {
    struct Poly {
        std::vector<Vec2> vertices;
        Color color;
        bool solid;
    };
    struct Line {
        Vec2 a, b;
        Color color;
    };
    std::vector<Poly> polygons;
    std::vector<std::pair<Vec2, float>> circles;  // centre, radius (solid or not)
    std::vector<Line> segments;
    std::vector<Vec2> points;

    void drawPolygon(std::span<const Vec2> v, Color c) override { polygons.push_back({{v.begin(), v.end()}, c, false}); }
    void drawSolidPolygon(std::span<const Vec2> v, float, Color c) override {
        polygons.push_back({{v.begin(), v.end()}, c, true});
    }
    void drawCircle(Vec2 center, float radius, Color) override { circles.push_back({center, radius}); }
    void drawSolidCircle(Vec2 center, float radius, Rot, Color) override { circles.push_back({center, radius}); }
    void drawSegment(Vec2 a, Vec2 b, Color c) override { segments.push_back({a, b, c}); }
    void drawPoint(Vec2 p, float, Color) override { points.push_back(p); }
};

bool sameColor(Color a, Color b) { return a.r == b.r && a.g == b.g && a.b == b.b && a.a == b.a; }

bool hasSegment(const Recorder& r, Vec2 a, Vec2 b, float tolerance = 1e-5f) {
    for (const Recorder::Line& s : r.segments) {
        if (distance(s.a, a) < tolerance && distance(s.b, b) < tolerance) return true;
    }
    return false;
}

struct BoxOnGround : testing::Test {
    World world{WorldDef{}};
    BodyId ground = world.createBody({.type = BodyType::Static, .position = {0.0f, -1.0f}, .linearVelocity = {}});
    BodyId box = world.createBody({.type = BodyType::Dynamic, .position = {1.0f, 3.0f}, .angle = 0.3f,
                                   .linearVelocity = {2.0f, -1.0f}});
    BoxOnGround() {
        world.createShape(ground, {}, makeBox(10.0f, 1.0f));
        world.createShape(box, {}, makeBox(0.5f, 0.25f));
    }
    const Recorder::Poly* solidOf(const Recorder& r, int index) const {
        int seen = 0;
        for (const Recorder::Poly& p : r.polygons) {
            if (p.solid && seen++ == index) return &p;
        }
        return nullptr;
    }
};

TEST_F(BoxOnGround, ShapesAreDrawnAtTheirBodysTransform) {
    Recorder r;
    debugDraw(world, r);
    ASSERT_EQ(r.polygons.size(), 2u);
    const Recorder::Poly* drawnBox = solidOf(r, 1);  // bodies in creation order: ground, box
    ASSERT_NE(drawnBox, nullptr);
    const Polygon& local = world.polygon(world.shapes(box)[0]);
    ASSERT_EQ(drawnBox->vertices.size(), size_t(local.count));
    for (int i = 0; i < local.count; ++i) {
        const Vec2 expected = transformPoint(world.transform(box), local.vertices[i]);
        EXPECT_NEAR(drawnBox->vertices[i].x, expected.x, 1e-5f);
        EXPECT_NEAR(drawnBox->vertices[i].y, expected.y, 1e-5f);
    }
}

TEST_F(BoxOnGround, ColoursTellBodyTypesAndSleepApart) {
    Recorder awake;
    debugDraw(world, awake);
    const Color staticColor = solidOf(awake, 0)->color, dynamicColor = solidOf(awake, 1)->color;
    EXPECT_FALSE(sameColor(staticColor, dynamicColor));

    world.setAwake(box, false);
    Recorder asleep, undimmed;
    debugDraw(world, asleep);
    EXPECT_FALSE(sameColor(solidOf(asleep, 1)->color, dynamicColor));  // dimmed
    EXPECT_TRUE(sameColor(solidOf(asleep, 0)->color, staticColor));
    debugDraw(world, undimmed, {.dimSleeping = false});
    EXPECT_TRUE(sameColor(solidOf(undimmed, 1)->color, dynamicColor));
}

TEST_F(BoxOnGround, LayersAppearOnlyWhenAsked) {
    Recorder none;
    debugDraw(world, none, {.shapes = false, .joints = false});
    EXPECT_TRUE(none.polygons.empty());
    EXPECT_TRUE(none.segments.empty());
    EXPECT_TRUE(none.points.empty());

    // AABB outlines: one closed rectangle per shape, matching World::aabb.
    Recorder boxes;
    debugDraw(world, boxes, {.shapes = false, .aabbs = true});
    ASSERT_EQ(boxes.polygons.size(), 2u);
    const AABB tight = world.aabb(world.shapes(box)[0]);
    EXPECT_EQ(boxes.polygons[1].vertices[0], tight.lower);
    EXPECT_EQ(boxes.polygons[1].vertices[2], tight.upper);

    // Velocity: from the centre of mass along v (0.1 s of travel); none for the static ground.
    Recorder velocity;
    debugDraw(world, velocity, {.shapes = false, .velocities = true});
    const Vec2 cm = world.worldCenter(box);
    EXPECT_EQ(velocity.segments.size(), 1u);
    EXPECT_TRUE(hasSegment(velocity, cm, cm + 0.1f * world.linearVelocity(box)));

    // Centre of mass: a point there, plus the body's axes.
    Recorder center;
    debugDraw(world, center, {.shapes = false, .centerOfMass = true});
    ASSERT_EQ(center.points.size(), 1u);
    EXPECT_EQ(center.points[0], cm);
}

TEST_F(BoxOnGround, ContactPointsAndNormalsFollowTheWorldsContacts) {
    world.setTransform(box, {1.0f, 0.3f}, 0.0f);  // resting on the ground
    world.setLinearVelocity(box, {});
    for (int i = 0; i < 30; ++i) world.step(1.0f / 60.0f);
    const std::vector<ContactData> contacts = world.contacts();
    ASSERT_EQ(contacts.size(), 1u);
    ASSERT_EQ(contacts[0].pointCount, 2);

    Recorder r;
    debugDraw(world, r, {.shapes = false, .contacts = true, .contactImpulses = true});
    ASSERT_EQ(r.points.size(), 2u);
    for (int i = 0; i < 2; ++i) {
        const ContactPoint& p = contacts[0].points[i];
        EXPECT_EQ(r.points[i], p.point);
        EXPECT_TRUE(hasSegment(r, p.point, p.point + 0.3f * contacts[0].normal));  // the normal
    }
    // Impulse arrows along the normal, the larger impulse drawn longer.
    std::vector<float> lengths;
    for (const Recorder::Line& s : r.segments) {
        const Vec2 d = s.b - s.a;
        const bool alongNormal = length(d) > 1e-6f && std::abs(perpDot(d, contacts[0].normal)) < 1e-5f;
        if (alongNormal && std::abs(length(d) - 0.3f) > 1e-4f) lengths.push_back(length(d));
    }
    ASSERT_EQ(lengths.size(), 2u);
    const float j0 = contacts[0].points[0].normalImpulse, j1 = contacts[0].points[1].normalImpulse;
    EXPECT_GT(j0 + j1, 0.0f);
    EXPECT_EQ(lengths[0] > lengths[1], j0 > j1);
}

TEST_F(BoxOnGround, JointsAreLinesBetweenTheirAnchors) {
    const Vec2 pivot{1.0f, 4.0f};
    const JointId joint = world.createJoint(RevoluteJointDef{.bodyA = ground, .bodyB = box,
                                                             .localAnchorA = invTransformPoint(world.transform(ground), pivot),
                                                             .localAnchorB = invTransformPoint(world.transform(box), pivot)});
    Recorder r;
    debugDraw(world, r, {.shapes = false});
    EXPECT_TRUE(hasSegment(r, world.jointAnchorA(joint), world.jointAnchorB(joint)));
    EXPECT_TRUE(hasSegment(r, world.position(box), world.jointAnchorB(joint)));
    Recorder hidden;
    debugDraw(world, hidden, {.shapes = false, .joints = false});
    EXPECT_TRUE(hidden.segments.empty());
}

// A pulley is drawn as Box2D draws it: each rope from its ground anchor down to its body's anchor,
// and the ground anchors joined.
TEST_F(BoxOnGround, APulleysRopesRunFromItsGroundAnchors) {
    const BodyId other = world.createBody({.type = BodyType::Dynamic, .position = {4.0f, 3.0f}, .linearVelocity = {}});
    world.createShape(other, {}, makeBox(0.5f, 0.5f));
    const Vec2 groundA{1.0f, 6.0f}, groundB{4.0f, 6.0f};
    const JointId pulley = world.createJoint(PulleyJointDef{.bodyA = box, .bodyB = other, .groundAnchorA = groundA,
                                                            .groundAnchorB = groundB, .lengthA = 3.0f, .lengthB = 3.0f});
    EXPECT_EQ(world.pulleyGroundAnchors(pulley), std::make_pair(groundA, groundB));
    EXPECT_THROW((void)world.pulleyGroundAnchors(JointId{}), Error);
    Recorder r;
    debugDraw(world, r, {.shapes = false});
    EXPECT_TRUE(hasSegment(r, groundA, world.jointAnchorA(pulley)));
    EXPECT_TRUE(hasSegment(r, groundB, world.jointAnchorB(pulley)));
    EXPECT_TRUE(hasSegment(r, groundA, groundB));
    EXPECT_FALSE(hasSegment(r, world.jointAnchorA(pulley), world.jointAnchorB(pulley))) << "no straight line between the bodies";
}

}  // namespace
}  // namespace perpdot
