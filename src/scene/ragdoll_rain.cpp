// Box2D v3's "rain" benchmark with this project's ragdoll figure: five shelves, each a row of
// 501 boxes of 0.5 m 45 m above the one below; every 8 steps a new column of groups (one group
// = five ragdolls side by side) is dropped 42 m above the shelves. Once 40 columns stand (1,000
// ragdolls), the oldest column is destroyed and dropped anew, so every ragdoll lives 320 steps.
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "scene/builtin_registry.hpp"
#include "scene/ragdoll_figure.hpp"
#include "scene/scene_builders.hpp"
#include "scene/scene_script.hpp"

namespace perpdot {
namespace {

constexpr int rows = 5, columns = 40, ragdollsPerGroup = 5;
constexpr int spawnEvery = 8;                  // steps between two columns
constexpr int shelfBoxes = 501;                // 0.5 m boxes per shelf
constexpr float boxSize = 0.5f, shelfSpacing = 45.0f, dropHeight = 42.0f;
constexpr float span = (shelfBoxes - 1) * boxSize;  // 250 m, where the groups fall

Scene ragdollRain() {
    Scene s;
    s.steps = 1000;
    SceneBody& ground = addBody(s, {.name = "ground", .type = BodyType::Static});
    for (int row = 0; row < rows; ++row)
        for (int i = 0; i < shelfBoxes; ++i)
            ground.shapes.push_back(boxShape(0.5f * boxSize, 0.5f * boxSize, {-0.5f * span + boxSize * i, shelfSpacing * row}));
    return s;
}

// Five ragdolls 1 m apart (v3 puts its narrower figures 0.5 m apart) above shelf `row`, in column `column`.
Scene group(int row, int column) {
    Scene fragment;
    const float columnWidth = span / columns;
    const float x = -0.5f * span + columnWidth * (column + 0.5f), y = shelfSpacing * row + dropHeight;
    for (int k = 0; k < ragdollsPerGroup; ++k) {
        std::string prefix = "r";  // appended, not "r" + …: g++ 12 -O2 misreads that as an overlapping memcpy
        prefix += std::to_string(k);
        prefix += '_';
        addRagdoll(fragment, {x + (k - 0.5f * (ragdollsPerGroup - 1)), y}, prefix);
    }
    for (SceneBody& body : fragment.bodies) body.allowSleep = false;
    return fragment;
}

class RagdollRain final : public SceneScript {
public:
    RagdollRain() {  // the fragments are made once, so a step times the engines, not scene building
        auto fragments = std::make_shared<Fragments>();
        for (int row = 0; row < rows; ++row)
            for (int column = 0; column < columns; ++column) (*fragments)[slot(row, column)] = group(row, column);
        fragments_ = std::move(fragments);
    }

    std::unique_ptr<SceneScript> clone() const override { return std::make_unique<RagdollRain>(*this); }

    void beforeStep(int step, SceneEditor& editor) override {
        if (step % spawnEvery != 0) return;
        const bool full = filledColumns_ == columns;
        const int column = full ? oldestColumn_ : filledColumns_;
        for (int row = 0; row < rows; ++row) {
            const int i = slot(row, column);
            if (full) editor.destroy(alive_[i]);
            alive_[i] = editor.spawn((*fragments_)[i]);
        }
        if (full)
            oldestColumn_ = (oldestColumn_ + 1) % columns;
        else
            ++filledColumns_;
    }

private:
    static int slot(int row, int column) { return row * columns + column; }

    using Fragments = std::array<Scene, rows * columns>;
    std::shared_ptr<const Fragments> fragments_;  // shared by clones
    std::array<SceneEditor::Group, rows * columns> alive_{};
    int filledColumns_ = 0, oldestColumn_ = 0;
};

}  // namespace

BuiltinScene ragdollRainScene() {
    return {"ragdoll_rain",
            "benchmark: ragdolls rain onto five shelves, a column of 25 every 8 steps, up to 1,000 alive (each lives "
            "320 steps), sleep off, 1,000 steps; scripted",
            ragdollRain};
}

std::unique_ptr<SceneScript> makeRagdollRainScript() { return std::make_unique<RagdollRain>(); }

}  // namespace perpdot
