/// @file
/// Contact and sensor events, buffered during World::step() and read after it (Box2D v3 style),
/// and the pre-solve callback that may disable a contact for one step (one-way platforms).
#pragma once

#include <functional>
#include <span>

#include "perpdot/ids.hpp"
#include "perpdot/math.hpp"

namespace perpdot {

struct ContactData;

/// Two shapes started touching (their manifold gained points) — needs enableContactEvents on either.
struct ContactBeginTouchEvent {
    ShapeId shapeA{};  ///< one shape of the contact
    ShapeId shapeB{};  ///< the other
};

/// Two shapes stopped touching, or their contact was destroyed (the ids may then be stale).
struct ContactEndTouchEvent {
    ShapeId shapeA{};  ///< one shape of the contact
    ShapeId shapeB{};  ///< the other
};

/// A touching contact whose approach speed −v_rel·n exceeded WorldDef::hitEventThreshold at the start
/// of the step — needs enableHitEvents on either shape. The point is the fastest-approaching one.
struct ContactHitEvent {
    ShapeId shapeA{};  ///< one shape of the contact
    ShapeId shapeB{};  ///< the other; the normal points from A to B
    Vec2 point{};          ///< world
    Vec2 normal{};         ///< from A to B
    float approachSpeed = 0.0f;  ///< m/s, > 0
};

/// The events of the last step; the spans stay valid until the next step().
struct ContactEvents {
    std::span<const ContactBeginTouchEvent> beginEvents{};  ///< contacts that started touching
    std::span<const ContactEndTouchEvent> endEvents{};    ///< contacts that stopped touching
    std::span<const ContactHitEvent> hitEvents{};         ///< touching contacts that hit hard enough
};

/// A shape (the visitor) began overlapping a sensor shape.
struct SensorBeginTouchEvent {
    ShapeId sensorShape{}; ///< the sensor
    ShapeId visitorShape{};  ///< the shape that entered it
};
/// A shape (the visitor) stopped overlapping a sensor shape, or one of them was destroyed.
struct SensorEndTouchEvent {
    ShapeId sensorShape{}; ///< the sensor
    ShapeId visitorShape{};  ///< the shape that left it
};
/// The sensor events of the last step; the spans stay valid until the next step().
struct SensorEvents {
    std::span<const SensorBeginTouchEvent> beginEvents{};  ///< shapes that entered a sensor
    std::span<const SensorEndTouchEvent> endEvents{};    ///< shapes that left a sensor
};

/// A joint whose reaction passed its break limits (World::setJointBreakLimits) at the end of a step.
struct JointBreakEvent {
    JointId joint{};        ///< the joint; stale if it was destroyed
    Vec2 force{};           ///< its reaction force on body B averaged over the step, N
    float torque = 0.0f;    ///< its reaction torque on body B averaged over the step, N·m
    bool destroyed = false; ///< whether the step destroyed it (its break limits said so)
    void* userData = nullptr;  ///< the joint's userData
};

/// The joint events of the last step; the span stays valid until the next step().
struct JointEvents {
    std::span<const JointBreakEvent> breakEvents{};  ///< joints that broke
};

/// Called during step()'s narrowphase for every touching contact where either shape has
/// ShapeDef::enablePreSolveEvents; return false to disable the contact for this step. The world is
/// locked: creating or destroying anything throws perpdot::Error.
using PreSolveFn = std::function<bool(ShapeId shapeA, ShapeId shapeB, const ContactData& contact)>;

/// World::setJointDestroyedCallback: a joint that destroyBody destroyed with its body.
using JointDestroyedFn = std::function<void(JointId joint, void* userData)>;

}  // namespace perpdot
