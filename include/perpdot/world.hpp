/// @file
/// The World owns bodies, shapes, joints and contacts and advances them with step().
#pragma once

#include <cstdint>
#include <functional>
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
    Vec2 point{};             ///< world, midway between the surfaces
    float separation = 0.0f;  ///< negative when overlapping
    float normalImpulse = 0.0f;  ///< N·s along the normal, accumulated over the last step
    float tangentImpulse = 0.0f;  ///< N·s of friction along perp(normal)
    uint32_t id = 0;          ///< feature id that carries warm starting between steps
};

/// A touching contact between two shapes: its manifold and impulses.
struct ContactData {
    ShapeId shapeA{};  ///< one shape
    ShapeId shapeB{};  ///< the other; the normal points from A to B
    Vec2 normal{};  ///< from A to B
    int pointCount = 0;  ///< points used, 0..2
    ContactPoint points[2]{};  ///< the first pointCount are valid
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

/// A game's own collision rule (Box2D 2.4's b2ContactFilter::ShouldCollide): asked, once the
/// shapes' Filters pass, when the broadphase finds a new pair of overlapping shapes; return false
/// and the pair gets no contact (it is asked again when their boxes part and overlap anew). Called
/// during step() on the caller's thread, pairs in a fixed order; the world is locked.
using ShouldCollideFn = std::function<bool(ShapeId shapeA, ShapeId shapeB)>;

/// The simulation: bodies, shapes, joints and contacts, advanced by step(). Every call that takes an
/// id throws perpdot::Error naming the call when the id is null, stale (its object was destroyed)
/// or from another World ("World::setTransform: stale BodyId {index 3, generation 2}"; ids.hpp).
class World {
public:
    explicit World(const WorldDef& def = {});  ///< An empty world with settings `def`.
    ~World();  ///< Destroys everything in the world.
    /// Takes over another world; the moved-from world may only be destroyed or assigned.
    World(World&&) noexcept;
    World& operator=(World&&) noexcept;  ///< Takes over another world.
    World(const World&) = delete;  ///< Not copyable: use snapshot() and restore().
    World& operator=(const World&) = delete;  ///< Not copyable.

    /// Advance by `timeStep` seconds; allocates nothing once contacts are cached. The events of
    /// the previous step are cleared as it starts (end events raised since, by destroyShape or
    /// destroyBody, are kept for it), so a paused game that calls step(0) counts no event twice.
    /// step(0) does what Box2D 2.4's Step(0) does: it finds new pairs and runs the narrowphase,
    /// raising begin and end events and calling the pre-solve callback, and moves nothing.
    /// Throws perpdot::Error (the world unchanged) for a negative, NaN or infinite time step, and
    /// when called from inside step() (a pre-solve callback, a task of the job system).
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

