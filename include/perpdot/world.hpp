/// @file
/// The World owns bodies, shapes, joints and contacts and advances them with step().
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "perpdot/body.hpp"
#include "perpdot/events.hpp"
#include "perpdot/ids.hpp"
#include "perpdot/joints.hpp"
#include "perpdot/math.hpp"
#include "perpdot/mover.hpp"
#include "perpdot/queries.hpp"
#include "perpdot/shapes.hpp"
#include "perpdot/tasks.hpp"

namespace perpdot {

/// The world's settings: gravity and the solver's soft-step parameters (Box2D v3's defaults).
struct WorldDef {
    Vec2 gravity{0.0f, -10.0f};  ///< m/s²
    int substeps = 4;                  ///< solver substeps per step (soft step)
    float contactHertz = 30.0f;        ///< contact stiffness, capped at a quarter of the substep rate
    float contactDampingRatio = 10.0f;  ///< ζ of the contact rows
    float jointHertz = 60.0f;          ///< stiffness of rigid joint rows
    float jointDampingRatio = 2.0f;  ///< ζ of rigid joint rows
    float contactPushMaxVelocity = 3.0f;  ///< m/s, cap on the speed that resolves overlap
    float restitutionThreshold = 1.0f;    ///< m/s, slower approaches do not bounce
    float maxLinearSpeed = 1000.0f;       ///< m/s, clamp against blow-ups (a 500 m/s bullet must fit)
    float hitEventThreshold = 1.0f;       ///< m/s, slower approaches report no ContactHitEvent
    bool enableSleep = true;  ///< bodies at rest fall asleep (islands)
    bool enableWarmStarting = true;  ///< start each step from the last step's impulses
    bool enableContinuous = true;         ///< time of impact for fast bodies against static shapes
    /// m: a touching contact keeps its manifold (normal, anchors) while its bodies' relative pose
    /// moves its anchors less than this since the last narrowphase; 0 rebuilds every step, as
    /// Box2D 2.4's b2World does. Kept manifolds are what hold tall stacks up (docs/stress.md).
    float contactReuseDistance = 0.05f;
    /// Rest on Box2D 2.4's polygon skin as b2World does: polygons and segments keep 1 cm of skin
    /// each, so a 1 m box rests at 0.515 m (like-for-like cross-checks). Off (the default): contacts
    /// are measured between the true surfaces and the skin is only a speculative margin.
    bool box2dSkin = false;
    /// Threads that run the step: 1 runs it on the caller's thread alone; N > 1 runs its parallel
    /// stages on N workers (oneTBB, or enqueueTask/finishTask when both are given). The results
    /// are bit-identical for every worker count.
    int workerCount = 1;
    /// A game's job system (both or neither): perpdot hands it its parallel loops (tasks.hpp).
    EnqueueTaskFn* enqueueTask = nullptr;
    FinishTaskFn* finishTask = nullptr;  ///< waits for a task of enqueueTask
    void* userTaskContext = nullptr;     ///< passed to enqueueTask and finishTask
};

/// One point of a contact manifold.
struct ContactPoint {
    Vec2 point;               ///< world, midway between the surfaces
    float separation = 0.0f;  ///< negative when overlapping
    float normalImpulse = 0.0f;  ///< N·s along the normal, accumulated over the last step
    float tangentImpulse = 0.0f;  ///< N·s of friction along perp(normal)
    uint32_t id = 0;          ///< feature id that carries warm starting between steps
};

/// A touching contact between two shapes: its manifold and impulses.
struct ContactData {
    ShapeId shapeA;  ///< one shape
    ShapeId shapeB;  ///< the other; the normal points from A to B
    Vec2 normal;  ///< from A to B
    int pointCount = 0;  ///< points used, 0..2
    ContactPoint points[2];  ///< the first pointCount are valid
};

/// Pool sizes and health counters, for soak tests and tools.
struct WorldStats {
    int bodies = 0;        ///< live bodies
    int shapes = 0;        ///< live shapes
    int contacts = 0;      ///< every cached pair, touching or not
    int bodySlots = 0;     ///< body pool size (live + free): bounded in steady state
    int shapeSlots = 0;    ///< shape pool size (live + free)
    int contactSlots = 0;  ///< contact pool size (live + free)
    int frozenBodies = 0;  ///< times a body was frozen because its state became NaN or infinite
};

/// The simulation: bodies, shapes, joints and contacts, advanced by step(). Every call that takes an
/// id throws perpdot::Error when the id is stale (its object was destroyed) or null.
class World {
public:
    explicit World(const WorldDef& def = {});  ///< An empty world with settings `def`.
    ~World();  ///< Destroys everything in the world.
    /// Takes over another world; the moved-from world may only be destroyed or assigned.
    World(World&&) noexcept;
    World& operator=(World&&) noexcept;  ///< Takes over another world.
    World(const World&) = delete;  ///< Not copyable: use snapshot() and restore().
    World& operator=(const World&) = delete;  ///< Not copyable.

