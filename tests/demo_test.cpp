// perpdot-demo end to end: headless frames are written, show something, and show each body
// where the World says it is; bad inputs fail with a non-zero status; the window runs under Xvfb.
#ifdef PERPDOT_DEMO

#include <SDL.h>
#include <SDL_image.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "camera.hpp"
#include "perpdot/debug_draw.hpp"
#include "perpdot/scene.hpp"
#include "sdl_draw.hpp"

namespace perpdot::demo {
namespace {

namespace fs = std::filesystem;

struct Image {
    std::unique_ptr<SDL_Surface, decltype(&SDL_FreeSurface)> surface{nullptr, SDL_FreeSurface};
    int width() const { return surface->w; }
    int height() const { return surface->h; }
    bool contains(Vec2 p) const { return p.x >= 0 && p.y >= 0 && p.x < width() && p.y < height(); }
    Color at(int x, int y) const {
        const auto* p = static_cast<const uint8_t*>(surface->pixels) + y * surface->pitch + 4 * x;
        return {p[0], p[1], p[2], p[3]};  // RGBA32: bytes in R, G, B, A order
    }
};

Image loadPng(const fs::path& path) {
    Image image;
    SDL_Surface* loaded = IMG_Load(path.c_str());
    if (!loaded) return image;
    image.surface.reset(SDL_ConvertSurfaceFormat(loaded, SDL_PIXELFORMAT_RGBA32, 0));
    SDL_FreeSurface(loaded);
    return image;
}

// A fresh directory for one test.
fs::path tempDir() {
    const auto* info = testing::UnitTest::GetInstance()->current_test_info();
    const fs::path dir = fs::temp_directory_path() /
                         ("perpdot_demo_" + std::string(info->name()) + "_" + std::to_string(getpid()));
    fs::remove_all(dir);
    return dir;
}

// Runs perpdot-demo with `args`; `prefix` wraps the command (xvfb-run).
struct DemoRun {
    int status = -1;     // exit status, -1 if it did not exit normally
    std::string output;  // stdout and stderr, for failure messages
};
DemoRun runDemo(const std::string& args, const std::string& prefix = "") {
    const fs::path log = fs::temp_directory_path() / ("perpdot_demo_" + std::to_string(getpid()) + ".log");
    const std::string command = prefix + "'" PERPDOT_DEMO "' " + args + " > '" + log.string() + "' 2>&1";
    const int status = std::system(command.c_str());
    DemoRun run;
    if (status != -1 && WIFEXITED(status)) run.status = WEXITSTATUS(status);
    std::ifstream in(log);
    run.output.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    fs::remove(log);
    return run;
}

std::string frameName(int frame) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.png", frame);
    return name;
}

// Standard deviation of the pixels' luminance: 0 for a blank frame.
float luminanceSpread(const Image& image) {
    double sum = 0.0, sumSquares = 0.0;
    const double n = double(image.width()) * image.height();
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const Color c = image.at(x, y);
            const double l = 0.299 * c.r + 0.587 * c.g + 0.114 * c.b;
            sum += l;
            sumSquares += l * l;
        }
    }
    return float(std::sqrt(std::max(0.0, sumSquares / n - (sum / n) * (sum / n))));
}

void expectColorNear(Color actual, Color expected, const char* what) {
    EXPECT_NEAR(actual.r, expected.r, 2) << what;
    EXPECT_NEAR(actual.g, expected.g, 2) << what;
    EXPECT_NEAR(actual.b, expected.b, 2) << what;
}

// The colour debugDraw gives each body's first solid shape, in body order.
struct ColorRecorder final : DebugDraw {
    std::vector<Color> solids;
    void drawPolygon(std::span<const Vec2>, Color) override {}
    void drawSolidPolygon(std::span<const Vec2>, float, Color c) override { solids.push_back(c); }
    void drawCircle(Vec2, float, Color) override {}
    void drawSolidCircle(Vec2, float, Rot, Color c) override { solids.push_back(c); }
    void drawSegment(Vec2, Vec2, Color) override {}
    void drawPoint(Vec2, float, Color) override {}
};

TEST(DemoHeadless, WritesTheRequestedFramesAndAContactSheet) {
    const fs::path dir = tempDir();
    const DemoRun run = runDemo("--headless single_box --frames 7 --every 10 --size 180x120 --out '" + dir.string() + "'");
    ASSERT_EQ(run.status, 0) << run.output;
    for (int f = 0; f < 7; ++f) {
        const Image frame = loadPng(dir / frameName(f));
        ASSERT_TRUE(frame.surface) << frameName(f);
        EXPECT_EQ(frame.width(), 180);
        EXPECT_EQ(frame.height(), 120);
    }
    EXPECT_FALSE(fs::exists(dir / frameName(7)));
    // 7 frames: a 3 x 3 grid of 60 x 40 thumbnails with 2 px gaps
    const Image sheet = loadPng(dir / "contact_sheet.png");
    ASSERT_TRUE(sheet.surface);
    EXPECT_EQ(sheet.width(), 3 * 62 + 2);
    EXPECT_EQ(sheet.height(), 3 * 42 + 2);
    fs::remove_all(dir);
}

