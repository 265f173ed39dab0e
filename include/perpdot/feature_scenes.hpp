/// @file
/// What a scene file cannot say about the built-in feature demos (one_way_platform, conveyor,
/// laser, sensor_zone, mover_course): callbacks, per-step scripts and per-frame queries.
/// buildWorldWithBehaviour() builds a scene and runs its setup() once (pre-solve callbacks,
/// tangent speeds) and has SceneWorld::step() run its beforeStep() (platforms that turn back); a
/// viewer calls draw() every frame (the laser's ray cast, the shapes inside a sensor zone) and
/// gives the player the scene's character mover.
#pragma once

#include <functional>
#include <optional>
#include <string_view>

#include "perpdot/debug_draw.hpp"
#include "perpdot/mover.hpp"
#include "perpdot/scene.hpp"

namespace perpdot {

/// The character mover a viewer gives the player in a scene (perpdot/mover.hpp).
struct SceneMover {
    Vec2 start{};  ///< capsule centre, world
    MoverDef def{};  ///< how it walks (one-way platform categories, slope limit, …)
};

/// Callbacks of a built-in scene, for what its JSON cannot say.
struct SceneBehaviour {
    std::function<void(SceneWorld&)> setup;                   ///< may be empty
    std::function<void(const SceneWorld&, DebugDraw&)> draw;  ///< may be empty
    std::function<void(SceneWorld&)> beforeStep{};            ///< run before every SceneWorld::step(); may be empty
    std::optional<SceneMover> mover{};                        ///< none: the scene has no player mover
};

/// The behaviour of a built-in scene, or nullptr when the scene needs none.
const SceneBehaviour* findSceneBehaviour(std::string_view sceneName);

/// buildWorld(scene, workerCount), then the setup() of the behaviour named like the scene, if it has one.
SceneWorld buildWorldWithBehaviour(const Scene& scene, int workerCount = 1);

}  // namespace perpdot
