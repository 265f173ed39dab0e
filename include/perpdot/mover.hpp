// A kinematic character mover: an upright capsule moved by collide-and-slide, with a slope
// limit, step-up, ground snapping, moving and one-way platforms, pushing and being pushed.
//
// Call World::moveMover() once per frame *after* World::step(dt), with the same dt (platforms have
// then moved, and the mover rides them by what they did). Its state is plain data (MoverState) the
// game keeps; the capsule itself lives in the World as a kinematic body (so dynamic bodies collide
// with it), and a World snapshot plus a copy of MoverState restore the mover exactly.
#pragma once

#include <cstdint>

#include "perpdot/ids.hpp"
#include "perpdot/math.hpp"
#include "perpdot/shapes.hpp"

namespace perpdot {

/// What a mover is: its capsule, how it walks, and what it treats as ground.
struct MoverDef {
    float radius = 0.3f;        ///< capsule radius, m
    float halfHeight = 0.4f;    ///< half the distance between the cap centres (the capsule stands upright), m
    float maxSlope = 0.8727f;   ///< steepest walkable slope, radians (50°); steeper surfaces are walls
    float stepHeight = 0.3f;    ///< tallest step climbed while walking, m
    float snapDistance = 0.3f;  ///< ground this far below the feet holds a grounded mover down (stairs down, crests)
    float skin = 0.01f;         ///< gap kept to every surface, m
    float jumpSpeed = 6.0f;     ///< upward speed of a jump, m/s
    float mass = 80.0f;         ///< kg: the momentum it gives dynamic bodies and takes from them
    float maxPushForce = 1500.0f;  ///< N, cap on the force it applies to one dynamic body it walks into
    float pushDamping = 8.0f;   ///< 1/s, decay of velocity it was given by others while grounded
    int maxIterations = 4;      ///< collide-and-slide passes per move
    Filter filter{};            ///< the capsule's collision filter (casts and its body)
    uint16_t oneWayCategories = 0;  ///< shapes with any of these category bits are solid only from above
};

/// Throws perpdot::Error naming the first invalid field (non-finite, non-positive size, maxSlope
/// outside (0, π/2), maxIterations < 1, …).
void validate(const MoverDef& def);

/// What the game asks for this frame.
struct MoverInput {
    float walkSpeed = 0.0f;  ///< m/s along the ground (+ is +x)
    bool jump = false;       ///< leave the ground at MoverDef::jumpSpeed (only when grounded)
};

/// The mover's whole state: plain data, copyable, comparable, safe to keep beside a snapshot.
struct MoverState {
    BodyId body{};            ///< its kinematic body in the World
    ShapeId shape{};          ///< the capsule shape on that body
    Vec2 position{};          ///< capsule centre, world
    Vec2 velocity{};          ///< own velocity (walking, falling), m/s
    Vec2 pushVelocity{};      ///< velocity given by dynamic bodies that pushed it, m/s
    bool grounded = false;    ///< standing on walkable ground
    Vec2 groundNormal{0.0f, 1.0f};  ///< normal of that ground
    ShapeId ground{};         ///< the shape it stands on (invalid when airborne)
    Vec2 lastDisplacement{};  ///< how far the last moveMover() moved it, m
    /// Exact equality of every field (a replayed mover compares equal).
    friend bool operator==(const MoverState&, const MoverState&) = default;
};

}  // namespace perpdot