TEST(DemoHeadless, DemoScenesRenderNonBlankMovingFrames) {
    for (const char* scene : {"card_house", "newtons_cradle", "offcenter_hit", "tumbler", "rain", "dominoes"}) {
        SCOPED_TRACE(scene);
        const fs::path dir = tempDir();
        const DemoRun run = runDemo(std::string("--headless ") + scene +
                                " --frames 3 --every 30 --size 160x100 --no-crosscheck --out '" + dir.string() + "'");
        ASSERT_EQ(run.status, 0) << run.output;
        const Image first = loadPng(dir / frameName(0)), last = loadPng(dir / frameName(2));
        ASSERT_TRUE(first.surface && last.surface);
        EXPECT_FALSE(fs::exists(dir / frameName(3)));
        EXPECT_GT(luminanceSpread(first), 5.0f);
        EXPECT_GT(luminanceSpread(last), 5.0f);
        if (std::string(scene) != "card_house") {  // the card house is meant to stand still
            int changed = 0;
            for (int y = 0; y < first.height(); ++y) {
                for (int x = 0; x < first.width(); ++x) {
                    const Color a = first.at(x, y), b = last.at(x, y);
                    changed += a.r != b.r || a.g != b.g || a.b != b.b;
                }
            }
            EXPECT_GT(changed, 20) << "nothing moved in 60 steps";
        }
        fs::remove_all(dir);
    }
}

// The box of single_box is drawn where the World puts it, in the dynamic-body fill colour:
// replay the scene to each frame's step and map the box's centre through the viewer's camera.
// The box falls about 0.9 m between frames 3 and 4, so frame f must show step f * every exactly.
TEST(DemoHeadless, BodyIsDrawnWhereTheWorldSaysItIs) {
    const int width = 320, height = 240, every = 10, frames = 7;
    const fs::path dir = tempDir();
    const DemoRun run = runDemo("--headless single_box --frames " + std::to_string(frames) + " --every " +
                            std::to_string(every) + " --size 320x240 --no-crosscheck --out '" + dir.string() + "'");
    ASSERT_EQ(run.status, 0) << run.output;
    SceneWorld sim = buildWorld(findScene("single_box"));
    const Camera camera = fitCamera(sim.world, width, height);
    size_t boxIndex = 0;
    while (boxIndex < sim.scene.bodies.size() && sim.scene.bodies[boxIndex].name != "box") ++boxIndex;
    ASSERT_LT(boxIndex, sim.scene.bodies.size());
    const BodyId box = sim.bodies[boxIndex];

    for (int frame = 0; frame < frames; ++frame) {
        SCOPED_TRACE(frame);
        if (frame > 0) for (int k = 0; k < every; ++k) sim.step();
        ColorRecorder colors;
        debugDraw(sim.world, colors);
        ASSERT_GT(colors.solids.size(), boxIndex);
        const Image image = loadPng(dir / frameName(frame));
        ASSERT_TRUE(image.surface);
        const Vec2 center = camera.toScreen(sim.world.worldCenter(box));
        ASSERT_TRUE(image.contains(center));
        expectColorNear(image.at(int(center.x), int(center.y)), fillColor(colors.solids[boxIndex]), "box centre");
        const Vec2 beside = camera.toScreen(sim.world.worldCenter(box) + Vec2{-1.2f, 0.0f});
        ASSERT_TRUE(image.contains(beside));
        expectColorNear(image.at(int(beside.x), int(beside.y)), backgroundColor, "1.2 m left of the box");
    }
    fs::remove_all(dir);
}

// The headless demo gives mover_course its character mover and walks it right: it must cross
// the course's first obstacles (more than 10 m from its start).
TEST(DemoHeadless, MoverCourseHasAWalkingCharacter) {
    const fs::path dir = tempDir();
    const DemoRun run = runDemo("--headless mover_course --frames 10 --every 30 --size 160x100 --no-crosscheck --out '" +
                                dir.string() + "'");
    ASSERT_EQ(run.status, 0) << run.output;
    float fromX = 0, fromY = 0, toX = 0, toY = 0;
    const size_t at = run.output.find("character mover: walked from");
    ASSERT_NE(at, std::string::npos) << run.output;
    ASSERT_EQ(std::sscanf(run.output.c_str() + at, "character mover: walked from (%f, %f) to (%f, %f)", &fromX, &fromY, &toX, &toY), 4)
        << run.output;
    EXPECT_GT(toX - fromX, 10.0f) << run.output;
    fs::remove_all(dir);
}

