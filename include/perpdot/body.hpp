// Body definitions. A body is a centre of mass with mass m, scalar inertia I, position,
// angle, velocity v and angular velocity ω; its shapes give it mass.
#pragma once

#include <cstdint>

#include "perpdot/math.hpp"

namespace perpdot {

enum class BodyType : uint8_t {
    Static,     // zero velocity, infinite mass
    Kinematic,  // moved by its velocity only, infinite mass
    Dynamic,    // moved by forces and contacts
};

struct BodyDef {
    BodyType type = BodyType::Static;
    Vec2 position;               // body origin, world frame
    float angle = 0.0f;          // radians, counter-clockwise
    Vec2 linearVelocity;         // of the centre of mass
    float angularVelocity = 0.0f;
    float linearDamping = 0.0f;  // dv/dt = -c v
    float angularDamping = 0.0f;
    float gravityScale = 1.0f;
    bool fixedRotation = false;
    bool bullet = false;         // continuous collision against dynamic bodies too
    bool allowSleep = true;
    bool awake = true;
    void* userData = nullptr;
};

}  // namespace perpdot
