// The large scenes of the benchmarks, built as Box2D v3's benchmark suite builds them
// (sleeping off, so every step solves every body).
#include "scene/builtin_registry.hpp"
#include "scene/scene_builders.hpp"

namespace perpdot {
namespace {

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

}  // namespace

std::vector<BuiltinScene> benchScenes() {
    return {
        {"large_pyramid", "benchmark: a pyramid 100 boxes wide (5,050 boxes), sleep off, 500 steps", largePyramid},
        {"many_pyramids", "benchmark: 20 x 20 pyramids of base 10 (22,000 boxes) on 20 shelves, sleep off, 200 steps",
         manyPyramids},
    };
}

}  // namespace perpdot