    // --- bodies at run time (Box2D's b2Body setters) ---
    /// Makes the body static, kinematic or dynamic (b2Body::SetType): its contacts end (end events)
    /// and are found again from the next step, its mass is recomputed from its shapes (a mass
    /// override is dropped), and it wakes; made static it also stops (v = 0, ω = 0).
    void setType(BodyId body, BodyType type);
    /// Infinite rotational inertia (true): the body stops turning and never turns; its mass is
    /// recomputed from its shapes, as setType does.
    void setFixedRotation(BodyId body, bool fixedRotation);
    bool isFixedRotation(BodyId body) const;  ///< BodyDef::fixedRotation, or the last setFixedRotation
    void setBullet(BodyId body, bool bullet);  ///< BodyDef::bullet: continuous collision against dynamic bodies too
    bool isBullet(BodyId body) const;  ///< BodyDef::bullet, or the last setBullet
    /// BodyDef::allowSleep; false also wakes the body.
    void setAllowSleep(BodyId body, bool allowSleep);
    bool allowsSleep(BodyId body) const;  ///< BodyDef::allowSleep, or the last setAllowSleep
    /// The body's mass m, centre of mass (body frame) and rotational inertia about it.
    MassData massData(BodyId body) const;
    /// Overrides a dynamic body's mass properties (b2Body::SetMassData; ignored for static and
    /// kinematic bodies): m ≤ 0 becomes 1 kg, as in Box2D; I ≤ 0 or fixed rotation, no turning. The
    /// material points keep their velocity. Kept until resetMassData(), setType(),
    /// setFixedRotation() or a shape of the body is created, destroyed or changes density.
    /// Error for a non-finite or negative value.
    void setMassData(BodyId body, const MassData& massData);
    /// The mass properties from the shapes again (b2Body::ResetMassData).
    void resetMassData(BodyId body);
    /// The touching contacts of the body's shapes (b2Body::GetContactList).
    std::vector<ContactData> bodyContacts(BodyId body) const;
    /// The joints attached to the body (b2Body::GetJointList), in the order they were attached.
    std::vector<JointId> bodyJoints(BodyId body) const;
    /// Box2D v3's b2Body_SetTargetTransform: sets the velocity with which a kinematic (or dynamic)
    /// body reaches the pose (position, angle) at the end of a step of `timeStep` seconds, and wakes
    /// it: v = (c_target − c)/h, ω = (angle − θ)/h (angles are not wrapped). What the body carries
    /// rides with it. Error for a non-finite pose or a time step not > 0; ignored for static bodies.
    void setTargetTransform(BodyId body, Vec2 position, float angle, float timeStep);
    void setUserData(BodyId body, void* userData);  ///< BodyDef::userData
    /// Takes the body out of the simulation without destroying it (b2Body::SetEnabled(false)): its
    /// contacts end (end events), its shapes leave the broadphase (no query, contact or sensor sees
    /// them), it is not moved, and its joints are not solved; true puts it back where it was, with
    /// the velocity it had, and wakes it. A disabled body keeps its mass, joints and shapes.
    void setEnabled(BodyId body, bool enabled);
    bool isEnabled(BodyId body) const;  ///< false while disabled by setEnabled
    /// Moves the world's origin to `newOrigin` (b2World::ShiftOrigin), for large worlds: every
    /// position, anchor, fat box and contact point is moved by −newOrigin, so the simulation goes
    /// on as before, translated (up to float rounding of the new coordinates). A game's own world
    /// positions (MoverState, targets) are its to shift. Error for a non-finite origin.
    void shiftOrigin(Vec2 newOrigin);

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
    /// A new chain on `body`: one-sided, solid on the side Chain::solid names (default: the right,
    /// so ground given left to right is solid below); Error if the chain is invalid.
    ShapeId createShape(BodyId body, const ShapeDef& def, const Chain& chain);
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
    // Shapes at run time (Box2D's b2Fixture setters):
    /// A new filter (b2Fixture::SetFilterData): contacts it no longer allows end at once (end
    /// events before the next step's), pairs it now allows are found in the next step.
    void setFilter(ShapeId shape, const Filter& filter);
    /// Makes the shape a sensor (true) or solid: its contacts end at once (end events), and the
    /// next step finds them again as sensor overlaps or as contacts.
    void setSensor(ShapeId shape, bool sensor);
    /// Takes the shape out of the broadphase (false: its contacts end, no query sees it; its body
    /// keeps the shape's mass) or puts it back (true); the shape of a disabled body stays out.
    void setEnabled(ShapeId shape, bool enabled);
    bool isEnabled(ShapeId shape) const;  ///< false while disabled by setEnabled(ShapeId, false)
    void* userData(ShapeId shape) const;  ///< ShapeDef::userData, or the last setUserData
    void setUserData(ShapeId shape, void* userData);  ///< ShapeDef::userData

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
    /// The joint breaks when its reaction force averaged over a step exceeds `maxForce` N or its
    /// reaction torque exceeds `maxTorque` N·m (infinity: never): a JointBreakEvent is reported at
    /// the end of the step, and the joint is destroyed then if `destroy`. The average is the
    /// joint's impulse summed over all the step's substeps divided by the step, so a sudden blow
    /// (an explosion) counts in full. Error for a negative or NaN limit.
    void setJointBreakLimits(JointId joint, float maxForce, float maxTorque, bool destroy = true);
    JointEvents jointEvents() const;  ///< Joint break events of the last step.
    Vec2 jointReactionForce(JointId joint) const;   ///< on B, N, from the last step
    float jointReactionTorque(JointId joint) const; ///< on B, N·m, from the last step
    void setMouseTarget(JointId joint, Vec2 target);  ///< Mouse joints: the world target.
    void setMotorSpeed(JointId joint, float speed);  ///< revolute, prismatic, wheel

