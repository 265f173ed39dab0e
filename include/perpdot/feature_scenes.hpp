/// @file
/// What a scene file cannot say about the built-in feature demos (one_way_platform, conveyor,
/// laser, sensor_zone): callbacks and per-frame queries. buildWorldWithBehaviour() builds a scene
/// and runs its setup() once (pre-solve callbacks, tangent speeds); a viewer calls draw() every
/// frame (the laser's ray cast, the shapes inside a sensor zone).
#pragma once

#include <functional>
#include <string_view>

#include "perpdot/debug_draw.hpp"
#include "perpdot/scene.hpp"

namespace perpdot {

/// Callbacks of a built-in scene, for what its JSON cannot say.
struct SceneBehaviour {
    std::function<void(SceneWorld&)> setup;                   ///< may be empty
    std::function<void(const SceneWorld&, DebugDraw&)> draw;  ///< may be empty
};

/// The behaviour of a built-in scene, or nullptr when the scene needs none.
const SceneBehaviour* findSceneBehaviour(std::string_view sceneName);

/// buildWorld(scene), then the setup() of the behaviour named like the scene, if it has one.
SceneWorld buildWorldWithBehaviour(const Scene& scene);

}  // namespace perpdot
