// What a scene file cannot say about a scene that changes while it runs: bodies created and
// destroyed at given steps (`ragdoll_rain`), a kinematic body driven along a path (`junkyard`). A SceneScript is called before each step with a
// SceneEditor; perpdot's World and Box2D's b2World each implement the editor
// (crosscheck/stepper.cpp), so both engines see the same spawns and destroys at the same steps.
#pragma once

#include <memory>
#include <string_view>

#include "perpdot/scene.hpp"

namespace perpdot {

// The edits a script may make to a running world.
class SceneEditor {
public:
    using Group = int;  // the bodies of one spawn()

    virtual ~SceneEditor() = default;
    // Creates the fragment's bodies and joints (its joints name its own bodies; its gravity,
    // time step and actions are ignored) and returns them as one group.
    virtual Group spawn(const Scene& fragment) = 0;
    // Destroys the group's bodies, with their shapes, joints and contacts.
    virtual void destroy(Group group) = 0;
    // Sets the velocity of the scene's body `sceneBody` (its index in Scene::bodies), e.g. to
    // drive a kinematic body along a path; Error for an index the scene does not have.
    virtual void setVelocity(int sceneBody, Vec2 linearVelocity, float angularVelocity) = 0;
};

class SceneScript {
public:
    virtual ~SceneScript() = default;
    // Called before step `step` (step 0 first), before that step's scene actions are applied.
    virtual void beforeStep(int step, SceneEditor& editor) = 0;
    // A copy of the script in its current state, saved beside a world snapshot so that a rolled
    // back run continues the script from the same point.
    virtual std::unique_ptr<SceneScript> clone() const = 0;
};

// A fresh script (with its own state) for the built-in scene named `sceneName`; nullptr when the
// scene has none. A scene exported to JSON keeps its name, so loading it back finds the script.
std::unique_ptr<SceneScript> makeSceneScript(std::string_view sceneName);

}  // namespace perpdot
