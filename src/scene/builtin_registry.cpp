// builtinScenes() joins the groups of builtin_registry.hpp; findScene() resolves a name or a file.
#include "scene/builtin_registry.hpp"

#include <filesystem>
#include <utility>

#include "perpdot/error.hpp"

namespace perpdot {
namespace {

std::vector<BuiltinScene> allScenes() {
    std::vector<BuiltinScene> all;
    for (std::vector<BuiltinScene> group : {coreScenes(), benchScenes(), demoScenes(), featureScenes(), jointScenes(), coupledJointScenes(), stressScenes()})
        for (BuiltinScene& entry : group) {
            for (const BuiltinScene& existing : all)
                if (existing.name == entry.name) throw Error("built-in scene \"" + entry.name + "\" is defined twice");
            // The entry's name and description are the scene's.
            entry.make = [make = std::move(entry.make), name = entry.name, description = entry.description] {
                Scene scene = make();
                scene.name = name;
                scene.description = description;
                return scene;
            };
            all.push_back(std::move(entry));
        }
    return all;
}

}  // namespace

const std::vector<BuiltinScene>& builtinScenes() {
    static const std::vector<BuiltinScene> scenes = allScenes();
    return scenes;
}

Scene findScene(const std::string& nameOrPath) {
    for (const BuiltinScene& entry : builtinScenes())
        if (entry.name == nameOrPath) return entry.make();
    std::error_code error;
    if (!std::filesystem::is_regular_file(nameOrPath, error))
        throw Error("\"" + nameOrPath + "\" is neither a built-in scene (see `perpdot list`) nor a scene file");
    Scene scene = loadScene(nameOrPath);
    if (scene.name.empty()) scene.name = std::filesystem::path(nameOrPath).stem().string();
    return scene;
}

}  // namespace perpdot
