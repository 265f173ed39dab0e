// The ImGui side of the viewer: the control panel and the help overlay.
#include <imgui.h>

#include "energy.hpp"
#include "viewer.hpp"

namespace perpdot::demo {
namespace {

struct Key {
    const char* keys;
    const char* action;
};
constexpr Key helpKeys[] = {
    {"Space", "pause / run"},
    {"S or Right", "single step (pauses)"},
    {"R", "reset the scene"},
    {"Z", "slow motion on/off (x0.25)"},
    {"Left drag", "pull a body by the grabbed point (spring)"},
    {"Right/middle drag", "pan"},
    {"Shift+arrows, Left/Up/Down", "pan"},
    {"Wheel, +/-", "zoom at the cursor"},
    {"C", "fit the camera to the scene"},
    {"X", "explosion at the mouse (World::explode, 20 N·s, 5 m)"},
    {"M", "character mover at the mouse (mover_course has one)"},
    {"A / D, W", "mover: walk left / right, jump"},
    {"H or F1", "this help"},
    {"Esc or Q", "quit"},
};

// ImGui::Checkbox, remembering where it was drawn (ViewerState::checkboxes).
bool checkbox(ViewerState& state, const char* label, bool* value) {
    const bool changed = ImGui::Checkbox(label, value);
    const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
    state.checkboxes[label] = {{min.x, min.y}, {max.x, max.y}};
    return changed;
}

}  // namespace

void applyTweaks(const Tweaks& tweaks, SceneWorld& sim) {
    sim.world.setGravity(tweaks.gravity);
    sim.world.setSubsteps(tweaks.substeps);
    if (!tweaks.overrideMaterials) return;
    for (BodyId body : sim.world.bodies()) {
        for (ShapeId shape : sim.world.shapes(body)) {
            sim.world.setFriction(shape, tweaks.friction);
            sim.world.setRestitution(shape, tweaks.restitution);
        }
    }
}

void drawPanel(ViewerState& state) {
    ImGui::SetNextWindowPos({10, 10}, ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize({320, 0}, ImGuiCond_FirstUseEver);
    ImGui::Begin("perpdot");
    const SceneEntry& entry = state.scenes[state.current];
    if (ImGui::BeginCombo("scene", entry.label.c_str())) {
        for (int i = 0; i < static_cast<int>(state.scenes.size()); ++i) {
            if (ImGui::Selectable(state.scenes[i].label.c_str(), i == state.current)) state.sceneRequested = i;
            if (ImGui::IsItemHovered() && !state.scenes[i].description.empty()) {
                ImGui::SetTooltip("%s", state.scenes[i].description.c_str());
            }
        }
        ImGui::EndCombo();
    }
    if (!entry.description.empty()) ImGui::TextWrapped("%s", entry.description.c_str());

    if (ImGui::Button(state.paused ? "Run" : "Pause")) state.paused = !state.paused;
    ImGui::SameLine();
    if (ImGui::Button("Step")) state.stepRequested = true;
    ImGui::SameLine();
    if (ImGui::Button("Reset")) state.resetRequested = true;
    ImGui::SameLine();
    if (ImGui::Button("Help")) state.showHelp = !state.showHelp;
    ImGui::SliderFloat("time scale", &state.timeScale, 0.05f, 1.0f, "%.2f");

    const World& world = state.sim->world;
    ImGui::Separator();
    ImGui::Text("time %.2f s (step %d)", state.sim->stepIndex * state.sim->scene.timestep, state.sim->stepIndex);
    ImGui::Text("step time %.3f ms", state.stepMilliseconds);
    ImGui::Text("bodies %d   contacts %d", world.bodyCount(), world.contactCount());
    ImGui::Text("total energy %.3f J", totalEnergy(world));

    ImGui::Separator();
    Tweaks& t = state.tweaks;
    bool changed = ImGui::SliderFloat2("gravity", &t.gravity.x, -30.0f, 30.0f, "%.1f");
    changed |= ImGui::SliderInt("substeps", &t.substeps, 1, 16);
    changed |= checkbox(state, "override materials", &t.overrideMaterials);
    if (t.overrideMaterials) {
        changed |= ImGui::SliderFloat("friction", &t.friction, 0.0f, 1.5f, "%.2f");
        changed |= ImGui::SliderFloat("restitution", &t.restitution, 0.0f, 1.0f, "%.2f");
    }
    if (changed) applyTweaks(t, *state.sim);

    ImGui::Separator();
    DebugDrawOptions& d = state.draw;
    checkbox(state, "shapes", &d.shapes);
    ImGui::SameLine();
    checkbox(state, "joints", &d.joints);
    ImGui::SameLine();
    checkbox(state, "dim sleeping", &d.dimSleeping);
    checkbox(state, "centre of mass", &d.centerOfMass);
    ImGui::SameLine();
    checkbox(state, "velocities", &d.velocities);
    ImGui::SameLine();
    checkbox(state, "AABBs", &d.aabbs);
    checkbox(state, "contacts", &d.contacts);
    ImGui::SameLine();
    checkbox(state, "impulses", &d.contactImpulses);

    ImGui::Separator();
    checkbox(state, "Box2D overlay (scene as defined)", &state.showBox2D);
    if (state.showBox2D) {
        ImGui::Text("largest position error %.4f m (%s)", state.box2d.maxPositionError(), state.box2d.worstBody().c_str());
    }
    ImGui::End();
}

void drawHelp(bool& open) {
    if (!open) return;
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    ImGui::SetNextWindowPos({viewport->WorkPos.x + viewport->WorkSize.x - 10, viewport->WorkPos.y + 10},
                            ImGuiCond_Always, {1.0f, 0.0f});
    ImGui::Begin("keys", &open, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings);
    if (ImGui::BeginTable("keys", 2)) {
        for (const Key& k : helpKeys) {
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(k.keys);
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(k.action);
        }
        ImGui::EndTable();
    }
    ImGui::End();
}

}  // namespace perpdot::demo
