// Feature demos: one-way platforms (pre-solve), a sensor zone, bullets against a thin wall
// (continuous collision), conveyor belts (tangent speed) and a ray-cast laser. The geometry is a
// Scene like any other; what a scene file cannot express lives in each scene's SceneBehaviour.
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <span>
#include <string>
#include <variant>

#include "perpdot/feature_scenes.hpp"
#include "perpdot/portable_math.hpp"
#include "scene/builtin_registry.hpp"
#include "scene/mover_course.hpp"
#include "scene/scene_builders.hpp"

namespace perpdot {
namespace {

// The shapes of the scene bodies whose names start with `prefix`.
std::vector<ShapeId> shapesNamed(const SceneWorld& sw, const std::string& prefix) {
    std::vector<ShapeId> out;
    for (size_t i = 0; i < sw.scene.bodies.size(); ++i)
        if (sw.scene.bodies[i].name.starts_with(prefix))
            for (ShapeId shape : sw.world.shapes(sw.bodies[i])) out.push_back(shape);
    return out;
}

bool contains(const std::vector<ShapeId>& ids, ShapeId id) { return std::find(ids.begin(), ids.end(), id) != ids.end(); }

// Platforms at three heights; balls launched upwards from below pass through them and land on top.
Scene oneWayPlatform() {
    Scene s;
    s.steps = 600;
    addGround(s, 10.0f);
    for (int i = 0; i < 3; ++i) {
        const float x = -5.0f + 5.0f * i;
        addBody(s, {.name = "platform" + std::to_string(i), .type = BodyType::Static, .position = {x, 3.0f + 1.5f * i},
                    .shapes = {boxShape(1.5f, 0.1f)}});
        addBody(s, {.position = {x, 0.5f}, .linearVelocity = {0.0f, 9.0f + 1.0f * i}, .shapes = {circleShape(0.3f)}});
        addBody(s, {.position = {x + 0.8f, 0.5f}, .linearVelocity = {0.0f, 9.0f + 1.0f * i}, .shapes = {boxShape(0.25f, 0.25f)}});
    }
    return s;
}

// Capsules: a row dropped flat (two-point manifolds), one balanced on its end cap (tips over), and
// capsules on a 0.3 rad ramp (tan 0.3 < μ = 0.6: they stay) and a 0.7 rad ramp (they slide).
Scene capsules() {
    Scene s;
    s.steps = 600;
    addGround(s, 12.0f);
    for (int i = 0; i < 4; ++i)
        addBody(s, {.position = {-9.0f + 1.5f * i, 1.0f + 0.6f * i}, .shapes = {capsuleShape({-0.5f, 0.0f}, {0.5f, 0.0f}, 0.25f)}});
    addBody(s, {.name = "upright", .position = {-2.0f, 0.85f}, .angularVelocity = 0.05f,
                .shapes = {capsuleShape({0.0f, -0.6f}, {0.0f, 0.6f}, 0.25f)}});
    for (const float angle : {0.3f, 0.7f}) {
        const float x = angle < 0.5f ? 2.0f : 8.0f;
        const SinCos tilt = sinCos(angle);
        const Vec2 down{tilt.cos, -tilt.sin}, normal{tilt.sin, tilt.cos};
        addBody(s, {.type = BodyType::Static, .position = {x, 3.0f}, .shapes = {segmentShape(-3.0f * down, 3.0f * down)}});
        addBody(s, {.position = Vec2{x, 3.0f} - 1.5f * down + 0.26f * normal, .angle = -angle,
                    .shapes = {capsuleShape({-0.4f, 0.0f}, {0.4f, 0.0f}, 0.25f)}});
    }
    return s;
}

// A platform's contact is enabled only while it pushes the visitor up, i.e. the visitor came from above.
SceneBehaviour oneWayBehaviour() {
    return {.setup = [](SceneWorld& sw) {
                const std::vector<ShapeId> platforms = shapesNamed(sw, "platform");
                for (ShapeId shape : platforms) sw.world.enablePreSolveEvents(shape, true);
                sw.world.setPreSolve([platforms](ShapeId a, ShapeId b, const ContactData& contact) {
                    if (!contains(platforms, a) && !contains(platforms, b)) return true;
                    const float up = contains(platforms, a) ? contact.normal.y : -contact.normal.y;
                    return up > 0.7f;
                });
            },
            .draw = {}};
}

// A sensor zone over the ground; balls and boxes rain through it.
Scene sensorZone() {
    Scene s;
    s.steps = 600;
    addGround(s, 10.0f);
    SceneShape zone = boxShape(3.0f, 1.5f);
    zone.sensor = true;
    addBody(s, {.name = "zone", .type = BodyType::Static, .position = {0.0f, 4.0f}, .shapes = {zone}});
    for (int i = 0; i < 12; ++i) {
        const float x = -2.75f + 0.5f * i;
        addBody(s, {.position = {x, 9.0f + 0.6f * (i % 4)}, .shapes = {i % 2 ? boxShape(0.2f, 0.2f) : circleShape(0.2f)}});
    }
    return s;
}

// Marks every shape inside the zone with a yellow point at its body's origin.
SceneBehaviour sensorZoneBehaviour() {
    return {.setup = {}, .draw = [](const SceneWorld& sw, DebugDraw& draw) {
                for (ShapeId zone : shapesNamed(sw, "zone")) {
                    const Transform xf = sw.world.transform(sw.world.shapeBody(zone));
                    for (ShapeId inside : sw.world.overlapShape(sw.world.polygon(zone), xf))
                        if (inside != zone) draw.drawPoint(sw.world.position(sw.world.shapeBody(inside)), 8.0f, {255, 220, 0, 255});
                }
            }};
}

// 0.1 m bullets at 500 m/s (8 m per step) against a 0.1 m static wall, a thin dynamic plank
// (bullets only), and a fast ordinary ball against the wall (every body against static geometry).
Scene bulletWall() {
    Scene s;
    s.steps = 300;
    s.gravity = {0.0f, -10.0f};
    addGround(s, 20.0f);
    addBody(s, {.name = "wall", .type = BodyType::Static, .position = {10.0f, 2.0f}, .shapes = {boxShape(0.05f, 2.0f)}});
    addBody(s, {.name = "plank", .position = {5.0f, 1.0f}, .shapes = {boxShape(0.05f, 1.0f)}});
    for (int i = 0; i < 3; ++i)
        addBody(s, {.name = "bullet" + std::to_string(i), .position = {-15.0f, 0.6f + 0.6f * i}, .linearVelocity = {500.0f, 0.0f},
                    .bullet = true, .shapes = {circleShape(0.05f)}});
    addBody(s, {.name = "ball", .position = {-15.0f, 3.5f}, .linearVelocity = {300.0f, 0.0f}, .shapes = {circleShape(0.1f)}});
    return s;
}

// Two belts carry boxes right, then left, onto the ground.
Scene conveyor() {
    Scene s;
    s.steps = 900;
    addGround(s, 12.0f);
    addBody(s, {.name = "belt_right", .type = BodyType::Static, .position = {-3.0f, 4.0f}, .angle = -0.1f, .shapes = {boxShape(5.0f, 0.2f)}});
    addBody(s, {.name = "belt_left", .type = BodyType::Static, .position = {3.0f, 1.5f}, .angle = 0.1f, .shapes = {boxShape(5.0f, 0.2f)}});
    for (int i = 0; i < 8; ++i)
        addBody(s, {.position = {-7.5f + 1.0f * i, 5.0f + 0.3f * i}, .shapes = {boxShape(0.3f, 0.3f)}});
    return s;
}

SceneBehaviour conveyorBehaviour() {
    return {.setup = [](SceneWorld& sw) {
                for (ShapeId belt : shapesNamed(sw, "belt_right")) sw.world.setTangentSpeed(belt, 2.0f);
                for (ShapeId belt : shapesNamed(sw, "belt_left")) sw.world.setTangentSpeed(belt, -2.0f);
            },
            .draw = {}};
}

// A turning laser and shapes to light: the beam is a ray cast reflected up to four times.
Scene laser() {
    Scene s;
    s.steps = 1200;
    addGround(s, 10.0f);
    addBody(s, {.type = BodyType::Static, .position = {-9.0f, 5.0f}, .shapes = {boxShape(0.2f, 5.0f)}});
    addBody(s, {.type = BodyType::Static, .position = {9.0f, 5.0f}, .shapes = {boxShape(0.2f, 5.0f)}});
    addBody(s, {.type = BodyType::Kinematic, .position = {3.0f, 5.0f}, .angularVelocity = 0.5f, .shapes = {boxShape(1.5f, 0.2f)}});
    for (int i = 0; i < 6; ++i)
        addBody(s, {.position = {-5.0f + 1.5f * i, 1.0f + 0.5f * i}, .shapes = {i % 2 ? circleShape(0.4f) : boxShape(0.4f, 0.4f)}});
    return s;
}

SceneBehaviour laserBehaviour() {
    return {.setup = {}, .draw = [](const SceneWorld& sw, DebugDraw& draw) {
                const float angle = -0.3f + 0.6f * sinCos(0.01f * static_cast<float>(sw.stepIndex)).sin;
                const SinCos aim = sinCos(angle - 0.4f);
                Vec2 origin{-8.5f, 8.0f}, direction{aim.cos, aim.sin};
                const Color beam{255, 40, 40, 255};
                for (int bounce = 0; bounce < 5; ++bounce) {
                    const Vec2 translation = 30.0f * direction;
                    const std::optional<RayHit> hit = sw.world.castRayClosest(origin, translation);
                    if (!hit) {
                        draw.drawSegment(origin, origin + translation, beam);
                        break;
                    }
                    draw.drawSegment(origin, hit->point, beam);
                    draw.drawPoint(hit->point, 6.0f, beam);
                    // Mirror reflection d' = d − 2 (d·n) n, started a hair off the surface.
                    direction = direction - 2.0f * dot(direction, hit->normal) * hit->normal;
                    origin = hit->point + 1.0e-3f * hit->normal;
                }
            }};
}

// Boxes and balls to sweep shapes through: a ball falls on a ledge, the rest lie still.
Scene shapeCasts() {
    Scene s;
    s.steps = 1200;
    addGround(s, 10.0f);
    addBody(s, {.type = BodyType::Static, .position = {-2.0f, 3.0f}, .angle = 0.3f, .shapes = {boxShape(1.5f, 0.15f)}});
    for (int i = 0; i < 5; ++i)
        addBody(s, {.position = {-6.0f + 3.0f * static_cast<float>(i), 0.5f + 0.5f * static_cast<float>(i % 2)},
                    .shapes = {i % 2 ? circleShape(0.5f) : boxShape(0.5f, 0.5f)}});
    addBody(s, {.position = {-2.0f, 6.0f}, .shapes = {circleShape(0.4f)}});
    return s;
}

// The swept shape at transform xf: a box's outline or a circle.
void drawCastShape(DebugDraw& draw, const CastShape& shape, const Transform& xf, Color color) {
    if (const auto* c = std::get_if<Circle>(&shape)) {
        draw.drawCircle(transformPoint(xf, c->center), c->radius, color);
    } else if (const auto* p = std::get_if<Polygon>(&shape)) {
        std::array<Vec2, maxPolygonVertices> v;
        for (int i = 0; i < p->count; ++i) v[i] = transformPoint(xf, p->vertices[i]);
        draw.drawPolygon(std::span<const Vec2>(v.data(), static_cast<size_t>(p->count)), color);
    }
}

// A turning box and a circle swept left to right at heights that rise and fall: the path, the
// shape where it starts, where it first touches (castShapeClosest) with the hit's normal, and a
// dot at every shape the whole sweep touches (castShape).
SceneBehaviour shapeCastsBehaviour() {
    return {.setup = {}, .draw = [](const SceneWorld& sw, DebugDraw& draw) {
                const float t = 0.01f * static_cast<float>(sw.stepIndex);
                const CastShape shapes[] = {makeBox(0.4f, 0.25f), Circle{{}, 0.3f}};
                for (int k = 0; k < 2; ++k) {
                    const Transform xf{{-9.0f, 3.0f + 2.5f * sinCos(t + 1.5f * static_cast<float>(k)).sin}, Rot::fromAngle(k == 0 ? t : 0.0f)};
                    const Vec2 translation{18.0f, -1.0f};
                    const Color path{120, 120, 255, 255}, hitColor{255, 200, 0, 255};
                    draw.drawSegment(xf.p, xf.p + translation, path);
                    drawCastShape(draw, shapes[k], xf, path);
                    for (const ShapeCastHit& hit : sw.world.castShape(shapes[k], xf, translation))
                        draw.drawPoint(hit.point, 4.0f, path);
                    if (const std::optional<ShapeCastHit> hit = sw.world.castShapeClosest(shapes[k], xf, translation)) {
                        drawCastShape(draw, shapes[k], {xf.p + hit->fraction * translation, xf.q}, hitColor);
                        draw.drawPoint(hit->point, 7.0f, hitColor);
                        draw.drawSegment(hit->point, hit->point + 0.5f * hit->normal, hitColor);
                    }
                }
            }};
}

const std::map<std::string_view, SceneBehaviour>& behaviours() {
    static const std::map<std::string_view, SceneBehaviour> table = {
        {"one_way_platform", oneWayBehaviour()},
        {"sensor_zone", sensorZoneBehaviour()},
        {"conveyor", conveyorBehaviour()},
        {"laser", laserBehaviour()},
        {"mover_course", moverCourseBehaviour()},
        {"shape_casts", shapeCastsBehaviour()},
    };
    return table;
}

}  // namespace

std::vector<BuiltinScene> featureScenes() {
    return {
        {"one_way_platform", "balls and boxes launched up through one-way platforms land on them (pre-solve callback)",
         oneWayPlatform},
        {"sensor_zone", "a sensor zone reports the shapes raining through it and does not touch them", sensorZone},
        {"bullet_wall", "0.1 m bullets at 500 m/s stop at a 0.1 m wall and a thin plank (continuous collision)", bulletWall},
        {"conveyor", "two conveyor belts (tangent speed +-2 m/s) carry boxes right, then left", conveyor},
        {"laser", "a ray-cast laser reflects off boxes, balls and a turning mirror", laser},
        {"capsules", "capsules land flat on two points, tip over from an end cap, hold on a gentle ramp and slide down a steep one",
         capsules},
        {"shape_casts", "a turning box and a circle swept through the scene: first touch, its normal, and every shape hit (World::castShape)",
         shapeCasts},
        {"mover_course", "a character mover course (A/D walk, W jumps in the viewer): boxes to push, stairs, a walkable and a "
                         "too-steep slope, a moving and a one-way platform, a low ceiling",
         moverCourse},
    };
}

const SceneBehaviour* findSceneBehaviour(std::string_view sceneName) {
    const auto found = behaviours().find(sceneName);
    return found == behaviours().end() ? nullptr : &found->second;
}

SceneWorld buildWorldWithBehaviour(const Scene& scene, int workerCount) {
    SceneWorld built = buildWorld(scene, workerCount);
    const SceneBehaviour* behaviour = findSceneBehaviour(scene.name);
    if (!behaviour) return built;
    if (behaviour->setup) behaviour->setup(built);
    built.beforeStep = behaviour->beforeStep;
    return built;
}

}  // namespace perpdot