    /// Advance by `timeStep` seconds. Never throws; allocates nothing once contacts are cached.
    void step(float timeStep);

    // --- bodies ---
    BodyId createBody(const BodyDef& def);  ///< A new body; Error if `def` is invalid (NaN, ...).
    void destroyBody(BodyId body);  ///< also destroys its shapes, joints and contacts
    bool isValid(BodyId body) const;  ///< Whether `body` names a live body.
    std::vector<BodyId> bodies() const;  ///< in creation order of live bodies
    int bodyCount() const;  ///< Live bodies.

    BodyType bodyType(BodyId body) const;  ///< Static, kinematic or dynamic.
    Vec2 position(BodyId body) const;      ///< body origin
    float angle(BodyId body) const;        ///< accumulated, not wrapped
    Transform transform(BodyId body) const;  ///< Origin and rotation.
    Vec2 worldCenter(BodyId body) const;   ///< centre of mass, world
    Vec2 localCenter(BodyId body) const;   ///< centre of mass, body frame
    Vec2 linearVelocity(BodyId body) const;  ///< v of the centre of mass
    float angularVelocity(BodyId body) const;  ///< ω, rad/s
    float mass(BodyId body) const;  ///< kg; 0 for static and kinematic bodies
    float rotationalInertia(BodyId body) const;  ///< about the centre of mass
    Vec2 pointVelocity(BodyId body, Vec2 worldPoint) const;  ///< v + ω perp(P - CM)
    bool isAwake(BodyId body) const;  ///< false while asleep
    float gravityScale(BodyId body) const;  ///< BodyDef::gravityScale
    void* userData(BodyId body) const;  ///< BodyDef::userData

    void setTransform(BodyId body, Vec2 position, float angle);  ///< Teleport the body origin (wakes it).
    void setLinearVelocity(BodyId body, Vec2 v);  ///< v of the centre of mass
    void setAngularVelocity(BodyId body, float omega);  ///< ω, rad/s
    void setAwake(BodyId body, bool awake);  ///< Wake the body, or put it to sleep.
    void setGravityScale(BodyId body, float scale);  ///< BodyDef::gravityScale
    void setLinearDamping(BodyId body, float damping);  ///< BodyDef::linearDamping
    void setAngularDamping(BodyId body, float damping);  ///< BodyDef::angularDamping

    // --- forces and impulses (wake the body) ---
    void applyForce(BodyId body, Vec2 force, Vec2 worldPoint);  ///< F and τ = perpDot(P - CM, F)
    void applyForceToCenter(BodyId body, Vec2 force);  ///< F at the centre of mass: no torque
    void applyTorque(BodyId body, float torque);  ///< τ, N·m, acting during the next step
    void applyLinearImpulse(BodyId body, Vec2 impulse, Vec2 worldPoint);  ///< Δv = J/m, Δω = perpDot(r, J)/I
    void applyLinearImpulseToCenter(BodyId body, Vec2 impulse);  ///< Δv = J/m
    void applyAngularImpulse(BodyId body, float impulse);  ///< Δω = L/I

