#include "headless.hpp"

#include <SDL.h>
#include <SDL_image.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "camera.hpp"
#include "player_mover.hpp"
#include "perpdot/crosscheck.hpp"
#include "perpdot/error.hpp"
#include "perpdot/feature_scenes.hpp"
#include "perpdot/scene.hpp"
#include "sdl_draw.hpp"
#include "sdl_handles.hpp"

namespace perpdot::demo {
namespace {

constexpr int defaultWidth = 640, defaultHeight = 400;
constexpr int maxSheetFrames = 16;
constexpr int sheetGap = 2;  // pixels between thumbnails

// The contact sheet: a grid of up to 16 evenly spaced frames, each downscaled.
class ContactSheet {
public:
    ContactSheet(int frames, int width, int height) {
        count_ = std::min(frames, maxSheetFrames);
        columns_ = static_cast<int>(std::ceil(std::sqrt(static_cast<float>(count_))));
        const int rows = (count_ + columns_ - 1) / columns_;
        thumbWidth_ = std::max(1, width / columns_);
        thumbHeight_ = std::max(1, height / columns_);
        frames_ = frames;
        sheet_.reset(SDL_CreateRGBSurfaceWithFormat(0, columns_ * (thumbWidth_ + sheetGap) + sheetGap,
                                                    rows * (thumbHeight_ + sheetGap) + sheetGap, 32,
                                                    SDL_PIXELFORMAT_RGBA32));
        if (sheet_) SDL_FillRect(sheet_.get(), nullptr, SDL_MapRGB(sheet_->format, 90, 90, 96));
    }
    bool ok() const { return sheet_ != nullptr; }
    // Slot k shows frame round(k (N-1) / (count-1)).
    int slotOf(int frame) const {
        for (int k = 0; k < count_; ++k) {
            const int f = count_ == 1 ? 0 : static_cast<int>(std::lround(float(k) * float(frames_ - 1) / float(count_ - 1)));
            if (f == frame) return k;
        }
        return -1;
    }
    void add(int frame, SDL_Surface* image) {
        const int k = slotOf(frame);
        if (k < 0) return;
        SDL_Rect cell{sheetGap + (k % columns_) * (thumbWidth_ + sheetGap), sheetGap + (k / columns_) * (thumbHeight_ + sheetGap),
                      thumbWidth_, thumbHeight_};
        SDL_SoftStretchLinear(image, nullptr, sheet_.get(), &cell);
    }
    SDL_Surface* surface() const { return sheet_.get(); }

private:
    int count_ = 0, columns_ = 1, frames_ = 0, thumbWidth_ = 1, thumbHeight_ = 1;
    SurfacePtr sheet_;
};

// How perpdot and Box2D 2.4's b2World compare over the same steps, as a finding in words.
void printCrosscheck(const Scene& scene, int steps) {
    try {
        std::fputs(crosscheck::summarize(scene, steps).c_str(), stdout);
    } catch (const Error& e) {
        std::printf("crosscheck vs Box2D 2.4: not available for this scene: %s\n", e.what());
    }
}

std::string framePath(const std::filesystem::path& dir, int frame) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.png", frame);
    return (dir / name).string();
}

}  // namespace

int runHeadless(const Options& options) {
    const int width = options.width ? options.width : defaultWidth;
    const int height = options.height ? options.height : defaultHeight;
    Scene scene;
    try {
        scene = findScene(options.scene);
    } catch (const Error& e) {
        std::fprintf(stderr, "perpdot-demo: %s\n", e.what());
        return 2;
    }
    const std::filesystem::path dir = options.outDir;
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec || !std::filesystem::is_directory(dir)) {
        std::fprintf(stderr, "perpdot-demo: cannot create output directory '%s': %s\n", dir.c_str(),
                     ec ? ec.message().c_str() : "not a directory");
        return 2;
    }

    setenv("SDL_VIDEODRIVER", "dummy", 0);  // no display needed; keep a driver the user chose
    SdlLibrary sdl(SDL_INIT_VIDEO);
    if (!sdl.ok) {
        std::fprintf(stderr, "perpdot-demo: SDL_Init failed: %s\n", SDL_GetError());
        return 1;
    }
    SurfacePtr target(SDL_CreateRGBSurfaceWithFormat(0, width, height, 32, SDL_PIXELFORMAT_RGBA32));
    RendererPtr renderer(target ? SDL_CreateSoftwareRenderer(target.get()) : nullptr);
    ContactSheet sheet(options.frames, width, height);
    if (!renderer || !sheet.ok()) {
        std::fprintf(stderr, "perpdot-demo: cannot create a %dx%d software renderer: %s\n", width, height, SDL_GetError());
        return 1;
    }

    SceneWorld sw = buildWorldWithBehaviour(scene);
    const SceneBehaviour* behaviour = findSceneBehaviour(scene.name);
    // A scene with a character mover gets one, walked right by the autopilot (the window's keys).
    PlayerMover mover;
    if (behaviour && behaviour->mover) mover.place(sw.world, behaviour->mover->def, behaviour->mover->start);
    Camera camera = fitCamera(sw.world, width, height);
    double stepSeconds = 0.0;
    for (int frame = 0; frame < options.frames; ++frame) {
        if (frame > 0) {
            const auto start = std::chrono::steady_clock::now();
            for (int k = 0; k < options.every; ++k) {
                sw.step();
                mover.autopilot(scene.timestep);
                mover.move(sw.world, scene.timestep);
            }
            stepSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        }
        followCamera(sw.world, camera);
        drawWorld(renderer.get(), sw.world, camera, options.draw);
        SdlDraw draw(renderer.get(), camera);
        if (behaviour && behaviour->draw) behaviour->draw(sw, draw);
        if (mover.active()) mover.draw(draw);
        SDL_RenderFlush(renderer.get());
        const std::string path = framePath(dir, frame);
        if (IMG_SavePNG(target.get(), path.c_str()) != 0) {
            std::fprintf(stderr, "perpdot-demo: cannot write %s: %s\n", path.c_str(), IMG_GetError());
            return 1;
        }
        sheet.add(frame, target.get());
    }
    const std::string sheetPath = (dir / "contact_sheet.png").string();
    if (IMG_SavePNG(sheet.surface(), sheetPath.c_str()) != 0) {
        std::fprintf(stderr, "perpdot-demo: cannot write %s: %s\n", sheetPath.c_str(), IMG_GetError());
        return 1;
    }
    const int steps = (options.frames - 1) * options.every;
    std::printf("%s: %d frames (%d steps, %.2f s simulated, %.3f ms/step) -> %s/frame_0000.png .. frame_%04d.png, "
                "contact_sheet.png\n",
                scene.name.c_str(), options.frames, steps, steps * scene.timestep,
                steps > 0 ? 1000.0 * stepSeconds / steps : 0.0, dir.c_str(), options.frames - 1);
    if (mover.active()) {
        const Vec2 at = mover.state().position;
        std::printf("character mover: walked from (%.2f, %.2f) to (%.2f, %.2f)\n", behaviour->mover->start.x,
                    behaviour->mover->start.y, at.x, at.y);
    }
    if (options.crosscheck && steps > 0) printCrosscheck(scene, steps);
    return 0;
}

}  // namespace perpdot::demo
