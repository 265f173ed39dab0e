// The viewer's character mover (perpdot/mover.hpp) driven by keys: A and D walk, W jumps. The
// scene's SceneMover places it on load; M places one at the mouse in any scene.
#pragma once

#include <SDL.h>

#include <optional>

#include "perpdot/debug_draw.hpp"
#include "perpdot/world.hpp"

namespace perpdot::demo {

class PlayerMover {
public:
    static constexpr float walkSpeed = 4.0f;  // m/s

    // A new mover at `position` with `def`, replacing the one this world had.
    void place(World& world, const MoverDef& def, Vec2 position);
    // The world was rebuilt: its mover went with it.
    void forget();
    bool active() const { return state_.has_value(); }
    const MoverState& state() const { return *state_; }

    // A/D held walk, W jumps once; returns whether the key is one of the mover's.
    bool handleKey(SDL_Keycode key, bool down);
    // One frame of the mover, after World::step(dt).
    void move(World& world, float dt);
    // Headless runs: walk right, and jump where the last frame's walk was blocked (a step, a box).
    void autopilot(float dt);
    // The feet: green while grounded, grey in the air.
    void draw(DebugDraw& draw) const;

private:
    MoverDef def_;
    std::optional<MoverState> state_;
    bool left_ = false, right_ = false, jump_ = false;
};

}  // namespace perpdot::demo
