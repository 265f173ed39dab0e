#include "scene/mover_course.hpp"

#include <cmath>
#include <string>

#include "perpdot/portable_math.hpp"
#include "scene/scene_builders.hpp"

namespace perpdot {
namespace {

constexpr uint16_t oneWayCategory = 0x0002;
constexpr float platformSpeed = 1.5f;               // m/s
constexpr float platformLeft = 9.0f, platformRight = 13.0f;  // where the moving platform turns back, m

// A static ramp rising at `angle` from (x, 0) to height `height`, then a flat top 1 m long.
void addRamp(Scene& s, float x, float angle, float height) {
    const SinCos sc = sinCos(angle);
    const float run = height * sc.cos / sc.sin;  // height / tan(angle)
    addBody(s, {.type = BodyType::Static, .shapes = {polygonShape({{x, 0.0f}, {x + run + 1.0f, 0.0f}, {x + run + 1.0f, height}, {x + run, height}})}});
}

}  // namespace

// Left to right: a low ceiling over the start, two boxes to push (0.6 m: jump them), stairs of 0.25 m up and down,
// a 25° ramp (walkable, limit 50°), a 60° ramp (a wall to the mover), a platform shuttling
// between x = 9 and 13 m, and a one-way platform 1.5 m up to jump through.
Scene moverCourse() {
    Scene s;
    s.steps = 1200;
    addGround(s, 20.0f);
    addBody(s, {.name = "ceiling", .type = BodyType::Static, .position = {-16.0f, 2.2f}, .shapes = {boxShape(2.0f, 0.1f)}});
    for (int i = 0; i < 2; ++i)
        addBody(s, {.name = "box" + std::to_string(i), .position = {-12.0f + 0.8f * static_cast<float>(i), 0.3f}, .shapes = {boxShape(0.3f, 0.3f)}});
    for (int i = 0; i < 4; ++i) {
        const float height = 0.25f * static_cast<float>(i + 1);
        addBody(s, {.type = BodyType::Static, .position = {-7.0f, 0.5f * height}, .shapes = {boxShape(2.5f - 0.5f * static_cast<float>(i), 0.5f * height)}});
    }
    addRamp(s, -3.0f, 0.436f, 1.0f);
    addRamp(s, 2.5f, 1.047f, 1.5f);
    addBody(s, {.name = "platform", .type = BodyType::Kinematic, .position = {platformLeft, 1.0f}, .linearVelocity = {platformSpeed, 0.0f},
                .shapes = {boxShape(1.0f, 0.1f)}});
    SceneShape oneWay = boxShape(1.5f, 0.05f);
    oneWay.filter.category = oneWayCategory;
    addBody(s, {.name = "one_way", .type = BodyType::Static, .position = {17.0f, 1.5f}, .shapes = {oneWay}});
    return s;
}

SceneBehaviour moverCourseBehaviour() {
    return {.setup = {},
            .draw = {},
            // The platform turns back at either end: its velocity follows from its position alone, so
            // a restored snapshot replays it.
            .beforeStep = [](SceneWorld& sw) {
                for (size_t i = 0; i < sw.scene.bodies.size(); ++i) {
                    if (sw.scene.bodies[i].name != "platform") continue;
                    const BodyId platform = sw.bodies[i];
                    const float x = sw.world.position(platform).x;
                    const float vx = sw.world.linearVelocity(platform).x;
                    if ((x >= platformRight && vx > 0.0f) || (x <= platformLeft && vx < 0.0f))
                        sw.world.setLinearVelocity(platform, {-vx, 0.0f});
                }
            },
            .mover = SceneMover{.start = {-17.0f, 1.0f}, .def = {.oneWayCategories = oneWayCategory}}};
}

}  // namespace perpdot
