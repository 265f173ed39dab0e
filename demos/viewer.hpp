// The interactive SDL2 window: scene picker, pause/step/reset, slow motion, camera, mouse spring,
// explosions, a character mover, and an ImGui panel (panel.cpp) with statistics, settings and the
// debug-draw toggles. Viewer is one window's state and its frame; runViewer() opens the window.
#pragma once

#include <SDL.h>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "box2d_overlay.hpp"
#include "camera.hpp"
#include "mouse_spring.hpp"
#include "options.hpp"
#include "perpdot/scene.hpp"
#include "player_mover.hpp"

namespace perpdot::demo {

struct SceneEntry {
    std::string label;
    std::string description;
    std::function<Scene()> make;
};

// Settings the user changed for the current scene; kept across reset, dropped on a scene switch.
struct Tweaks {
    Vec2 gravity;
    int substeps = 4;
    bool overrideMaterials = false;  // apply friction/restitution below to every shape
    float friction = 0.6f;
    float restitution = 0.0f;
};

// Everything the panel shows or changes.
struct ViewerState {
    std::vector<SceneEntry> scenes;
    int current = 0;
    std::unique_ptr<SceneWorld> sim;
    Tweaks tweaks;
    DebugDrawOptions draw;
    bool paused = false;
    bool showHelp = false;
    float timeScale = 1.0f;  // < 1: slow motion
    double stepMilliseconds = 0.0;  // smoothed wall time of one step
    bool showBox2D = false;         // the cross-check overlay
    Box2DOverlay box2d;
    // requests from the panel, handled by the loop
    bool resetRequested = false;
    bool stepRequested = false;
    int sceneRequested = -1;
    // Where the panel drew each of its checkboxes last frame, by label: top-left and bottom-right
    // in window pixels (what a click must hit; the interaction tests click them by name).
    std::map<std::string, std::pair<Vec2, Vec2>> checkboxes;
};

// One viewer window: its scenes, camera, mouse spring and mover, fed SDL events frame by frame.
class Viewer {
public:
    Viewer(const Options& options, SDL_Renderer* renderer);

    // Until quit (Esc, Q, closing the window) or options.exitAfter frames. Returns the exit status.
    int run();
    // One frame: the queued SDL events, the panel's requests, `dt` seconds of simulation (fixed
    // steps, scaled by the time scale), then drawing.
    void frame(double dt);

    bool quit() const { return quit_; }
    const ViewerState& state() const { return state_; }
    const Camera& camera() const { return camera_; }
    const PlayerMover& mover() const { return mover_; }

private:
    void load(int index, bool newScene);
    void fitView();
    void handleRequests();
    void step();
    void simulate(double dt);
    Vec2 mouseWorld() const { return camera_.toWorld(mouse_); }
    void explodeAtCursor();
    void placeMoverAtCursor();
    void handleKey(const SDL_Keysym& key);
    void handleEvent(const SDL_Event& e);
    void render();

    Options options_;
    SDL_Renderer* renderer_;
    ViewerState state_;
    Camera camera_;
    MouseSpring spring_;
    PlayerMover mover_;
    Vec2 mouse_{};  // last mouse position seen in an event, window pixels
    double accumulator_ = 0.0;
    bool panning_ = false;
    bool quit_ = false;
};

// ImGui context and its two SDL backends, for the lifetime of the object.
struct ImGuiLayer {
    ImGuiLayer(SDL_Window* window, SDL_Renderer* renderer);
    ~ImGuiLayer();
    ImGuiLayer(const ImGuiLayer&) = delete;
    ImGuiLayer& operator=(const ImGuiLayer&) = delete;
};

// Opens the window and runs a Viewer in it. Returns the exit status.
int runViewer(const Options& options);

// panel.cpp
void drawPanel(ViewerState& state);
void drawHelp(bool& open);
void applyTweaks(const Tweaks& tweaks, SceneWorld& sim);

}  // namespace perpdot::demo
