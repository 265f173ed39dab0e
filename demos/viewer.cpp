#include "viewer.hpp"

#include <SDL.h>
#include <imgui.h>
#include <imgui_impl_sdl.h>
#include <imgui_impl_sdlrenderer.h>

#include <algorithm>
#include <chrono>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <utility>

#include "perpdot/error.hpp"
#include "perpdot/feature_scenes.hpp"
#include "sdl_draw.hpp"
#include "sdl_handles.hpp"

namespace perpdot::demo {
namespace {

constexpr int defaultWidth = 1280, defaultHeight = 800;
constexpr float panPixelsPerKey = 40.0f;
constexpr float slowMotion = 0.25f;
constexpr int maxStepsPerFrame = 8;  // past this the simulation runs slower than real time

// The built-in scenes, plus the file given on the command line if it is not one of them.
std::vector<SceneEntry> sceneList(const std::string& requested, int& current) {
    std::vector<SceneEntry> list;
    current = 0;
    for (const BuiltinScene& b : builtinScenes()) {
        if (b.name == requested) current = static_cast<int>(list.size());
        list.push_back({b.name, b.description, b.make});
    }
    const bool isBuiltin = std::any_of(list.begin(), list.end(), [&](const SceneEntry& e) { return e.label == requested; });
    if (!requested.empty() && !isBuiltin) {
        Scene scene = findScene(requested);  // throws Error with a clear message
        current = static_cast<int>(list.size());
        list.push_back({requested, scene.description, [scene] { return scene; }});
    }
    if (list.empty()) throw Error("no scenes: the built-in registry is empty and no file was given");
    return list;
}

}  // namespace

Viewer::Viewer(const Options& options, SDL_Renderer* renderer) : options_(options), renderer_(renderer) {
    state_.scenes = sceneList(options.scene, state_.current);
    state_.draw = options.draw;
    load(state_.current, true);
}

int Viewer::run() {
    Uint64 last = SDL_GetPerformanceCounter();
    for (int count = 0; !quit_; ++count) {
        if (options_.exitAfter > 0 && count >= options_.exitAfter) break;
        const Uint64 now = SDL_GetPerformanceCounter();
        const double dt = std::min(0.1, double(now - last) / double(SDL_GetPerformanceFrequency()));
        last = now;
        frame(dt);
    }
    return 0;
}

void Viewer::frame(double dt) {
    SDL_Event e;
    while (SDL_PollEvent(&e)) handleEvent(e);
    handleRequests();
    simulate(dt);
    render();
}

void Viewer::load(int index, bool newScene) {
    state_.current = index;
    state_.sim = std::make_unique<SceneWorld>(buildWorldWithBehaviour(state_.scenes[index].make()));
    SceneWorld& sim = *state_.sim;
    if (newScene) {
        state_.tweaks = {.gravity = sim.scene.gravity, .substeps = sim.world.settings().substeps};
        fitView();
    } else {
        applyTweaks(state_.tweaks, sim);
    }
    spring_.release();
    mover_.forget();
    if (const SceneBehaviour* behaviour = findSceneBehaviour(sim.scene.name); behaviour && behaviour->mover)
        mover_.place(sim.world, behaviour->mover->def, behaviour->mover->start);
    state_.box2d.clear();
    accumulator_ = 0.0;
}

void Viewer::fitView() {
    int w = defaultWidth, h = defaultHeight;
    SDL_GetRendererOutputSize(renderer_, &w, &h);
    camera_ = fitCamera(state_.sim->world, w, h);
}

void Viewer::handleRequests() {
    if (state_.sceneRequested >= 0) load(std::exchange(state_.sceneRequested, -1), true);
    if (std::exchange(state_.resetRequested, false)) load(state_.current, false);
}

void Viewer::step() {
    SceneWorld& sim = *state_.sim;
    spring_.applyForce(sim.world);
    const auto start = std::chrono::steady_clock::now();
    sim.step();
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    state_.stepMilliseconds = state_.stepMilliseconds == 0.0 ? ms : 0.9 * state_.stepMilliseconds + 0.1 * ms;
    mover_.move(sim.world, sim.scene.timestep);
}

void Viewer::simulate(double dt) {
    if (std::exchange(state_.stepRequested, false)) {
        state_.paused = true;
        step();
    }
    if (state_.paused) return;
    const double h = state_.sim->scene.timestep;
    accumulator_ += dt * state_.timeScale;
    int steps = 0;
    for (; accumulator_ >= h && steps < maxStepsPerFrame; ++steps) {
        step();
        accumulator_ -= h;
    }
    if (steps == maxStepsPerFrame) accumulator_ = 0.0;
}

// World::explode at the mouse: 20 N·s falling off to nothing 5 m away, behind walls too.
void Viewer::explodeAtCursor() { state_.sim->world.explode({.position = mouseWorld(), .radius = 5.0f, .impulse = 20.0f}); }

// The scene's mover definition if it has one (its one-way platforms), else the default.
void Viewer::placeMoverAtCursor() {
    const SceneBehaviour* behaviour = findSceneBehaviour(state_.sim->scene.name);
    mover_.place(state_.sim->world, behaviour && behaviour->mover ? behaviour->mover->def : MoverDef{}, mouseWorld());
}

void Viewer::handleKey(const SDL_Keysym& key) {
    const bool shift = (key.mod & KMOD_SHIFT) != 0;
    switch (key.sym) {
        case SDLK_SPACE: state_.paused = !state_.paused; break;
        case SDLK_s: state_.stepRequested = true; break;
        case SDLK_RIGHT:
            if (shift) camera_.center.x += panPixelsPerKey / camera_.pixelsPerMetre;
            else state_.stepRequested = true;
            break;
        case SDLK_LEFT: camera_.center.x -= panPixelsPerKey / camera_.pixelsPerMetre; break;
        case SDLK_UP: camera_.center.y += panPixelsPerKey / camera_.pixelsPerMetre; break;
        case SDLK_DOWN: camera_.center.y -= panPixelsPerKey / camera_.pixelsPerMetre; break;
        case SDLK_r: state_.resetRequested = true; break;
        case SDLK_z: state_.timeScale = state_.timeScale < 1.0f ? 1.0f : slowMotion; break;
        case SDLK_c: fitView(); break;
        case SDLK_x: explodeAtCursor(); break;
        case SDLK_m: placeMoverAtCursor(); break;
        case SDLK_h:
        case SDLK_F1: state_.showHelp = !state_.showHelp; break;
        case SDLK_PLUS:
        case SDLK_EQUALS:
        case SDLK_KP_PLUS: camera_.zoomAt({0.5f * camera_.width, 0.5f * camera_.height}, 1.25f); break;
        case SDLK_MINUS:
        case SDLK_KP_MINUS: camera_.zoomAt({0.5f * camera_.width, 0.5f * camera_.height}, 0.8f); break;
        case SDLK_ESCAPE:
        case SDLK_q: quit_ = true; break;
        default: break;
    }
}

void Viewer::handleEvent(const SDL_Event& e) {
    ImGui_ImplSDL2_ProcessEvent(&e);
    const ImGuiIO& io = ImGui::GetIO();
    World& world = state_.sim->world;
    switch (e.type) {
        case SDL_QUIT: quit_ = true; break;
        case SDL_WINDOWEVENT:
            if (e.window.event == SDL_WINDOWEVENT_SIZE_CHANGED) SDL_GetRendererOutputSize(renderer_, &camera_.width, &camera_.height);
            break;
        case SDL_KEYDOWN:
            if (!io.WantCaptureKeyboard && !mover_.handleKey(e.key.keysym.sym, true)) handleKey(e.key.keysym);
            break;
        case SDL_KEYUP: mover_.handleKey(e.key.keysym.sym, false); break;  // a released walk key stops even under the panel
        case SDL_MOUSEBUTTONDOWN:
            mouse_ = {float(e.button.x), float(e.button.y)};
            if (io.WantCaptureMouse) break;
            if (e.button.button == SDL_BUTTON_LEFT) {
                if (const auto body = bodyAt(world, mouseWorld())) spring_.grab(world, *body, mouseWorld());
            } else {
                panning_ = true;
            }
            break;
        case SDL_MOUSEBUTTONUP:
            if (e.button.button == SDL_BUTTON_LEFT) spring_.release();
            else panning_ = false;
            break;
        case SDL_MOUSEMOTION:
            mouse_ = {float(e.motion.x), float(e.motion.y)};
            if (panning_) camera_.center += Vec2{-float(e.motion.xrel), float(e.motion.yrel)} * (1.0f / camera_.pixelsPerMetre);
            spring_.setTarget(mouseWorld());
            break;
        case SDL_MOUSEWHEEL:
            if (!io.WantCaptureMouse) camera_.zoomAt(mouse_, std::pow(1.15f, e.wheel.preciseY));
            break;
        default: break;
    }
}

void Viewer::render() {
    const World& world = state_.sim->world;
    drawWorld(renderer_, world, camera_, state_.draw);
    SdlDraw draw(renderer_, camera_);
    if (const SceneBehaviour* behaviour = findSceneBehaviour(state_.sim->scene.name); behaviour && behaviour->draw)
        behaviour->draw(*state_.sim, draw);
    mover_.draw(draw);
    if (state_.showBox2D) {
        state_.box2d.update(*state_.sim);
        state_.box2d.draw(draw, *state_.sim);
    }
    if (spring_.active(world)) {
        draw.drawSegment(spring_.anchor(world), spring_.target(), Color{255, 255, 255});
        draw.drawPoint(spring_.anchor(world), 6.0f, Color{255, 255, 255});
    }
    ImGui_ImplSDLRenderer_NewFrame();
    ImGui_ImplSDL2_NewFrame();
    // ImGui 1.86's SDL backend reads the pointer only while SDL gives this window focus; without it
    // (click-through, the dummy video driver) the pointer is where this window's events last saw it.
    if (ImGuiIO& io = ImGui::GetIO(); io.MousePos.x == -FLT_MAX) io.MousePos = {mouse_.x, mouse_.y};
    ImGui::NewFrame();
    drawPanel(state_);
    drawHelp(state_.showHelp);
    ImGui::Render();
    ImGui_ImplSDLRenderer_RenderDrawData(ImGui::GetDrawData());
    SDL_RenderPresent(renderer_);
}

ImGuiLayer::ImGuiLayer(SDL_Window* window, SDL_Renderer* renderer) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini in the user's directory
    ImGui::StyleColorsDark();
    ImGui_ImplSDL2_InitForSDLRenderer(window);
    ImGui_ImplSDLRenderer_Init(renderer);
}

