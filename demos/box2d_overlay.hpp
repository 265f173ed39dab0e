// The cross-check overlay: the same scene stepped by Box2D 2.4's b2World (through the public
// crosscheck API, so no Box2D header here), drawn as outlines over perpdot's bodies, with the
// largest position error between the two. Box2D sees the scene as defined: no panel tweaks and
// no mouse forces, so dragging a body makes the two part ways on purpose.
#pragma once

#include <string>

#include "perpdot/crosscheck.hpp"
#include "perpdot/debug_draw.hpp"
#include "perpdot/scene.hpp"

namespace perpdot::demo {

// Outline of one scene shape placed at body frame `xf`.
void drawSceneShape(DebugDraw& draw, const SceneShape& shape, const Transform& xf, Color color);

class Box2DOverlay {
public:
    // Forget the recorded Box2D run (new scene or reset).
    void clear() { trajectory_ = {}; }
    // Box2D's state at `sim.stepIndex`, recording further ahead when needed.
    void update(const SceneWorld& sim);
    void draw(DebugDraw& draw, const SceneWorld& sim) const;

    float maxPositionError() const { return maxError_; }  // metres, over the non-static bodies
    const std::string& worstBody() const { return worstBody_; }

private:
    crosscheck::Trajectory trajectory_;
    int frame_ = 0;
    float maxError_ = 0.0f;
    std::string worstBody_;
};

}  // namespace perpdot::demo