    // --- shapes ---
    /// A new shape on `body`, which gains its mass (Error if the geometry or `def` is invalid).
    ShapeId createShape(BodyId body, const ShapeDef& def, const Circle& circle);
    /// A new polygon on `body`.
    ShapeId createShape(BodyId body, const ShapeDef& def, const Polygon& polygon);
    /// A new segment on `body`.
    ShapeId createShape(BodyId body, const ShapeDef& def, const Segment& segment);
    ShapeId createShape(BodyId body, const ShapeDef& def, const Chain& chain);  ///< A new chain on `body`.
    /// Attach a capsule; Error on a non-finite or out-of-range centre, radius <= 0, or centres
    /// closer than the linear slop (0.005 m).
    ShapeId createShape(BodyId body, const ShapeDef& def, const Capsule& capsule);
    void destroyShape(ShapeId shape);  ///< Also destroys its contacts; the body's mass is recomputed.
    bool isValid(ShapeId shape) const;  ///< Whether `shape` names a live shape.
    std::vector<ShapeId> shapes(BodyId body) const;  ///< The shapes of `body`.
    BodyId shapeBody(ShapeId shape) const;  ///< The body the shape is on.
    ShapeType shapeType(ShapeId shape) const;  ///< Which geometry it holds.
    const Circle& circle(ShapeId shape) const;    ///< Error if the shape is not a circle
    const Polygon& polygon(ShapeId shape) const;  ///< Error if not a polygon
    const Segment& segment(ShapeId shape) const;  ///< Error if not a segment
    const Chain& chain(ShapeId shape) const;  ///< Error if not a chain
    /// The capsule geometry (body frame); Error if the shape is not a capsule.
    const Capsule& capsule(ShapeId shape) const;
    float friction(ShapeId shape) const;  ///< ShapeDef::friction
    float restitution(ShapeId shape) const;  ///< ShapeDef::restitution
    float density(ShapeId shape) const;  ///< ShapeDef::density
    bool isSensor(ShapeId shape) const;  ///< ShapeDef::sensor
    Filter filter(ShapeId shape) const;  ///< ShapeDef::filter
    AABB aabb(ShapeId shape) const;  ///< tight world bounds
    void setFriction(ShapeId shape, float friction);  ///< ShapeDef::friction
    void setRestitution(ShapeId shape, float restitution);  ///< ShapeDef::restitution
    void setDensity(ShapeId shape, float density);  ///< recomputes the body's mass
    float rollingResistance(ShapeId shape) const;  ///< ShapeDef::rollingResistance
    float tangentSpeed(ShapeId shape) const;  ///< ShapeDef::tangentSpeed
    void setRollingResistance(ShapeId shape, float resistance);  ///< ShapeDef::rollingResistance
    void setTangentSpeed(ShapeId shape, float speed);  ///< conveyor belt surface speed, m/s
    void enablePreSolveEvents(ShapeId shape, bool enable);  ///< ShapeDef::enablePreSolveEvents

    // --- joints ---
    /// A new joint of def's type (joints.hpp) between def.bodyA and def.bodyB (a gear's: the bodies B
    /// of its two joints); throws perpdot::Error if `def` breaks the rules its struct documents.
    template <JointDef Def>
    JointId createJoint(const Def& def);
    void destroyJoint(JointId joint);  ///< Wakes its bodies.
    bool isValid(JointId joint) const;  ///< Whether `joint` names a live joint.
    std::vector<JointId> joints() const;  ///< Live joints, in creation order.
    JointType jointType(JointId joint) const;  ///< Which kind of joint.
    BodyId jointBodyA(JointId joint) const;  ///< The definition's bodyA.
    BodyId jointBodyB(JointId joint) const;  ///< The definition's bodyB.
    Vec2 jointAnchorA(JointId joint) const;  ///< world
    Vec2 jointAnchorB(JointId joint) const;  ///< world
    /// A pulley's two ground anchors, world (the points its ropes hang from); Error for other types.
    std::pair<Vec2, Vec2> pulleyGroundAnchors(JointId joint) const;
    /// The joint breaks when, at the end of a step, its reaction force exceeds `maxForce` N or its
    /// reaction torque exceeds `maxTorque` N·m (infinity: never): a JointBreakEvent is reported,
    /// and the joint is destroyed then if `destroy`. Error for a negative or NaN limit.
    void setJointBreakLimits(JointId joint, float maxForce, float maxTorque, bool destroy = true);
    JointEvents jointEvents() const;  ///< Joint break events of the last step.
    Vec2 jointReactionForce(JointId joint) const;   ///< on B, N, from the last step
    float jointReactionTorque(JointId joint) const; ///< on B, N·m, from the last step
    void setMouseTarget(JointId joint, Vec2 target);  ///< Mouse joints: the world target.
    void setMotorSpeed(JointId joint, float speed);  ///< revolute, prismatic, wheel

    // --- contacts ---
    int contactCount() const;  ///< touching contacts
    std::vector<ContactData> contacts() const;  ///< touching contacts, for drawing and inspection

    // --- events (of the last step; valid until the next step) ---
    ContactEvents contactEvents() const;  ///< Begin, end and hit events of the last step.
    SensorEvents sensorEvents() const;  ///< Sensor begin and end events of the last step.
    void setPreSolve(PreSolveFn callback);  ///< empty function: none