    // --- joints at run time (joint_settings.cpp): each call names the joint types it serves and
    // throws perpdot::Error for another type, a stale id or a value its definition would refuse.
    // A setter wakes the joint's bodies; the settings are part of snapshots. ---
    /// Revolute, prismatic: turn the limit rows on or off (off forgets their impulses).
    void enableLimit(JointId joint, bool enable);
    bool isLimitEnabled(JointId joint) const;  ///< Revolute, prismatic: whether the limit is on.
    /// Revolute (rad, of jointAngle) and prismatic (m, of jointTranslation): the limits, lower <= upper.
    void setLimits(JointId joint, float lower, float upper);
    float lowerLimit(JointId joint) const;  ///< Revolute, prismatic: the lower limit.
    float upperLimit(JointId joint) const;  ///< Revolute, prismatic: the upper limit.
    /// Revolute, prismatic, wheel: turn the motor row on or off (a change forgets its impulse).
    void enableMotor(JointId joint, bool enable);
    bool isMotorEnabled(JointId joint) const;  ///< Revolute, prismatic, wheel: whether the motor is on.
    float motorSpeed(JointId joint) const;  ///< Revolute, wheel (rad/s), prismatic (m/s).
    /// Revolute, wheel: the motor's torque bound, N·m (>= 0).
    void setMaxMotorTorque(JointId joint, float torque);
    float maxMotorTorque(JointId joint) const;  ///< Revolute, wheel: the motor's torque bound.
    void setMaxMotorForce(JointId joint, float force);  ///< Prismatic: the motor's force bound, N (>= 0).
    float maxMotorForce(JointId joint) const;  ///< Prismatic: the motor's force bound.
    /// Revolute, wheel: the torque the motor applied over the last step's last substep, N·m.
    float motorTorque(JointId joint) const;
    /// Prismatic: the force the motor applied over the last step's last substep, N.
    float motorForce(JointId joint) const;
    /// Wheel, distance, weld, mouse: the spring's frequency (0: rigid, Box2D's EnableSpring(false)).
    void setSpringHertz(JointId joint, float hertz);
    /// Wheel, distance, weld, mouse: the spring's damping ratio ζ (>= 0).
    void setSpringDampingRatio(JointId joint, float dampingRatio);
    float springHertz(JointId joint) const;  ///< Wheel, distance, weld, mouse: the spring's frequency.
    float springDampingRatio(JointId joint) const;  ///< Wheel, distance, weld, mouse: ζ.
    void setLength(JointId joint, float length);  ///< Distance: the rest length, m (> 0).
    /// Distance: the anchors' distance stays within [minLength, maxLength] (0 <= min <= max;
    /// Box2D 2.4's rope joint is maxLength alone).
    void setLengthRange(JointId joint, float minLength, float maxLength);
    float restLength(JointId joint) const;  ///< Distance: the rest length (Box2D: GetLength).
    float minLength(JointId joint) const;  ///< Distance: the shortest the anchors may come.
    float maxLength(JointId joint) const;  ///< Distance: the furthest the anchors may part.
    float currentLength(JointId joint) const;  ///< Distance: the anchors' distance now, m.
    /// Motor, friction (maxForce), mouse (maxForce): the force bound, N (>= 0).
    void setMaxForce(JointId joint, float force);
    void setMaxTorque(JointId joint, float torque);  ///< Motor, friction: the torque bound, N·m (>= 0).
    float maxForce(JointId joint) const;  ///< Motor, friction, mouse: the force bound.
    float maxTorque(JointId joint) const;  ///< Motor, friction: the torque bound.
    void setLinearOffset(JointId joint, Vec2 offset);  ///< Motor: B's origin target, A's frame.
    void setAngularOffset(JointId joint, float offset);  ///< Motor: the target θB − θA, rad.
    /// Revolute, weld, prismatic: θB − θA − referenceAngle, rad (accumulated, not wrapped).
    float jointAngle(JointId joint) const;
    /// Revolute, weld, prismatic, wheel: ωB − ωA, rad/s.
    float jointAngularSpeed(JointId joint) const;
    /// Prismatic, wheel: (pB − pA)·axis, the anchors' separation along the world axis, m.
    float jointTranslation(JointId joint) const;
    /// Prismatic, wheel: d/dt of jointTranslation, m/s (the axis turns with body A).
    float jointLinearSpeed(JointId joint) const;
    void* userData(JointId joint) const;  ///< The definition's userData, or the last setUserData's.
    void setUserData(JointId joint, void* userData);  ///< Any type: the application's pointer.
    /// Called by destroyBody, after the body is gone, once for each joint it destroyed with it
    /// (Box2D 2.4's b2DestructionListener::SayGoodbye): the joint's id, stale by then, and its
    /// userData; the callback may change the world. Not called by destroyJoint, nor for joints a
    /// break destroys (JointBreakEvent reports those). An empty function: none.
    void setJointDestroyedCallback(JointDestroyedFn callback);
    // --- end of joints at run time ---

    // --- contacts ---
    int contactCount() const;  ///< touching contacts
    std::vector<ContactData> contacts() const;  ///< touching contacts, for drawing and inspection

    // --- events (of the last step; valid until the next step) ---
    ContactEvents contactEvents() const;  ///< Begin, end and hit events of the last step.
    SensorEvents sensorEvents() const;  ///< Sensor begin and end events of the last step.
    void setPreSolve(PreSolveFn callback);  ///< empty function: none
    /// The game's collision rule (ShouldCollideFn); empty function: none. Pairs that already have
    /// a contact keep it. Not saved in snapshots (restore keeps this World's).
    void setShouldCollide(ShouldCollideFn callback);

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
    /// with its warm-start impulses, end events raised since the last step, and this World's
    /// identity (ids.hpp). Not saved: userData pointers, the pre-solve and should-collide
    /// callbacks, the events of the last step.
    std::vector<uint8_t> snapshot() const;
    /// Replaces this world's state with a snapshot's (ids from the snapshotted world are valid, and
    /// so are this World's own; the callbacks stay). Corrupt or truncated bytes: Error, and the
    /// world is unchanged.
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
    /// Inside step(), that is from one of its callbacks (b2World::IsLocked): the calls that
    /// change the world throw Error until step() returns.
    bool isLocked() const;

    // --- settings ---
    const WorldDef& settings() const;  ///< The current settings.
    void setGravity(Vec2 gravity);  ///< WorldDef::gravity
    void setSubsteps(int substeps);  ///< WorldDef::substeps (Error outside 1..64)

    struct Impl;  ///< internal; src/core and src/collide see it

private:
    std::unique_ptr<Impl> impl_;
};

}  // namespace perpdot
