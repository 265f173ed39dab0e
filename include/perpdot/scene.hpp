/// @file
/// The engine-neutral scene of docs/scene-format.md (`perpdot-scene/1`): what the JSON says,
/// nothing more. Both perpdot's World and Box2D's b2World are built from it.
/// Every member has an initializer so that designated initializers may skip any of them.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "perpdot/body.hpp"
#include "perpdot/math.hpp"
#include "perpdot/shapes.hpp"
#include "perpdot/world.hpp"

namespace perpdot {

/// A shape of a scene body, in the body frame.
struct SceneShape {
    /// The geometry.
    enum class Kind { Circle, Box, Polygon, Segment, Chain, Capsule };
    Kind kind = Kind::Circle;  ///< which geometry
    // geometry; which fields matter depends on kind
    float radius = 0.5f;           ///< circle and capsule radius; polygon rounding (default 0 for polygons)
    Vec2 center{};                 ///< circle, box
    Vec2 halfExtents{0.5f, 0.5f};  ///< box
    float angle = 0.0f;            ///< box
    std::vector<Vec2> vertices{};  ///< polygon, chain
    Vec2 v1{};                     ///< segment start; capsule center1 (JSON "center1")
    Vec2 v2{};                     ///< segment end; capsule center2 (JSON "center2")
    bool loop = false;             ///< chain
    /// chain: the solid side (JSON "solid": "left" or "right"); the scene format's default is
    /// Left, the one-sided rule of Box2D and of scene files written before the key existed
    ChainSide solid = ChainSide::Left;
    std::optional<Vec2> prevVertex{};  ///< open chain: ghost vertex before the first (JSON "prev_vertex")
    std::optional<Vec2> nextVertex{};  ///< open chain: ghost vertex after the last (JSON "next_vertex")
    // material
    float density = 1.0f;  ///< kg/m²
    float friction = 0.6f;  ///< Coulomb μ
    float restitution = 0.0f;  ///< e
    bool sensor = false;  ///< ShapeDef::sensor
    Filter filter{};  ///< collision filter
    bool enabled = true;  ///< false: created disabled (World::setEnabled(ShapeId, false))
    /// Equal in every field (a scene that round-trips through JSON compares equal).
    friend bool operator==(const SceneShape&, const SceneShape&) = default;
};

/// A body's mass properties given instead of its shapes' (World::setMassData, JSON "mass_data").
struct SceneMass {
    float mass = 1.0f;               ///< kg (0: 1 kg, as World::setMassData)
    Vec2 center{};                   ///< centre of mass, body frame
    float rotationalInertia = 0.0f;  ///< about the centre of mass, kg·m² (0: the body does not turn)
    /// Equal in every field.
    friend bool operator==(const SceneMass&, const SceneMass&) = default;
};

/// A named body of a scene; the fields are BodyDef's.
struct SceneBody {
    std::string name{};  ///< unique in the scene; joints and actions refer to it
    BodyType type = BodyType::Dynamic;  ///< BodyDef::type
    Vec2 position{};  ///< body origin, world
    float angle = 0.0f;  ///< rad
    Vec2 linearVelocity{};  ///< m/s
    float angularVelocity = 0.0f;  ///< rad/s
    float linearDamping = 0.0f;  ///< BodyDef::linearDamping
    float angularDamping = 0.0f;  ///< BodyDef::angularDamping
    float gravityScale = 1.0f;  ///< BodyDef::gravityScale
    bool fixedRotation = false;  ///< BodyDef::fixedRotation
    bool bullet = false;  ///< BodyDef::bullet
    bool allowSleep = true;  ///< BodyDef::allowSleep
    bool awake = true;  ///< BodyDef::awake: false starts it asleep (where allowSleep)
    bool enabled = true;  ///< false: created disabled (World::setEnabled(BodyId, false); b2BodyDef::enabled)
    std::vector<SceneShape> shapes{};  ///< its shapes
    std::optional<SceneMass> massData{};  ///< overrides the shapes' mass (dynamic bodies; none: from the shapes)
    /// Equal in every field (a scene that round-trips through JSON compares equal).
    friend bool operator==(const SceneBody&, const SceneBody&) = default;
};

/// A joint of a scene: one struct for every JointType, each using the fields of its *JointDef.
struct SceneJoint {
    JointType type = JointType::Revolute;  ///< which joint
    std::string bodyA{};  ///< name of the first body
    std::string bodyB{};  ///< name of the second body
    std::optional<Vec2> anchor{};        ///< world anchor (A's, and B's unless anchorB is given)
    std::optional<Vec2> anchorB{};       ///< distance joint: B's world anchor
    std::optional<Vec2> localAnchorA{};  ///< alternative to `anchor`
    std::optional<Vec2> localAnchorB{};  ///< alternative to `anchor` / `anchorB`
    bool collideConnected = false;  ///< the two bodies still collide
    bool enableLimit = false;  ///< revolute, prismatic
    float lowerAngle = 0.0f;  ///< revolute limit, rad
    float upperAngle = 0.0f;  ///< revolute limit, rad
    float lower = 0.0f;       ///< prismatic limit, m
    float upper = 0.0f;       ///< prismatic limit, m
    bool enableMotor = false;  ///< revolute, prismatic, wheel
    float motorSpeed = 0.0f;  ///< rad/s (revolute, wheel), m/s (prismatic)
    float maxMotorTorque = 0.0f;  ///< N·m, revolute and wheel
    float maxMotorForce = 0.0f;  ///< N, prismatic
    std::optional<float> length{};                 ///< distance; default: current distance
    float minLength = 0.0f;  ///< distance
    float maxLength = 1.0e30f;  ///< distance
    float hertz = 0.0f;  ///< spring frequency (distance, weld, wheel, mouse); 0: rigid
    float dampingRatio = 0.0f;  ///< spring damping ratio ζ
    Vec2 axis{1.0f, 0.0f};                       ///< prismatic, wheel (world)
    Vec2 linearOffset{};                         ///< motor
    float angularOffset = 0.0f;  ///< motor, rad
    float maxForce = 1.0f;  ///< motor (friction: the file's default is 0), N
    float maxTorque = 1.0f;  ///< motor (friction: the file's default is 0), N·m
    /// Equal in every field (a scene that round-trips through JSON compares equal).
    int jointA = -1;  ///< gear: index of an earlier revolute or prismatic joint
    int jointB = -1;  ///< gear: index of an earlier revolute or prismatic joint
    float ratio = 1.0f;  ///< gear, pulley
    Vec2 groundAnchorA{};  ///< pulley: world point the rope to A hangs from
    Vec2 groundAnchorB{};  ///< pulley: world point the rope to B hangs from
    std::optional<float> lengthA{};  ///< pulley; default: current rope length on A's side
    std::optional<float> lengthB{};  ///< pulley; default: current rope length on B's side
    std::optional<float> breakForce{};   ///< N; World::setJointBreakLimits (none: never breaks on force)
    std::optional<float> breakTorque{};  ///< N·m; none: never breaks on torque
    bool destroyOnBreak = true;          ///< the joint goes when it breaks
    /// Equal in every field (a scene that round-trips through JSON compares equal).
    friend bool operator==(const SceneJoint&, const SceneJoint&) = default;
};

/// A force, impulse or torque the scene applies to a body over a range of steps.
struct SceneAction {
    /// What is applied.
    enum class Kind { Force, Impulse, Torque, AngularImpulse, Explosion };
    Kind kind = Kind::Force;  ///< what is applied
    std::string body{};  ///< name of the body (empty for an explosion, which acts on every shape in reach)
    Vec2 value{};               ///< force / impulse
    float scalar = 0.0f;        ///< torque / angular impulse / an explosion's impulse at its centre (N·s)
    std::optional<Vec2> point{};  ///< world; default: centre of mass; an explosion's centre (required)
    float radius = 0.0f;          ///< explosion: reach, m (World::explode)
    bool blockedByStatic = false;  ///< explosion: ExplosionDef::blockedByStatic
    int firstStep = 0;  ///< first step index it applies to
    int lastStep = 0;  ///< last step index it applies to (inclusive)
    /// Equal in every field (a scene that round-trips through JSON compares equal).
    friend bool operator==(const SceneAction&, const SceneAction&) = default;
};

/// Solver settings of a scene, for each engine.
struct SceneSolver {
    std::optional<int> substeps{};  ///< perpdot; default WorldDef::substeps
    int velocityIterations = 8;   ///< Box2D, in cross-checks and benchmarks
    int positionIterations = 3;  ///< Box2D
    bool box2dSkin = false;  ///< perpdot rests on Box2D 2.4's polygon skin (WorldDef::box2dSkin)
    /// Equal in every field (a scene that round-trips through JSON compares equal).
    friend bool operator==(const SceneSolver&, const SceneSolver&) = default;
};

/// A whole scene: world settings, bodies, joints and scripted actions.
struct Scene {
    std::string name{};  ///< the scene's name
    std::string description{};  ///< one line on what it shows
    Vec2 gravity{0.0f, -10.0f};  ///< m/s²
    float timestep = 1.0f / 60.0f;  ///< s per step
    int steps = 600;  ///< how many steps a run takes
    SceneSolver solver{};  ///< solver settings
    bool enableSleep = true;  ///< not in the file format; benchmarks turn it off
    std::vector<SceneBody> bodies{};  ///< in creation order
    std::vector<SceneJoint> joints{};  ///< in creation order
    std::vector<SceneAction> actions{};  ///< scripted forces and impulses
    /// Equal in every field (a scene that round-trips through JSON compares equal).
    friend bool operator==(const Scene&, const Scene&) = default;
};

/// A scene from `perpdot-scene/1` JSON text. Errors are perpdot::Error whose message starts with
/// the JSON path, e.g. "bodies[3].shapes[0].vertices: polygon is not convex".
Scene parseScene(std::string_view json);
Scene loadScene(const std::string& path);  ///< parseScene() of a file's contents; Error names the file
std::string toJson(const Scene& scene);  ///< The scene as `perpdot-scene/1` JSON; parseScene(toJson(s)) == s.
/// Write toJson(scene) to `path`; Error if it cannot be written.
void saveScene(const Scene& scene, const std::string& path);

/// A built-in scene: its name, what it shows, and how to make it.
struct BuiltinScene {
    std::string name{};  ///< the name for findScene() and `perpdot run`
    std::string description{};  ///< one line on what it shows
    std::function<Scene()> make;  ///< builds the scene
};
const std::vector<BuiltinScene>& builtinScenes();  ///< Every built-in scene, in `perpdot list` order.
/// A built-in scene's name, or a path to a .json file. Error if neither.
Scene findScene(const std::string& nameOrPath);

/// A scene built into a World; bodies[i] and joints[i] follow the scene's order.
struct SceneWorld {
    World world{};  ///< the world built from `scene`
    std::vector<BodyId> bodies{};  ///< bodies[i] is scene.bodies[i]
    std::vector<JointId> joints{};  ///< joints[i] is scene.joints[i]
    Scene scene{};  ///< the scene it was built from

    /// Apply the scene's actions whose range contains `step` (before stepping it).
    void applyActions(int step);
    /// beforeStep(), applyActions(stepIndex), then world.step(scene.timestep); counts steps itself.
    void step();
    int stepIndex = 0;  ///< steps taken by step()
    /// What a built-in scene does before each step (perpdot/feature_scenes.hpp); may be empty.
    std::function<void(SceneWorld&)> beforeStep{};
};
/// A World with the scene's settings, bodies, shapes and joints (Error if a definition is invalid),
/// stepped by `workerCount` threads (WorldDef::workerCount; not part of the scene: the results
/// are the same for any count).
SceneWorld buildWorld(const Scene& scene, int workerCount = 1);

}  // namespace perpdot
