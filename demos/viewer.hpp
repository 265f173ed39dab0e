// The interactive SDL2 window: scene picker, pause/step/reset, slow motion, camera, mouse spring,
// and an ImGui panel (panel.cpp) with statistics, settings and the debug-draw toggles.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "box2d_overlay.hpp"
#include "camera.hpp"
#include "mouse_spring.hpp"
#include "options.hpp"
#include "perpdot/scene.hpp"

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
};

// Runs until the window closes (or after options.exitAfter frames). Returns the exit status.
int runViewer(const Options& options);

// panel.cpp
void drawPanel(ViewerState& state);
void drawHelp(bool& open);
void applyTweaks(const Tweaks& tweaks, SceneWorld& sim);

}  // namespace perpdot::demo
