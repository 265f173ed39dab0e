// The engine-neutral scene of ../shared/scene-format.md (`perpdot-scene/1`): what the JSON says,
// nothing more. Both perpdot's World and Box2D's b2World are built from it.
// Every member has an initializer so that designated initializers may skip any of them.
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

struct SceneShape {
    enum class Kind { Circle, Box, Polygon, Segment, Chain, Capsule };
    Kind kind = Kind::Circle;
    // geometry; which fields matter depends on kind
    float radius = 0.5f;           // circle and capsule radius; polygon rounding (default 0 for polygons)
    Vec2 center{};                 // circle, box
    Vec2 halfExtents{0.5f, 0.5f};  // box
    float angle = 0.0f;            // box
    std::vector<Vec2> vertices{};  // polygon, chain
    Vec2 v1{}, v2{};               // segment; capsule centres (JSON "center1", "center2")
    bool loop = false;             // chain
    // material
    float density = 1.0f;
    float friction = 0.6f;
    float restitution = 0.0f;
    bool sensor = false;
    Filter filter{};
    friend bool operator==(const SceneShape&, const SceneShape&) = default;
};

struct SceneBody {
    std::string name{};
    BodyType type = BodyType::Dynamic;
    Vec2 position{};
    float angle = 0.0f;
    Vec2 linearVelocity{};
    float angularVelocity = 0.0f;
    float linearDamping = 0.0f;
    float angularDamping = 0.0f;
    float gravityScale = 1.0f;
    bool fixedRotation = false;
    bool bullet = false;
    bool allowSleep = true;
    std::vector<SceneShape> shapes{};
    friend bool operator==(const SceneBody&, const SceneBody&) = default;
};

struct SceneJoint {
    JointType type = JointType::Revolute;
    std::string bodyA{}, bodyB{};
    std::optional<Vec2> anchor{};        // world anchor (A's, and B's unless anchorB is given)
    std::optional<Vec2> anchorB{};       // distance joint: B's world anchor
    std::optional<Vec2> localAnchorA{};  // alternative to `anchor`
    std::optional<Vec2> localAnchorB{};
    bool collideConnected = false;
    bool enableLimit = false;
    float lowerAngle = 0.0f, upperAngle = 0.0f;  // revolute
    float lower = 0.0f, upper = 0.0f;            // prismatic
    bool enableMotor = false;
    float motorSpeed = 0.0f;
    float maxMotorTorque = 0.0f;
    float maxMotorForce = 0.0f;
    std::optional<float> length{};                 // distance; default: current distance
    float minLength = 0.0f;
    float maxLength = 1.0e30f;
    float hertz = 0.0f;
    float dampingRatio = 0.0f;
    Vec2 axis{1.0f, 0.0f};                       // prismatic, wheel (world)
    Vec2 linearOffset{};                         // motor
    float angularOffset = 0.0f;
    float maxForce = 1.0f;
    float maxTorque = 1.0f;
    friend bool operator==(const SceneJoint&, const SceneJoint&) = default;
};

struct SceneAction {
    enum class Kind { Force, Impulse, Torque, AngularImpulse };
    Kind kind = Kind::Force;
    std::string body{};
    Vec2 value{};               // force / impulse
    float scalar = 0.0f;        // torque / angular impulse
    std::optional<Vec2> point{};  // world; default: centre of mass
    int firstStep = 0;
    int lastStep = 0;
    friend bool operator==(const SceneAction&, const SceneAction&) = default;
};

struct SceneSolver {
    std::optional<int> substeps{};  // perpdot; default WorldDef::substeps
    int velocityIterations = 8;   // Box2D, in cross-checks and benchmarks
    int positionIterations = 3;
    friend bool operator==(const SceneSolver&, const SceneSolver&) = default;
};

struct Scene {
    std::string name{};
    std::string description{};
    Vec2 gravity{0.0f, -10.0f};
    float timestep = 1.0f / 60.0f;
    int steps = 600;
    SceneSolver solver{};
    bool enableSleep = true;  // not in the file format; benchmarks turn it off
    std::vector<SceneBody> bodies{};
    std::vector<SceneJoint> joints{};
    std::vector<SceneAction> actions{};
    friend bool operator==(const Scene&, const Scene&) = default;
};

// JSON. Errors are perpdot::Error whose message starts with the JSON path, e.g.
// "bodies[3].shapes[0].vertices: polygon is not convex".
Scene parseScene(std::string_view json);
Scene loadScene(const std::string& path);
std::string toJson(const Scene& scene);
void saveScene(const Scene& scene, const std::string& path);

// Built-in scenes, by name.
struct BuiltinScene {
    std::string name;
    std::string description;
    std::function<Scene()> make;
};
const std::vector<BuiltinScene>& builtinScenes();
// A built-in scene's name, or a path to a .json file. Error if neither.
Scene findScene(const std::string& nameOrPath);

// A scene built into a World; bodies[i] and joints[i] follow the scene's order.
struct SceneWorld {
    World world{};
    std::vector<BodyId> bodies{};
    std::vector<JointId> joints{};
    Scene scene{};

    // Apply the scene's actions whose range contains `step` (before stepping it).
    void applyActions(int step);
    // applyActions(stepIndex) then world.step(scene.timestep); counts steps itself.
    void step();
    int stepIndex = 0;
};
SceneWorld buildWorld(const Scene& scene);

}  // namespace perpdot
