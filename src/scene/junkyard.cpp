// Box2D v3's "junkyard" benchmark: 200 × 40 = 8,000 pentagons dropped into a bin 160 m wide and
// shoved back and forth by a kinematic pusher. The pusher follows x(t) = 60 sin(0.2 t) m; v3 sets
// its target pose every step, which here is a script that gives it, before step n, the velocity
// that carries it from x(t_{n-1}) to x(t_n) in one step: a scene file cannot say that.
#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "perpdot/portable_math.hpp"
#include "scene/builtin_registry.hpp"
#include "scene/scene_builders.hpp"
#include "scene/scene_script.hpp"

namespace perpdot {
namespace {

constexpr float timestep = 1.0f / 60.0f;
constexpr float sweep = 60.0f, sweepRate = 0.2f;  // x(t) = sweep · sin(sweepRate · t)

// Five points of a circle of radius r, each turned from the last by π(√5 − 1) (the golden angle's
// complement, as v3 places them), in the order they go round: an irregular pentagon.
std::vector<Vec2> pentagon(float r) {
    const float turn = pi * (std::sqrt(5.0f) - 1.0f);
    std::vector<float> angles;
    for (int i = 0; i < 5; ++i) angles.push_back(std::fmod(turn * static_cast<float>(i), 2.0f * pi));
    std::sort(angles.begin(), angles.end());
    std::vector<Vec2> points;
    for (const float a : angles) {
        const SinCos turned = sinCos(a);
        points.push_back({r * turned.cos, r * turned.sin});
    }
    return points;
}

// Bin: a floor from x = -80 to 80 m and walls 50 m high. Pentagons: 200 columns 0.375 m apart,
// 40 rows 1 m apart from 15 m up, every other one 0.1 m left or right. Sleep on, 800 steps.
Scene junkyard() {
    Scene s;
    s.steps = 800;
    s.timestep = timestep;
    addBin(s, 80, 50);
    const SceneShape junk = polygonShape(pentagon(0.25f));
    const int columns = 200, rows = 40;
    float side = -0.1f;
    for (int i = 0; i < columns; ++i)
        for (int j = 0; j < rows; ++j) {
            addBody(s, {.position = {0.375f * static_cast<float>(2 * i - columns) + side, 15.0f + static_cast<float>(j)},
                        .shapes = {junk}});
            side = -side;
        }
    addBody(s, {.name = "pusher", .type = BodyType::Kinematic, .allowSleep = false, .shapes = {boxShape(2.0f, 4.0f, {0.0f, 4.0f})}});
    return s;
}

class Pusher final : public SceneScript {
public:
    void beforeStep(int step, SceneEditor& editor) override {
        if (step == 0) return;  // at rest at x(0) = 0
        const auto x = [](int n) { return sweep * sinCos(sweepRate * timestep * static_cast<float>(n)).sin; };
        editor.setVelocity(pusherIndex, {(x(step) - x(step - 1)) / timestep, 0.0f}, 0.0f);
    }
    std::unique_ptr<SceneScript> clone() const override { return std::make_unique<Pusher>(*this); }

private:
    static constexpr int pusherIndex = 1 + 200 * 40;  // after the bin and the pentagons
};

}  // namespace

BuiltinScene junkyardScene() {
    return {"junkyard",
            "benchmark: a kinematic pusher sweeps 8,000 pentagons back and forth in a bin 160 m wide, 800 steps; scripted",
            junkyard};
}

std::unique_ptr<SceneScript> makeJunkyardScript() { return std::make_unique<Pusher>(); }

}  // namespace perpdot
