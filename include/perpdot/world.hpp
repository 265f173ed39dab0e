// The World owns bodies, shapes, joints and contacts and advances them with step().
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "perpdot/body.hpp"
#include "perpdot/events.hpp"
#include "perpdot/ids.hpp"
#include "perpdot/joints.hpp"
#include "perpdot/math.hpp"
#include "perpdot/mover.hpp"
#include "perpdot/queries.hpp"
#include "perpdot/shapes.hpp"

namespace perpdot {

struct WorldDef {
    Vec2 gravity{0.0f, -10.0f};
    int substeps = 4;                  // solver substeps per step (soft step)
    float contactHertz = 30.0f;        // contact stiffness, capped at a quarter of the substep rate
    float contactDampingRatio = 10.0f;
    float jointHertz = 60.0f;          // stiffness of rigid joint rows
    float jointDampingRatio = 2.0f;
    float contactPushMaxVelocity = 3.0f;  // m/s, cap on the speed that resolves overlap
    float restitutionThreshold = 1.0f;    // m/s, slower approaches do not bounce
    float maxLinearSpeed = 1000.0f;       // m/s, clamp against blow-ups (a 500 m/s bullet must fit)
    float hitEventThreshold = 1.0f;       // m/s, slower approaches report no ContactHitEvent
    bool enableSleep = true;
    bool enableWarmStarting = true;
    bool enableContinuous = true;         // time of impact for fast bodies against static shapes
};

struct ContactPoint {
    Vec2 point;               // world, midway between the surfaces
    float separation = 0.0f;  // negative when overlapping
    float normalImpulse = 0.0f;
    float tangentImpulse = 0.0f;
    uint32_t id = 0;          // feature id that carries warm starting between steps
};

struct ContactData {
    ShapeId shapeA, shapeB;
    Vec2 normal;  // from A to B
    int pointCount = 0;
    ContactPoint points[2];
};

// Pool sizes and health counters, for soak tests and tools.
struct WorldStats {
    int bodies = 0, shapes = 0, contacts = 0;            // live; contacts: every cached pair, touching or not
    int bodySlots = 0, shapeSlots = 0, contactSlots = 0;  // pool sizes (live + free): bounded in steady state
    int frozenBodies = 0;  // times a body was frozen because its state became NaN or infinite
};

class World {
public:
    explicit World(const WorldDef& def = {});
    ~World();
    World(World&&) noexcept;
    World& operator=(World&&) noexcept;
    World(const World&) = delete;
    World& operator=(const World&) = delete;

    // Advance by `timeStep` seconds. Never throws; allocates nothing once contacts are cached.
    void step(float timeStep);

    // --- bodies ---
    BodyId createBody(const BodyDef& def);
    void destroyBody(BodyId body);  // also destroys its shapes, joints and contacts
    bool isValid(BodyId body) const;
    std::vector<BodyId> bodies() const;  // in creation order of live bodies
    int bodyCount() const;

    BodyType bodyType(BodyId body) const;
    Vec2 position(BodyId body) const;      // body origin
    float angle(BodyId body) const;        // accumulated, not wrapped
    Transform transform(BodyId body) const;
    Vec2 worldCenter(BodyId body) const;   // centre of mass, world
    Vec2 localCenter(BodyId body) const;   // centre of mass, body frame
    Vec2 linearVelocity(BodyId body) const;
    float angularVelocity(BodyId body) const;
    float mass(BodyId body) const;
    float rotationalInertia(BodyId body) const;  // about the centre of mass
    Vec2 pointVelocity(BodyId body, Vec2 worldPoint) const;  // v + ω perp(P - CM)
    bool isAwake(BodyId body) const;
    float gravityScale(BodyId body) const;
    void* userData(BodyId body) const;

    void setTransform(BodyId body, Vec2 position, float angle);
    void setLinearVelocity(BodyId body, Vec2 v);
    void setAngularVelocity(BodyId body, float omega);
    void setAwake(BodyId body, bool awake);
    void setGravityScale(BodyId body, float scale);
    void setLinearDamping(BodyId body, float damping);
    void setAngularDamping(BodyId body, float damping);

    // --- forces and impulses (wake the body) ---
    void applyForce(BodyId body, Vec2 force, Vec2 worldPoint);  // F and τ = perpDot(P - CM, F)
    void applyForceToCenter(BodyId body, Vec2 force);
    void applyTorque(BodyId body, float torque);
    void applyLinearImpulse(BodyId body, Vec2 impulse, Vec2 worldPoint);  // Δv = J/m, Δω = perpDot(r, J)/I
    void applyLinearImpulseToCenter(BodyId body, Vec2 impulse);
    void applyAngularImpulse(BodyId body, float impulse);

