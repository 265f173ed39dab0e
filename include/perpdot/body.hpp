/// @file
/// Body definitions. A body is a centre of mass with mass m, scalar inertia I, position,
/// angle, velocity v and angular velocity ω; its shapes give it mass.
#pragma once

#include <cstdint>

#include "perpdot/math.hpp"

namespace perpdot {

/// How a body moves.
enum class BodyType : uint8_t {
    Static,     ///< zero velocity, infinite mass
    Kinematic,  ///< moved by its velocity only, infinite mass
    Dynamic,    ///< moved by forces and contacts
};

/// Everything createBody() needs; designated initialisers name the fields that differ from the defaults.
struct BodyDef {
    BodyType type = BodyType::Static;  ///< static, kinematic or dynamic
    Vec2 position{};             ///< body origin, world frame
    float angle = 0.0f;          ///< radians, counter-clockwise
    Vec2 linearVelocity{};       ///< of the centre of mass
    float angularVelocity = 0.0f;  ///< ω, rad/s, counter-clockwise
    float linearDamping = 0.0f;  ///< dv/dt = -c v
    float angularDamping = 0.0f;  ///< dω/dt = -c ω
    float gravityScale = 1.0f;  ///< multiplies the world's gravity for this body
    bool fixedRotation = false;  ///< infinite rotational inertia: never turns
    bool bullet = false;         ///< continuous collision against dynamic bodies too
    bool allowSleep = true;  ///< may fall asleep when it and its island come to rest
    bool awake = true;       ///< starts awake (false: asleep until something wakes it)
    void* userData = nullptr;  ///< the application's pointer, returned by World::userData()
};

}  // namespace perpdot
