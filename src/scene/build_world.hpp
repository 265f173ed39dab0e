// Building a Scene's bodies and joints into an existing World: what buildWorld() does after
// creating the World, and what a SceneScript's spawn() does with a fragment while a world runs.
#pragma once

#include <vector>

#include "perpdot/scene.hpp"

namespace perpdot {

struct SceneBodies {
    std::vector<BodyId> bodies;  // in scene order
    std::vector<JointId> joints;
};

// Creates the scene's bodies (with their shapes) and joints in `world`; its joints and actions
// must name its own bodies. The scene's gravity, time step and solver are not looked at.
// perpdot::Error naming the JSON path (`bodies[3].shapes[0]: …`) for what cannot be built.
SceneBodies addToWorld(World& world, const Scene& scene);

}  // namespace perpdot