    // --- queries ---
    /// Closest hit of the ray origin -> origin + translation, if any.
    std::optional<RayHit> castRayClosest(Vec2 origin, Vec2 translation, const Filter& filter = {}) const;
    /// Every hit (one per shape child), ordered by fraction.
    std::vector<RayHit> castRay(Vec2 origin, Vec2 translation, const Filter& filter = {}) const;
    /// Shapes whose tight bounds overlap `box`.
    std::vector<ShapeId> overlapAABB(const AABB& box, const Filter& filter = {}) const;
    /// Solid shapes (circles, polygons) containing the point.
    std::vector<ShapeId> overlapPoint(Vec2 point, const Filter& filter = {}) const;
    /// Shapes overlapping a query shape placed at `xf`.
    std::vector<ShapeId> overlapShape(const Circle& shape, const Transform& xf, const Filter& filter = {}) const;
    /// Shapes overlapping a query polygon placed at `xf`.
    std::vector<ShapeId> overlapShape(const Polygon& shape, const Transform& xf, const Filter& filter = {}) const;
    /// Sweeps `shape`, placed at `xf`, along `translation` (no rotation) and returns the first
    /// world shape it touches, if any (b2ShapeCast, Box2D's GJK ray cast). Only shapes whose filter
    /// passes shouldCollide(filter, ·) are considered. Throws perpdot::Error for a non-finite
    /// transform or translation or an invalid shape (radius ≤ 0, degenerate segment or polygon).
    std::optional<ShapeCastHit> castShapeClosest(const CastShape& shape, const Transform& xf, Vec2 translation,
                                                 const Filter& filter = {}) const;
    /// Every shape child the swept shape touches, ordered by fraction (see castShapeClosest).
    std::vector<ShapeCastHit> castShape(const CastShape& shape, const Transform& xf, Vec2 translation,
                                        const Filter& filter = {}) const;

    /// Applies the explosion to every dynamic body shape it reaches (see ExplosionDef) and wakes
    /// them; returns how many shapes it pushed. Throws perpdot::Error for a non-finite position,
    /// a radius not > 0 or a negative or non-finite impulse.
    int explode(const ExplosionDef& def);

    // --- character movers (perpdot/mover.hpp) ---
    /// Create a mover's kinematic capsule body with its capsule centre at `position`; Error on an
    /// invalid MoverDef or position.
    MoverState createMover(const MoverDef& def, Vec2 position);
    /// Move the mover for one frame of `dt` seconds (call after step(dt)): be pushed out of what
    /// moved into it, ride the platform under it, walk/fall/jump with collide-and-slide, climb
    /// steps, snap to the ground, push dynamic bodies it walks into, and place its body there.
    void moveMover(const MoverDef& def, MoverState& state, const MoverInput& input, float dt);

    // --- snapshots (bit-exact: restore + N steps equals N steps) ---
    /// Versioned bytes of the whole state: settings, bodies, shapes, joints, and the contact cache
    /// with its warm-start impulses, and end events raised since the last step. Not saved: userData
    /// pointers, the pre-solve callback, the events of the last step.
    std::vector<uint8_t> snapshot() const;
    /// Replaces this world's state with a snapshot's (ids from the snapshotted world stay valid, the
    /// pre-solve callback stays). Corrupt or truncated bytes: Error, and the world is unchanged.
    void restore(std::span<const uint8_t> snapshot);
    // Compact snapshots for rollback (docs/reliability.md): the bytes in which this world's state
    // differs from `baseline`, any earlier snapshot() or baselineSnapshot(); unchanged bodies,
    // sleeping islands and static geometry cost nothing.
    /// snapshot() without the contact values the next step recomputes (zeros: contacts() shows them
    /// only after a step), which makes deltas against it smaller.
    std::vector<uint8_t> baselineSnapshot() const;
    /// The XOR delta of this world's state against `baseline`, unchanged runs skipped.
    std::vector<uint8_t> compactSnapshot(std::span<const uint8_t> baseline) const;
    /// Replaces this world's state with `baseline` patched by `compact`, continuing bit for bit
    /// like restore(snapshot()); a compact snapshot of another baseline: Error.
    void restoreCompact(std::span<const uint8_t> baseline, std::span<const uint8_t> compact);

    WorldStats stats() const;  ///< Pool sizes and health counters.

    // --- settings ---
    const WorldDef& settings() const;  ///< The current settings.
    void setGravity(Vec2 gravity);  ///< WorldDef::gravity
    void setSubsteps(int substeps);  ///< WorldDef::substeps (Error outside 1..64)

    struct Impl;  ///< internal; src/core and src/collide see it

private:
    std::unique_ptr<Impl> impl_;
};

}  // namespace perpdot