ImGuiLayer::~ImGuiLayer() {
    ImGui_ImplSDLRenderer_Shutdown();
    ImGui_ImplSDL2_Shutdown();
    ImGui::DestroyContext();
}

int runViewer(const Options& options) {
    SdlLibrary sdl(SDL_INIT_VIDEO | SDL_INIT_TIMER);
    if (!sdl.ok) {
        std::fprintf(stderr, "perpdot-demo: cannot open a display (%s); try --headless\n", SDL_GetError());
        return 1;
    }
    WindowPtr window(SDL_CreateWindow("perpdot", SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED,
                                      options.width ? options.width : defaultWidth,
                                      options.height ? options.height : defaultHeight,
                                      SDL_WINDOW_RESIZABLE | SDL_WINDOW_ALLOW_HIGHDPI));
    if (!window) {
        std::fprintf(stderr, "perpdot-demo: cannot create a window: %s\n", SDL_GetError());
        return 1;
    }
    RendererPtr renderer(SDL_CreateRenderer(window.get(), -1, SDL_RENDERER_ACCELERATED | SDL_RENDERER_PRESENTVSYNC));
    if (!renderer) renderer.reset(SDL_CreateRenderer(window.get(), -1, SDL_RENDERER_SOFTWARE));
    if (!renderer) {
        std::fprintf(stderr, "perpdot-demo: cannot create a renderer: %s\n", SDL_GetError());
        return 1;
    }
    ImGuiLayer imgui(window.get(), renderer.get());
    try {
        Viewer viewer(options, renderer.get());
        return viewer.run();
    } catch (const Error& e) {
        std::fprintf(stderr, "perpdot-demo: %s\n", e.what());
        return 2;
    }
}

}  // namespace perpdot::demo