    // --- shapes ---
    ShapeId createShape(BodyId body, const ShapeDef& def, const Circle& circle);
    ShapeId createShape(BodyId body, const ShapeDef& def, const Polygon& polygon);
    ShapeId createShape(BodyId body, const ShapeDef& def, const Segment& segment);
    ShapeId createShape(BodyId body, const ShapeDef& def, const Chain& chain);
    /// Attach a capsule; Error on a non-finite or out-of-range centre, radius <= 0, or centres
    /// closer than the linear slop (0.005 m).
    ShapeId createShape(BodyId body, const ShapeDef& def, const Capsule& capsule);
    void destroyShape(ShapeId shape);
    bool isValid(ShapeId shape) const;
    std::vector<ShapeId> shapes(BodyId body) const;
    BodyId shapeBody(ShapeId shape) const;
    ShapeType shapeType(ShapeId shape) const;
    const Circle& circle(ShapeId shape) const;    // Error if the shape is not a circle
    const Polygon& polygon(ShapeId shape) const;
    const Segment& segment(ShapeId shape) const;
    const Chain& chain(ShapeId shape) const;
    /// The capsule geometry (body frame); Error if the shape is not a capsule.
    const Capsule& capsule(ShapeId shape) const;
    float friction(ShapeId shape) const;
    float restitution(ShapeId shape) const;
    float density(ShapeId shape) const;
    bool isSensor(ShapeId shape) const;
    Filter filter(ShapeId shape) const;
    AABB aabb(ShapeId shape) const;  // tight world bounds
    void setFriction(ShapeId shape, float friction);
    void setRestitution(ShapeId shape, float restitution);
    void setDensity(ShapeId shape, float density);  // recomputes the body's mass
    float rollingResistance(ShapeId shape) const;
    float tangentSpeed(ShapeId shape) const;
    void setRollingResistance(ShapeId shape, float resistance);
    void setTangentSpeed(ShapeId shape, float speed);  // conveyor belt surface speed, m/s
    void enablePreSolveEvents(ShapeId shape, bool enable);  // ShapeDef::enablePreSolveEvents

    // --- joints ---
    JointId createJoint(const RevoluteJointDef& def);
    JointId createJoint(const PrismaticJointDef& def);
    JointId createJoint(const DistanceJointDef& def);
    JointId createJoint(const WeldJointDef& def);
    JointId createJoint(const WheelJointDef& def);
    JointId createJoint(const MotorJointDef& def);
    JointId createJoint(const MouseJointDef& def);
    void destroyJoint(JointId joint);
    bool isValid(JointId joint) const;
    std::vector<JointId> joints() const;
    JointType jointType(JointId joint) const;
    BodyId jointBodyA(JointId joint) const;
    BodyId jointBodyB(JointId joint) const;
    Vec2 jointAnchorA(JointId joint) const;  // world
    Vec2 jointAnchorB(JointId joint) const;  // world
    Vec2 jointReactionForce(JointId joint) const;   // on B, N, from the last step
    float jointReactionTorque(JointId joint) const; // on B, N·m, from the last step
    void setMouseTarget(JointId joint, Vec2 target);
    void setMotorSpeed(JointId joint, float speed);  // revolute, prismatic, wheel

    // --- contacts ---
    int contactCount() const;  // touching contacts
    std::vector<ContactData> contacts() const;  // touching contacts, for drawing and inspection

    // --- events (of the last step; valid until the next step) ---
    ContactEvents contactEvents() const;
    SensorEvents sensorEvents() const;
    void setPreSolve(PreSolveFn callback);  // empty function: none

    // --- queries ---
    // Closest hit of the ray origin -> origin + translation, if any.
    std::optional<RayHit> castRayClosest(Vec2 origin, Vec2 translation, const Filter& filter = {}) const;
    // Every hit (one per shape child), ordered by fraction.
    std::vector<RayHit> castRay(Vec2 origin, Vec2 translation, const Filter& filter = {}) const;
    // Shapes whose tight bounds overlap `box`.
    std::vector<ShapeId> overlapAABB(const AABB& box, const Filter& filter = {}) const;
    // Solid shapes (circles, polygons) containing the point.
    std::vector<ShapeId> overlapPoint(Vec2 point, const Filter& filter = {}) const;
    // Shapes overlapping a query shape placed at `xf`.
    std::vector<ShapeId> overlapShape(const Circle& shape, const Transform& xf, const Filter& filter = {}) const;
    std::vector<ShapeId> overlapShape(const Polygon& shape, const Transform& xf, const Filter& filter = {}) const;

    // --- character movers (perpdot/mover.hpp) ---
    /// Create a mover's kinematic capsule body with its capsule centre at `position`; Error on an
    /// invalid MoverDef or position.
    MoverState createMover(const MoverDef& def, Vec2 position);
    /// Move the mover for one frame of `dt` seconds (call after step(dt)): be pushed out of what
    /// moved into it, ride the platform under it, walk/fall/jump with collide-and-slide, climb
    /// steps, snap to the ground, push dynamic bodies it walks into, and place its body there.
    void moveMover(const MoverDef& def, MoverState& state, const MoverInput& input, float dt);

    // --- snapshots (bit-exact: restore + N steps equals N steps) ---
    // Versioned bytes of the whole state: settings, bodies, shapes, joints, and the contact cache
    // with its warm-start impulses. Not saved: userData pointers, the pre-solve callback, events.
    std::vector<uint8_t> snapshot() const;
    // Replaces this world's state with a snapshot's (ids from the snapshotted world stay valid, the
    // pre-solve callback stays). Corrupt or truncated bytes: Error, and the world is unchanged.
    void restore(std::span<const uint8_t> snapshot);

    WorldStats stats() const;

    // --- settings ---
    const WorldDef& settings() const;
    void setGravity(Vec2 gravity);
    void setSubsteps(int substeps);

    struct Impl;  // internal; src/core and src/collide see it

private:
    std::unique_ptr<Impl> impl_;
};

}  // namespace perpdot
