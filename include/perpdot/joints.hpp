// Joint definitions. Every joint is a set of constraint rows solved in the same loop as contacts,
// each row's effective mass built from perpDot terms (see src/core/joint_*.cpp).
// Anchors are in each body's local frame; `hertz` = 0 means rigid, otherwise a spring with
// the given frequency and damping ratio.
#pragma once

#include <cstdint>

#include "perpdot/ids.hpp"
#include "perpdot/math.hpp"

namespace perpdot {

enum class JointType : uint8_t { Revolute, Prismatic, Distance, Weld, Wheel, Motor, Mouse, Gear, Pulley };

struct RevoluteJointDef {
    BodyId bodyA, bodyB;
    Vec2 localAnchorA, localAnchorB;
    float referenceAngle = 0.0f;  // θB - θA when the joint angle is zero
    bool enableLimit = false;
    float lowerAngle = 0.0f, upperAngle = 0.0f;
    bool enableMotor = false;
    float motorSpeed = 0.0f;       // rad/s
    float maxMotorTorque = 0.0f;   // N·m
    bool collideConnected = false;
    void* userData = nullptr;
};

struct PrismaticJointDef {
    BodyId bodyA, bodyB;
    Vec2 localAnchorA, localAnchorB;
    Vec2 localAxisA{1.0f, 0.0f};
    float referenceAngle = 0.0f;
    bool enableLimit = false;
    float lower = 0.0f, upper = 0.0f;  // metres along the axis
    bool enableMotor = false;
    float motorSpeed = 0.0f;          // m/s
    float maxMotorForce = 0.0f;       // N
    bool collideConnected = false;
    void* userData = nullptr;
};

struct DistanceJointDef {
    BodyId bodyA, bodyB;
    Vec2 localAnchorA, localAnchorB;
    float length = 1.0f;
    float minLength = 0.0f;
    float maxLength = 1.0e30f;
    float hertz = 0.0f;         // 0: rigid rod of `length`
    float dampingRatio = 0.0f;
    bool collideConnected = false;
    void* userData = nullptr;
};

struct WeldJointDef {
    BodyId bodyA, bodyB;
    Vec2 localAnchorA, localAnchorB;
    float referenceAngle = 0.0f;
    float hertz = 0.0f;         // 0: rigid
    float dampingRatio = 0.0f;
    bool collideConnected = false;
    void* userData = nullptr;
};

struct WheelJointDef {
    BodyId bodyA, bodyB;  // A: chassis, B: wheel
    Vec2 localAnchorA, localAnchorB;
    Vec2 localAxisA{0.0f, 1.0f};  // suspension axis
    float hertz = 1.0f;           // suspension spring
    float dampingRatio = 0.7f;
    bool enableMotor = false;
    float motorSpeed = 0.0f;
    float maxMotorTorque = 0.0f;
    bool collideConnected = false;
    void* userData = nullptr;
};

// Drives B towards A's frame offset by (linearOffset, angularOffset) with bounded force and torque.
struct MotorJointDef {
    BodyId bodyA, bodyB;
    Vec2 linearOffset;            // in A's frame
    float angularOffset = 0.0f;
    float maxForce = 1.0f;
    float maxTorque = 1.0f;
    float correctionFactor = 0.3f;
    bool collideConnected = false;
    void* userData = nullptr;
};

// Pulls a point of bodyB towards a world target with a soft spring (mouse dragging).
struct MouseJointDef {
    BodyId bodyA;  // usually a static body; only bodyB moves
    BodyId bodyB;
    Vec2 target;   // world
    float hertz = 5.0f;
    float dampingRatio = 0.7f;
    float maxForce = 1000.0f;
    bool collideConnected = false;
    void* userData = nullptr;
};

/// Couples two revolute or prismatic joints so that coordinateA + ratio·coordinateB stays
/// constant, where a revolute joint's coordinate is its angle (rad) and a prismatic joint's its
/// translation along the axis (m) — Box2D's b2GearJoint. The gear acts between the moving bodies
/// (body B) of the two joints; each joint's body A must be static (perpdot solves two-body rows),
/// and the two moving bodies must differ. The joints' geometry is captured at creation: the gear
/// keeps working if they are destroyed later.
struct GearJointDef {
    /// A revolute or prismatic joint; the gear's body A is its body B.
    JointId jointA;
    /// A revolute or prismatic joint; the gear's body B is its body B.
    JointId jointB;
    /// Finite and not 0; negative turns both the same way.
    float ratio = 1.0f;
    /// Whether the two geared bodies collide with each other.
    bool collideConnected = false;
    /// Not used by the engine.
    void* userData = nullptr;
};

/// Two bodies hung from two fixed ground points by one rope over a pulley: lengthA + ratio·lengthB
/// stays constant, where length is the distance from a ground anchor to the body's anchor
/// (Box2D's b2PulleyJoint, an equality: the rope also pushes).
struct PulleyJointDef {
    /// The body on the first side of the rope.
    BodyId bodyA;
    /// The body on the second side of the rope.
    BodyId bodyB;
    /// World point the rope to body A hangs from.
    Vec2 groundAnchorA;
    /// World point the rope to body B hangs from.
    Vec2 groundAnchorB;
    /// Where the rope holds body A, in A's frame.
    Vec2 localAnchorA;
    /// Where the rope holds body B, in B's frame.
    Vec2 localAnchorB;
    /// Rope length on A's side (m, > 0): usually the anchors' current distance.
    float lengthA = 1.0f;
    /// Rope length on B's side (m, > 0).
    float lengthB = 1.0f;
    /// Block and tackle ratio (> 0, finite): B's side moves 1/ratio as far as A's.
    float ratio = 1.0f;
    /// Whether the two bodies collide with each other.
    bool collideConnected = false;
    /// Not used by the engine.
    void* userData = nullptr;
};

}  // namespace perpdot
