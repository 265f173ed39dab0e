// A perpdot::Scene built into Box2D 2.4's own b2World, as exactly as Box2D allows; the reference
// side of the cross-check. Differences that Box2D 2.4 forces are listed in docs/crosscheck.md.
#pragma once

#include <memory>
#include <vector>

#include <box2d/box2d.h>

#include "perpdot/scene.hpp"

namespace perpdot::crosscheck {

class Box2DScene {
public:
    // Throws perpdot::Error for what Box2D cannot build (unknown body name in a joint or action).
    explicit Box2DScene(const Scene& scene);

    // Applies the actions of step `stepIndex()` (before stepping, as the scene format says),
    // then b2World::Step(timestep, velocity iterations, position iterations).
    void step();
    int stepIndex() const { return stepIndex_; }

    // Creates a fragment's bodies and joints (its joints name its own bodies) in the running world;
    // returns its bodies in fragment order. The scene's own bodies stay what body() returns.
    std::vector<b2Body*> add(const Scene& fragment);
    // Destroys a body made by add(), with its fixtures, joints and contacts.
    void destroy(b2Body* body);

    const Scene& scene() const { return scene_; }
    b2Body* body(int sceneIndex) const { return bodies_[size_t(sceneIndex)]; }

    // Contacts whose manifolds touch, sensors excluded (what perpdot's World::contactCount() counts).
    int touchingContactCount() const;

private:
    void applyActions(int step);

    Scene scene_;
    std::unique_ptr<b2World> world_;  // bodies keep pointers to it: never moved
    std::vector<b2Body*> bodies_;
    std::vector<b2Body*> actionBodies_;  // actions[i] acts on actionBodies_[i]
    int stepIndex_ = 0;
};

}  // namespace perpdot::crosscheck
