// One engine running one Scene, seen the same way whichever engine it is, so the cross-check,
// `perpdot record` and `perpdot bench` drive perpdot and Box2D with one loop.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "perpdot/crosscheck.hpp"
#include "perpdot/scene.hpp"
#include "scene/scene_script.hpp"

namespace perpdot::crosscheck {

// What the comparison needs of one non-static body at one frame.
struct BodySample {
    BodyState state;
    Vec2 center;           // centre of mass, world
    float mass = 0.0f;     // 0 for kinematic bodies
    float inertia = 0.0f;  // about the centre of mass
    float gravityScale = 1.0f;
};

class Stepper {
public:
    virtual ~Stepper() = default;
    // Runs the scene's script (scene_script.hpp) and applies the scene's actions for the next step
    // index, then advances one time step.
    virtual void step() = 0;
    // The scene's non-static bodies, in scene order.
    virtual void sample(std::vector<BodySample>& out) const = 0;
    // Every non-static body alive: the scene's, then those its script spawned, oldest spawn first.
    virtual void sampleAll(std::vector<BodySample>& out) const = 0;
    // Touching contacts, sensors excluded.
    virtual int contactCount() const = 0;
};

// The scene in `engine`, with the script of the built-in scene of its name (makeSceneScript), if any.
std::unique_ptr<Stepper> makeStepper(Engine engine, const Scene& scene);
// The scene in `engine`, run by `script` (may be nullptr: none); perpdot on `workerCount` threads.
std::unique_ptr<Stepper> makeStepper(Engine engine, const Scene& scene, std::unique_ptr<SceneScript> script,
                                     int workerCount = 1);

// The scene body's name, or its default `body<index>` when unnamed.
std::string bodyName(const Scene& scene, size_t index);

// Names of the scene's non-static bodies, in scene order (the trajectory's bodies).
std::vector<std::string> movingBodyNames(const Scene& scene);

}  // namespace perpdot::crosscheck
