/// @file
/// Joint definitions. Every joint is a set of constraint rows solved in the same loop as contacts,
/// each row's effective mass built from perpDot terms (see src/core/joint_*.cpp).
/// Anchors are in each body's local frame; `hertz` = 0 means rigid, otherwise a spring with
/// the given frequency and damping ratio.
#pragma once

#include <concepts>
#include <cstdint>

#include "perpdot/ids.hpp"
#include "perpdot/math.hpp"

namespace perpdot {

/// Which kind of joint a JointId names.
enum class JointType : uint8_t { Revolute, Prismatic, Distance, Weld, Wheel, Motor, Mouse, Gear, Pulley, Filter, Friction };

/// A joint definition of this header (World::createJoint): it names its joint type.
template <class Def>
concept JointDef = std::same_as<decltype(Def::type), const JointType>;

/// A hinge: the anchors coincide, B turns freely about them, optionally limited and motorised.
struct RevoluteJointDef {
    static constexpr JointType type = JointType::Revolute;  ///< the joint this defines
    BodyId bodyA{};  ///< the first body
    BodyId bodyB{};  ///< the second body
    Vec2 localAnchorA{};  ///< anchor point, A's frame
    Vec2 localAnchorB{};  ///< anchor point, B's frame
    float referenceAngle = 0.0f;  ///< θB - θA when the joint angle is zero
    bool enableLimit = false;  ///< keep the joint angle within [lowerAngle, upperAngle]
    float lowerAngle = 0.0f;   ///< rad
    float upperAngle = 0.0f;   ///< rad
    bool enableMotor = false;  ///< drive the relative angular speed to motorSpeed
    float motorSpeed = 0.0f;       ///< rad/s
    float maxMotorTorque = 0.0f;   ///< N·m
    bool collideConnected = false;  ///< whether A and B still collide with each other
    void* userData = nullptr;       ///< the application's pointer
};

/// A slider: B moves along an axis fixed in A and does not turn relative to A.
struct PrismaticJointDef {
    static constexpr JointType type = JointType::Prismatic;  ///< the joint this defines
    BodyId bodyA{};  ///< the first body
    BodyId bodyB{};  ///< the second body
    Vec2 localAnchorA{};  ///< anchor point, A's frame
    Vec2 localAnchorB{};  ///< anchor point, B's frame
    Vec2 localAxisA{1.0f, 0.0f};  ///< the sliding axis, A's frame (normalised on creation)
    float referenceAngle = 0.0f;  ///< θB - θA held by the joint
    bool enableLimit = false;     ///< keep the translation within [lower, upper]
    float lower = 0.0f;           ///< metres along the axis
    float upper = 0.0f;           ///< metres along the axis
    bool enableMotor = false;     ///< drive the relative speed along the axis to motorSpeed
    float motorSpeed = 0.0f;          ///< m/s
    float maxMotorForce = 0.0f;       ///< N
    bool collideConnected = false;  ///< whether A and B still collide with each other
    void* userData = nullptr;       ///< the application's pointer
};

/// A rod or spring between two anchors, optionally with a minimum and maximum length.
struct DistanceJointDef {
    static constexpr JointType type = JointType::Distance;  ///< the joint this defines
    BodyId bodyA{};  ///< the first body
    BodyId bodyB{};  ///< the second body
    Vec2 localAnchorA{};  ///< anchor point, A's frame
    Vec2 localAnchorB{};  ///< anchor point, B's frame
    float length = 1.0f;        ///< rest length, m
    float minLength = 0.0f;     ///< the anchors never come closer than this
    float maxLength = 1.0e30f;  ///< nor move further apart than this
    float hertz = 0.0f;         ///< 0: rigid rod of `length`
    float dampingRatio = 0.0f;  ///< spring damping ratio ζ
    bool collideConnected = false;  ///< whether A and B still collide with each other
    void* userData = nullptr;       ///< the application's pointer
};

/// Glues B to A: no relative motion (hertz = 0), or a linear and angular spring.
struct WeldJointDef {
    static constexpr JointType type = JointType::Weld;  ///< the joint this defines
    BodyId bodyA{};  ///< the first body
    BodyId bodyB{};  ///< the second body
    Vec2 localAnchorA{};  ///< anchor point, A's frame
    Vec2 localAnchorB{};  ///< anchor point, B's frame
    float referenceAngle = 0.0f;  ///< θB - θA held by the joint
    float hertz = 0.0f;         ///< 0: rigid
    float dampingRatio = 0.0f;  ///< spring damping ratio ζ
    bool collideConnected = false;  ///< whether A and B still collide with each other
    void* userData = nullptr;       ///< the application's pointer
};

/// A wheel on a suspension: B slides along a sprung axis of A and turns freely, optionally motorised.
struct WheelJointDef {
    static constexpr JointType type = JointType::Wheel;  ///< the joint this defines
    BodyId bodyA{};  ///< the chassis
    BodyId bodyB{};  ///< the wheel
    Vec2 localAnchorA{};  ///< anchor point, A's frame
    Vec2 localAnchorB{};  ///< anchor point, B's frame
    Vec2 localAxisA{0.0f, 1.0f};  ///< suspension axis
    float hertz = 1.0f;           ///< suspension spring
    float dampingRatio = 0.7f;    ///< suspension damping ratio ζ
    bool enableMotor = false;     ///< drive the wheel's relative angular speed to motorSpeed
    float motorSpeed = 0.0f;      ///< rad/s
    float maxMotorTorque = 0.0f;  ///< N·m
    bool collideConnected = false;  ///< whether A and B still collide with each other
    void* userData = nullptr;       ///< the application's pointer
};

/// Drives B towards A's frame offset by (linearOffset, angularOffset) with bounded force and torque.
struct MotorJointDef {
    static constexpr JointType type = JointType::Motor;  ///< the joint this defines
    BodyId bodyA{};  ///< the first body
    BodyId bodyB{};  ///< the second body
    Vec2 linearOffset{};          ///< in A's frame
    float angularOffset = 0.0f;     ///< target θB - θA, rad
    float maxForce = 1.0f;          ///< N
    float maxTorque = 1.0f;         ///< N·m
    float correctionFactor = 0.3f;  ///< fraction of the position error corrected per step, 0..1
    bool collideConnected = false;  ///< whether A and B still collide with each other
    void* userData = nullptr;       ///< the application's pointer
};

/// Pulls a point of bodyB towards a world target with a soft spring (mouse dragging).
struct MouseJointDef {
    static constexpr JointType type = JointType::Mouse;  ///< the joint this defines
    BodyId bodyA{};  ///< usually a static body; only bodyB moves
    BodyId bodyB{};  ///< the body dragged
    Vec2 target{}; ///< world
    float hertz = 5.0f;         ///< spring frequency
    float dampingRatio = 0.7f;  ///< spring damping ratio ζ
    float maxForce = 1000.0f;   ///< N
    bool collideConnected = false;  ///< whether A and B still collide with each other
    void* userData = nullptr;       ///< the application's pointer
};

/// Couples two revolute or prismatic joints so that coordinateA + ratio·coordinateB stays
/// constant, where a revolute joint's coordinate is its angle (rad) and a prismatic joint's its
/// translation along the axis (m) — Box2D's b2GearJoint. The gear acts between the moving bodies
/// (body B) of the two joints; each joint's body A must be static (perpdot solves two-body rows),
/// and the two moving bodies must differ. The joints' geometry is captured at creation: the gear
/// keeps working if they are destroyed later.
struct GearJointDef {
    static constexpr JointType type = JointType::Gear;  ///< the joint this defines
    /// A revolute or prismatic joint; the gear's body A is its body B.
    JointId jointA{};
    /// A revolute or prismatic joint; the gear's body B is its body B.
    JointId jointB{};
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
    static constexpr JointType type = JointType::Pulley;  ///< the joint this defines
    /// The body on the first side of the rope.
    BodyId bodyA{};
    /// The body on the second side of the rope.
    BodyId bodyB{};
    /// World point the rope to body A hangs from.
    Vec2 groundAnchorA{};
    /// World point the rope to body B hangs from.
    Vec2 groundAnchorB{};
    /// Where the rope holds body A, in A's frame.
    Vec2 localAnchorA{};
    /// Where the rope holds body B, in B's frame.
    Vec2 localAnchorB{};
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

/// Keeps two bodies from colliding and does nothing else: no rows (Box2D v3's b2FilterJointDef,
/// formerly its null joint). Being a joint, it keeps the two bodies in one island, so they sleep
/// and wake together; destroying it lets them collide again.
struct FilterJointDef {
    static constexpr JointType type = JointType::Filter;  ///< the joint this defines
    BodyId bodyA{};            ///< the first body
    BodyId bodyB{};            ///< the second body
    void* userData = nullptr;  ///< the application's pointer
};

/// Top-down friction between two bodies (Box2D 2.4's b2FrictionJoint): the relative velocity of
/// the anchors is driven to zero with a force of at most maxForce, the relative angular velocity
/// with a torque of at most maxTorque; no position is held. Against a static body A a sliding body
/// decelerates at maxForce/m and its spin at maxTorque/I, and it stays still under smaller loads.
/// (Box2D v3 has no friction joint: its motor joint with a zero correction factor does the same.)
struct FrictionJointDef {
    static constexpr JointType type = JointType::Friction;  ///< the joint this defines
    BodyId bodyA;  ///< usually the static ground
    BodyId bodyB;  ///< the body slowed down
    Vec2 localAnchorA;  ///< anchor point, A's frame
    Vec2 localAnchorB;  ///< anchor point, B's frame
    float maxForce = 0.0f;   ///< N, >= 0 and finite
    float maxTorque = 0.0f;  ///< N·m, >= 0 and finite
    bool collideConnected = false;  ///< whether A and B still collide with each other
    void* userData = nullptr;       ///< the application's pointer
};

}  // namespace perpdot