// The camera follows a scene whose bodies leave the fitted view (the car drives 40 m) and keeps
// the fitted camera of one whose bodies stay in it (single_box).
TEST(DemoCamera, FollowsTheCarAndKeepsAStillScenesFraming) {
    SceneWorld car = buildWorld(findScene("car"));
    Camera camera = fitCamera(car.world, 320, 200);
    size_t chassis = 0;
    while (car.scene.bodies[chassis].name != "chassis") ++chassis;
    for (int step = 0; step < car.scene.steps; ++step) {
        car.step();
        followCamera(car.world, camera);
        const Vec2 p = camera.toScreen(car.world.worldCenter(car.bodies[chassis]));
        ASSERT_TRUE(p.x >= 0 && p.x <= 320 && p.y >= 0 && p.y <= 200) << "step " << step;
    }
    EXPECT_TRUE(camera.following);

    SceneWorld still = buildWorld(findScene("single_box"));
    const Camera fitted = fitCamera(still.world, 320, 240);
    Camera camera2 = fitted;
    for (int step = 0; step < 300; ++step) {
        still.step();
        followCamera(still.world, camera2);
    }
    EXPECT_FALSE(camera2.following);
    EXPECT_EQ(camera2.center, fitted.center);
}

// The feature scenes' behaviours run in the demo: the laser's beam, drawn by its SceneBehaviour
// and not by debugDraw, shows as beam-red pixels.
TEST(DemoHeadless, FeatureSceneBehaviourDrawsTheLaser) {
    const fs::path dir = tempDir();
    const DemoRun run = runDemo("--headless laser --frames 2 --every 10 --size 320x240 --no-crosscheck --out '" + dir.string() + "'");
    ASSERT_EQ(run.status, 0) << run.output;
    const Image frame = loadPng(dir / frameName(1));
    ASSERT_TRUE(frame.surface);
    int beam = 0;
    for (int y = 0; y < frame.height(); ++y)
        for (int x = 0; x < frame.width(); ++x) {
            const Color c = frame.at(x, y);
            beam += c.r == 255 && c.g == 40 && c.b == 40;
        }
    EXPECT_GT(beam, 50) << "no laser beam drawn";
    fs::remove_all(dir);
}

TEST(DemoHeadless, BadInputsExitNonZero) {
    const fs::path dir = tempDir();
    const std::string out = " --out '" + dir.string() + "'";
    // each refused with status 2 and a message naming the problem
    const std::pair<std::string, std::string> cases[] = {
        {"--headless no_such_scene --frames 2", "no_such_scene"},
        {"--headless single_box --frames 0", "--frames"},
        {"--headless single_box --frames 2 --size 0x100", "--size"},
        {"--headless single_box --frames 2 --size big", "--size"},
        {"--headless single_box", "--frames"},
        {"--headless single_box --frames 2 --bogus", "--bogus"},
        {"--headless single_box --frames 2 --show sparkles", "sparkles"},
    };
    for (const auto& [args, message] : cases) {
        const DemoRun run = runDemo(args + out);
        EXPECT_EQ(run.status, 2) << args;
        EXPECT_NE(run.output.find(message), std::string::npos) << args << " said: " << run.output;
    }
    EXPECT_FALSE(fs::exists(dir / frameName(0)));
    // an output "directory" below a regular file cannot be created
    fs::create_directories(dir);
    { std::FILE* f = std::fopen((dir / "file").c_str(), "w"); ASSERT_NE(f, nullptr); std::fclose(f); }
    const DemoRun unwritable = runDemo("--headless single_box --frames 2 --out '" + (dir / "file" / "frames").string() + "'");
    EXPECT_NE(unwritable.status, 0);
    EXPECT_NE(unwritable.output.find("cannot create output directory"), std::string::npos) << unwritable.output;
    fs::remove_all(dir);
}

TEST(DemoWindow, RunsUnderXvfbAndExitsAfterTheFrameLimit) {
    if (std::system("command -v xvfb-run > /dev/null 2>&1") != 0) GTEST_SKIP() << "xvfb-run is not installed";
    const DemoRun run = runDemo("dominoes --exit-after 90 --size 640x400", "xvfb-run -a -s '-screen 0 800x600x24' ");
    EXPECT_EQ(run.status, 0) << run.output;
}

}  // namespace
}  // namespace perpdot::demo

#endif  // PERPDOT_DEMO
