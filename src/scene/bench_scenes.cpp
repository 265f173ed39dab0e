// The large scenes of the benchmarks, built as Box2D v3's benchmark suite builds them (dt = 1/60;
// sleeping off where v3 turns it off, so every step solves every body).
#include <cmath>
#include <string>

#include "scene/builtin_registry.hpp"
#include "perpdot/portable_math.hpp"
#include "scene/scene_builders.hpp"

namespace perpdot {
namespace {

constexpr float degrees = pi / 180.0f;

// 100 boxes in the bottom row: 100·101/2 = 5,050 boxes on a 200 m ground.
Scene largePyramid() {
    Scene s;
    s.steps = 500;
    const int baseCount = 100;
    const float h = 0.5f;
    addGround(s, 100.0f);
    addPyramid(s, baseCount, h, -h * baseCount, 0.0f, false);
    return s;
}

// 20 shelves (segments of one static body), each holding 20 pyramids of base 10: 22,000 boxes.
Scene manyPyramids() {
    Scene s;
    s.steps = 200;
    const int baseCount = 10, rows = 20, columns = 20;
    const float h = 0.5f;
    const float shelfSpacing = 2.0f * h * (baseCount + 1.0f);
    const float shelfWidth = 2.0f * h * columns * (baseCount + 1.0f);
    SceneBody& ground = addBody(s, {.name = "ground", .type = BodyType::Static});
    for (int row = 0; row < rows; ++row)
        ground.shapes.push_back(segmentShape({-0.5f * shelfWidth, row * shelfSpacing}, {0.5f * shelfWidth, row * shelfSpacing}));
    const float baseWidth = 2.0f * h * baseCount;
    for (int row = 0; row < rows; ++row)
        for (int column = 0; column < columns; ++column) {
            const float centerX = -0.5f * shelfWidth + column * (baseWidth + 2.0f * h) + h;
            addPyramid(s, baseCount, h, centerX - 0.5f, row * shelfSpacing, false);
        }
    return s;
}

// A 20 m hollow box (four 1 m thick walls, density 50) turned at 25°/s by a revolute motor about
// its centre, 10 m up, tumbling 45 × 45 = 2,025 boxes of 0.25 m laid out 0.4 m apart inside it.
Scene benchTumbler() {
    Scene s;
    s.steps = 750;
    const Vec2 center{0.0f, 10.0f};
    const float half = 10.0f, wall = 0.5f;
    addBody(s, {.name = "ground", .type = BodyType::Static});
    SceneBody& container = addBody(s, {.name = "container", .position = center, .allowSleep = false,
                                       .shapes = {boxShape(wall, half, {half, 0.0f}), boxShape(wall, half, {-half, 0.0f}),
                                                  boxShape(half, wall, {0.0f, half}), boxShape(half, wall, {0.0f, -half})}});
    for (SceneShape& shape : container.shapes) shape.density = 50.0f;
    SceneJoint motor{.type = JointType::Revolute, .bodyA = "ground", .bodyB = "container", .anchor = center};
    motor.enableMotor = true, motor.motorSpeed = 25.0f * degrees, motor.maxMotorTorque = 1.0e8f;
    s.joints.push_back(motor);
    const int grid = 45;
    const float spacing = 0.4f, start = -0.5f * spacing * grid;
    for (int i = 0; i < grid; ++i)
        for (int j = 0; j < grid; ++j)
            addBody(s, {.position = {start + spacing * j, center.y + start + spacing * i}, .allowSleep = false,
                        .shapes = {boxShape(0.125f, 0.125f)}});
    return s;
}

// Zero gravity: an 8 m box of density 8 at 40 m/s into a touching block of 120 × 80 boxes of
// 0.4 m (9,600), asleep until the box reaches them, as Box2D v3's benchmark builds it. Nothing
// outside acts on the bodies, so their total momentum must stay the box's.
Scene smash() {
    Scene s;
    s.steps = 300;
    s.gravity = {0.0f, 0.0f};
    SceneShape ram = boxShape(4.0f, 4.0f);
    ram.density = 8.0f;
    addBody(s, {.name = "ram", .position = {-20.0f, 0.0f}, .linearVelocity = {40.0f, 0.0f}, .shapes = {ram}});
    const int columns = 120, rows = 80;
    const float d = 0.4f;
    for (int i = 0; i < columns; ++i)
        for (int j = 0; j < rows; ++j)
            addBody(s, {.position = {30.0f + d * i, d * (j - 0.5f * rows)}, .awake = false,
                        .shapes = {boxShape(0.5f * d, 0.5f * d)}});
    return s;
}

// A closed chain loop of radius 40 (360 points, wound clockwise so its one-sided segments face
// inwards) with a 40 m rounded bar turned at 5 rad/s by a revolute motor, stirring 6,000 boxes,
// circles and hexagons. Box2D v3 stirs 3,038 larger, overlapping shapes; these fit their 0.5 m grid.
Scene spinner() {
    Scene s;
    s.steps = 500;
    const Vec2 loopCenter{0.0f, 32.0f};
    const float loopRadius = 40.0f;
    const int points = 360;
    SceneShape loop{.kind = SceneShape::Kind::Chain, .loop = true, .friction = 0.1f};
    for (int i = 0; i < points; ++i) {
        const SinCos a = sinCos(-2.0f * pi * static_cast<float>(i) / points);
        loop.vertices.push_back({loopCenter.x + loopRadius * a.cos, loopCenter.y + loopRadius * a.sin});
    }
    addBody(s, {.name = "container", .type = BodyType::Static, .shapes = {loop}});

    const Vec2 pivot{0.0f, 12.0f};
    const float barHalfWidth = 0.4f, barHalfLength = 20.0f;
    SceneShape bar = polygonShape({{-barHalfWidth, -barHalfLength}, {barHalfWidth, -barHalfLength},
                                   {barHalfWidth, barHalfLength}, {-barHalfWidth, barHalfLength}},
                                  0.2f);
    bar.friction = 0.0f;
    addBody(s, {.name = "bar", .position = pivot, .allowSleep = false, .shapes = {bar}});
    SceneJoint motor{.type = JointType::Revolute, .bodyA = "container", .bodyB = "bar", .anchor = pivot};
    motor.enableMotor = true, motor.motorSpeed = 5.0f, motor.maxMotorTorque = 40000.0f;
    s.joints.push_back(motor);

    std::vector<Vec2> hexagon;
    for (int k = 0; k < 6; ++k) {
        const SinCos a = sinCos(k * pi / 3.0f);
        hexagon.push_back({0.22f * a.cos, 0.22f * a.sin});
    }
    const SceneShape kinds[] = {boxShape(0.2f, 0.2f), circleShape(0.2f), polygonShape(hexagon)};
    const int count = 6000;
    const float spacing = 0.5f, halfRow = 23.0f, barClearance = 0.75f;
    float x = -halfRow, y = 2.0f;
    for (int i = 0; i < count; ++i) {
        SceneShape shape = kinds[i % 3];
        shape.friction = 0.1f, shape.restitution = 0.1f, shape.density = 0.25f;
        addBody(s, {.position = {x, y}, .allowSleep = false, .shapes = {shape}});
        do {  // next grid point, leaving the upright bar free
            x += spacing;
            if (x > halfRow) x = -halfRow, y += spacing;
        } while (std::abs(x - pivot.x) < barClearance);
    }
    return s;
}

// The joint types other than revolute in bulk, in mixed blocks: 24 cantilever beams of 20 welded
// segments (every other beam's welds springs), 400 pistons on vertical prismatic rails (by fours:
// a limit, a motor up and a limit, a motor down and a limit, free and weightless) and 80 carts on
// wheel joints (a motor on the rear wheel, every other cart sprung) driving along the ground.
Scene jointRack() {
    Scene s;
    s.steps = 500;
    addGround(s, 200.0f);
    auto name = [](const char* kind, int k, int i = -1) {
        std::string text = kind;
        text += std::to_string(k);
        if (i >= 0) {
            text += '_';
            text += std::to_string(i);
        }
        return text;
    };

    SceneBody& wall = addBody(s, {.name = "wall", .type = BodyType::Static});
    const int beams = 24, segments = 20;
    const float segment = 0.5f;
    SceneShape plank = boxShape(0.5f * segment, 0.1f);
    plank.filter.category = 0x0004;  // the beams pass through each other
    plank.filter.mask = 0xFFFB;
    for (int k = 0; k < beams; ++k) {
        const Vec2 root{-120.0f + 10.0f * k, 40.0f + 3.0f * (k % 2)};
        wall.shapes.push_back(boxShape(0.2f, 0.5f, root - Vec2{0.2f, 0.0f}));
    }
    for (int k = 0; k < beams; ++k) {
        const Vec2 root{-120.0f + 10.0f * k, 40.0f + 3.0f * (k % 2)};
        for (int i = 0; i < segments; ++i) {
            addBody(s, {.name = name("beam", k, i), .position = root + Vec2{segment * (i + 0.5f), 0.0f}, .allowSleep = false,
                        .shapes = {plank}});
            SceneJoint weld{.type = JointType::Weld, .bodyA = i == 0 ? "wall" : name("beam", k, i - 1), .bodyB = name("beam", k, i),
                            .anchor = root + Vec2{segment * i, 0.0f}};
            if (k % 2 == 1) weld.hertz = 8.0f, weld.dampingRatio = 0.5f;
            s.joints.push_back(weld);
        }
    }

    addBody(s, {.name = "rails", .type = BodyType::Static});
    const int pistons = 400;
    for (int k = 0; k < pistons; ++k) {
        const int row = k / 200, column = k % 200;
        const Vec2 p{-100.0f + static_cast<float>(column), 20.0f + 4.0f * static_cast<float>(row)};
        const int kind = k % 4;
        addBody(s, {.name = name("piston", k), .position = p, .gravityScale = kind == 3 ? 0.0f : 1.0f, .allowSleep = false,
                    .shapes = {boxShape(0.3f, 0.3f)}});
        SceneJoint rail{.type = JointType::Prismatic, .bodyA = "rails", .bodyB = name("piston", k), .anchor = p};
        rail.axis = {0.0f, 1.0f};
        if (kind != 3) rail.enableLimit = true, rail.lower = -0.5f, rail.upper = 0.5f;
        if (kind == 1 || kind == 2) rail.enableMotor = true, rail.motorSpeed = kind == 1 ? 1.0f : -1.0f, rail.maxMotorForce = 20.0f;
        s.joints.push_back(rail);
    }

    const int carts = 80;
    const float y = 1.2f;
    for (int k = 0; k < carts; ++k) {
        const float x = -140.0f + 3.5f * k;
        addBody(s, {.name = name("cart", k), .position = {x, y}, .allowSleep = false, .shapes = {boxShape(1.2f, 0.25f)}});
        for (float side : {-1.0f, 1.0f}) {
            const std::string wheelName = name(side < 0 ? "rear" : "front", k);
            SceneShape wheel = circleShape(0.4f);
            wheel.friction = 0.9f;
            const Vec2 axle{x + 0.9f * side, y - 0.6f};
            addBody(s, {.name = wheelName, .position = axle, .allowSleep = false, .shapes = {wheel}});
            SceneJoint j{.type = JointType::Wheel, .bodyA = name("cart", k), .bodyB = wheelName, .anchor = axle};
            j.axis = {0.0f, 1.0f};
            if (k % 2 == 1) j.hertz = 4.0f, j.dampingRatio = 0.7f;
            if (side < 0) j.enableMotor = true, j.motorSpeed = -6.0f, j.maxMotorTorque = 30.0f;
            s.joints.push_back(j);
        }
    }
    return s;
}

// Distance joints in bulk, for their four-wide rows: 32 ropes of 16 rigid links (rods, hertz 0)
// released horizontal from a ceiling, every fourth ending in a heavy ball; and 12 soft blobs of
// 5 × 5 discs held by distance joints along the grid's edges and diagonals (72 each), dropped on
// the ground: springs of 4 or 8 Hz kept between 80 % and 120 % of their rest lengths by the min
// and max rows, every fourth blob a rigid truss. Sleep off.
Scene distanceNet() {
    Scene s;
    s.steps = 500;
    addGround(s, 200.0f);
    addBody(s, {.name = "ceiling", .type = BodyType::Static});
    auto name = [](const char* kind, int k, int i) { return kind + std::to_string(k) + '_' + std::to_string(i); };

    const int ropes = 32, links = 16;
    const float link = 0.4f;
    SceneShape bead = circleShape(0.1f);
    bead.filter.category = 0x0008;  // the ropes pass through each other
    bead.filter.mask = 0xFFF7;
    for (int k = 0; k < ropes; ++k) {
        const Vec2 top{-100.0f + 6.5f * static_cast<float>(k), 30.0f};
        for (int i = 0; i < links; ++i) {
            const Vec2 p = top + Vec2{link * static_cast<float>(i + 1), 0.0f};
            SceneShape shape = bead;
            if (i == links - 1 && k % 4 == 0) shape.radius = 0.3f, shape.density = 5.0f;
            addBody(s, {.name = name("rope", k, i), .position = p, .allowSleep = false, .shapes = {shape}});
            s.joints.push_back({.type = JointType::Distance, .bodyA = i == 0 ? "ceiling" : name("rope", k, i - 1),
                                .bodyB = name("rope", k, i), .anchor = p - Vec2{link, 0.0f}, .anchorB = p});
        }
    }

    const int blobs = 12, side = 5;
    const float spacing = 0.4f;
    for (int k = 0; k < blobs; ++k) {
        const Vec2 corner{-100.0f + 16.0f * static_cast<float>(k), 3.0f + 2.0f * static_cast<float>(k % 3)};
        auto at = [&](int x, int y) { return corner + Vec2{spacing * static_cast<float>(x), spacing * static_cast<float>(y)}; };
        for (int y = 0; y < side; ++y)
            for (int x = 0; x < side; ++x)
                addBody(s, {.name = name("blob", k, y * side + x), .position = at(x, y), .allowSleep = false,
                            .shapes = {circleShape(0.15f)}});
        auto tie = [&](int x0, int y0, int x1, int y1) {
            SceneJoint j{.type = JointType::Distance, .bodyA = name("blob", k, y0 * side + x0), .bodyB = name("blob", k, y1 * side + x1),
                         .anchor = at(x0, y0), .anchorB = at(x1, y1)};
            if (k % 4 != 3) {
                const float rest = distance(at(x0, y0), at(x1, y1));
                j.hertz = k % 2 == 0 ? 4.0f : 8.0f, j.dampingRatio = 0.3f;
                j.minLength = 0.8f * rest, j.maxLength = 1.2f * rest;
            }
            s.joints.push_back(j);
        };
        for (int y = 0; y < side; ++y)
            for (int x = 0; x < side; ++x) {
                if (x + 1 < side) tie(x, y, x + 1, y);
                if (y + 1 < side) tie(x, y, x, y + 1);
                if (x + 1 < side && y + 1 < side) {
                    tie(x, y, x + 1, y + 1);
                    tie(x + 1, y, x, y + 1);
                }
            }
    }
    return s;
}

// Motor joints in bulk, for their four-wide rows: 20 × 20 boxes held by motor joints from the
// ground, each driven to a point 0.5 m from where it starts and turned to an angle of its own (by
// fours: a force above its weight, one below it, whose cap then holds, and as much torque as it
// needs or a small one); and 100 carts on the ground, each carrying a box held by a motor joint
// 1 m above it. Sleep off.
Scene motorSwarm() {
    Scene s;
    s.steps = 500;
    addGround(s, 100.0f);
    const int grid = 20;
    for (int k = 0; k < grid * grid; ++k) {
        const int row = k / grid, column = k % grid;
        const Vec2 p{-15.0f + 1.5f * static_cast<float>(column), 4.0f + 1.5f * static_cast<float>(row)};
        const std::string name = "hover" + std::to_string(k);
        addBody(s, {.name = name, .position = p, .allowSleep = false, .shapes = {boxShape(0.3f, 0.3f)}});
        const SinCos phase = sinCos(0.7f * static_cast<float>(k));
        SceneJoint motor{.type = JointType::Motor, .bodyA = "ground", .bodyB = name};
        motor.linearOffset = p + 0.5f * Vec2{phase.cos, phase.sin};
        motor.angularOffset = 0.4f * static_cast<float>(k % 5 - 2);
        motor.maxForce = k % 2 == 0 ? 20.0f : 2.0f;  // a box weighs 3.6 N
        motor.maxTorque = (k / 2) % 2 == 0 ? 10.0f : 0.05f;
        s.joints.push_back(motor);
    }
    const int carts = 100;
    for (int k = 0; k < carts; ++k) {
        const float x = -90.0f + 1.8f * static_cast<float>(k);
        const std::string cart = "cart" + std::to_string(k), load = "load" + std::to_string(k);
        addBody(s, {.name = cart, .position = {x, 0.25f}, .allowSleep = false, .shapes = {boxShape(0.6f, 0.25f)}});
        addBody(s, {.name = load, .position = {x, 1.25f}, .allowSleep = false, .shapes = {boxShape(0.2f, 0.2f)}});
        SceneJoint motor{.type = JointType::Motor, .bodyA = cart, .bodyB = load};
        motor.linearOffset = {0.0f, 1.0f};
        motor.maxForce = 10.0f, motor.maxTorque = 1.0f;
        s.joints.push_back(motor);
    }
    return s;
}

// A drum turning at 25°/s, tumbling 90 × 90 = 8,100 boxes of 0.2 m, as Box2D v3's "washer"
// benchmark builds it. The drum is a kinematic body 10 m up (drifting at (1, -2) mm/s, as v3's
// does): a ring of 36 blocks between radii 16 and 18 m, each spanning 12° so that neighbours
// overlap by 2°, and every 90° a paddle between radii 14 and 16 m. Sleep on, 500 steps.
Scene washer() {
    Scene s;
    s.steps = 500;
    const Vec2 center{0.0f, 10.0f};
    const float r0 = 14.0f, r1 = 16.0f, r2 = 18.0f, block = 10.0f * degrees, overlap = degrees;
    const auto direction = [](float angle) {
        const SinCos turned = sinCos(angle);
        return Vec2{turned.cos, turned.sin};
    };
    SceneBody drum{.name = "container", .type = BodyType::Kinematic, .position = center, .linearVelocity = {0.001f, -0.002f},
                   .angularVelocity = 25.0f * degrees, .allowSleep = false};
    for (int i = 0; i < 36; ++i) {
        const float a = block * static_cast<float>(i), b = block * static_cast<float>(i + 1);
        const Vec2 u1 = direction(a - overlap), u2 = direction(b + overlap);
        drum.shapes.push_back(polygonShape({r1 * u1, r2 * u1, r2 * u2, r1 * u2}));
        if (i % 9 == 0) drum.shapes.push_back(polygonShape({r0 * direction(a), r1 * direction(a), r1 * direction(b), r0 * direction(b)}));
    }
    addBody(s, std::move(drum));
    const int grid = 90;
    const float half = 0.1f, spacing = 2.1f * half, start = -1.1f * half * grid;
    for (int i = 0; i < grid; ++i)
        for (int j = 0; j < grid; ++j)
            addBody(s, {.position = {start + spacing * j, center.y + start + spacing * i}, .shapes = {boxShape(half, half)}});
    return s;
}

// 20 × 150 = 3,000 bodies, each a compound of two crossed triangles (density 1, friction 0.5),
// dropped in columns 2 m apart, 2.25 m above each other, into a bin 80 m wide with walls 100 m
// high, as Box2D v3's "compounds" benchmark builds them. A static segment 80 m below the floor
// (v3 puts it on the bin's body; here it is a body of its own, the same physics) catches what
// leaves the bin. Sleep on, 500 steps.
Scene compounds() {
    Scene s;
    s.steps = 500;
    addBin(s, 40, 100);
    addBody(s, {.name = "catcher", .type = BodyType::Static, .shapes = {segmentShape({-800.0f, -80.0f}, {800.0f, -80.0f})}});
    SceneShape left = polygonShape({{-1.0f, 0.0f}, {0.5f, 1.0f}, {0.0f, 2.0f}});
    SceneShape right = polygonShape({{1.0f, 0.0f}, {-0.5f, 1.0f}, {0.0f, 2.0f}});
    left.friction = right.friction = 0.5f;
    const int columns = 20, rows = 150;
    const float spacing = 2.0f, rowSpacing = 2.25f, firstX = 1.0f - 0.5f * spacing * columns, firstY = 5.575f;
    float side = 0.25f;  // alternate bodies sit a quarter metre right and left of their column
    for (int i = 0; i < columns; ++i)
        for (int j = 0; j < rows; ++j) {
            addBody(s, {.position = {firstX + spacing * i + side, firstY + rowSpacing * j}, .shapes = {left, right}});
            side = -side;
        }
    return s;
}

}  // namespace

std::vector<BuiltinScene> benchScenes() {
    return {
        {"large_pyramid", "benchmark: a pyramid 100 boxes wide (5,050 boxes), sleep off, 500 steps", largePyramid},
        {"many_pyramids", "benchmark: 20 x 20 pyramids of base 10 (22,000 boxes) on 20 shelves, sleep off, 200 steps",
         manyPyramids},
        {"bench_tumbler",
         "benchmark: a 20 m hollow box turned at 25 deg/s by a revolute motor tumbles 2,025 boxes, sleep off, 750 steps",
         benchTumbler},
        {"smash", "benchmark: zero gravity, an 8 m box at 40 m/s smashes a block of 9,600 boxes that sleep until it "
         "hits (as in Box2D v3's benchmark), 300 steps",
         smash},
        ragdollRainScene(),
        {"spinner",
         "benchmark: a 40 m bar turned at 5 rad/s by a motor stirs 6,000 shapes in a chain loop, sleep off, 500 steps",
         spinner},
        {"joint_rack",
         "benchmark: 480 welded beam segments, 400 pistons on prismatic rails, 80 carts on wheel joints, sleep off, 500 steps",
         jointRack},
        {"distance_net",
         "benchmark: 32 ropes of 16 rigid distance links, 12 soft blobs of 25 discs on 864 springs with min and max "
         "lengths (every fourth blob rigid), sleep off, 500 steps",
         distanceNet},
        {"motor_swarm",
         "benchmark: 400 boxes driven by motor joints from the ground, 100 carts carrying a box on a motor joint, sleep "
         "off, 500 steps",
         motorSwarm},
        {"washer", "benchmark: a kinematic drum with paddles turning at 25 deg/s tumbles 8,100 boxes of 0.2 m, 500 steps",
         washer},
        {"compounds",
         "benchmark: 3,000 compounds of two triangles fall in 20 columns into a bin 80 m wide, 500 steps", compounds},
        junkyardScene(),
    };
}

}  // namespace perpdot
