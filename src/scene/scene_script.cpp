// The scripts of the built-in scenes, by name.
#include "scene/scene_script.hpp"

#include "scene/builtin_registry.hpp"

namespace perpdot {

std::unique_ptr<SceneScript> makeSceneScript(std::string_view sceneName) {
    if (sceneName == "ragdoll_rain") return makeRagdollRainScript();
    if (sceneName == "junkyard") return makeJunkyardScript();
    return nullptr;
}

}  // namespace perpdot
