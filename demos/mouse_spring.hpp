// Pulling a body with the mouse: a damped spring from the grabbed body point P to the cursor,
//   F = k (target - P) - c v_P,   applied AT P, so grabbing a corner also spins the body (τ = perpDot(r, F)).
#pragma once

#include <optional>

#include "perpdot/world.hpp"

namespace perpdot::demo {

// The dynamic body whose shape contains world point p (the last created wins), if any.
std::optional<BodyId> bodyAt(const World& world, Vec2 p);

class MouseSpring {
public:
    static constexpr float hertz = 5.0f;         // spring frequency felt at the grabbed point
    static constexpr float dampingRatio = 0.7f;

    void grab(const World& world, BodyId body, Vec2 worldPoint);
    void release() { body_.reset(); }
    bool active(const World& world) const { return body_ && world.isValid(*body_); }
    void setTarget(Vec2 target) { target_ = target; }
    Vec2 target() const { return target_; }
    Vec2 anchor(const World& world) const;  // P, world

    // Call before every step. k and c come from the effective mass at P,
    // m_eff = 1 / (1/m + |r|²/I) (Hecker's denominator in the stiffest direction), so the spring
    // has the same frequency wherever the body is grabbed and stays stable under explicit integration.
    void applyForce(World& world) const;

private:
    std::optional<BodyId> body_;
    Vec2 localPoint_;  // P in the body frame
    Vec2 target_;
};

}  // namespace perpdot::demo
