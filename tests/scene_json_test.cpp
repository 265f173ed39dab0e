// perpdot-scene/1: defaults, round trips of every built-in scene, and refusals that name the JSON path.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "perpdot/error.hpp"
#include "perpdot/scene.hpp"

namespace perpdot {
namespace {

std::string tempPath(const std::string& name) {
    return (std::filesystem::temp_directory_path() / ("perpdot_scene_json_" + name)).string();
}

std::string errorOf(const std::string& json) {
    try {
        parseScene(json);
    } catch (const Error& e) {
        return e.what();
    }
    return "(accepted)";
}

TEST(SceneJson, EveryBuiltinSceneRoundTrips) {
    ASSERT_FALSE(builtinScenes().empty());
    for (const BuiltinScene& entry : builtinScenes()) {
        SCOPED_TRACE(entry.name);
        const Scene scene = entry.make();
        EXPECT_EQ(scene.name, entry.name);
        EXPECT_FALSE(entry.description.empty());
        EXPECT_FALSE(scene.bodies.empty());
        const Scene loaded = parseScene(toJson(scene));
        EXPECT_TRUE(loaded == scene);
        EXPECT_EQ(toJson(loaded), toJson(scene));
    }
}

TEST(SceneJson, ExportThenLoadIsEqual) {
    const Scene scene = findScene("bouncing_balls");
    const std::string path = tempPath("bouncing_balls.json");
    saveScene(scene, path);
    EXPECT_TRUE(loadScene(path) == scene);
    std::filesystem::remove(path);
}

TEST(SceneJson, BuiltinNamesAreUniqueAndFindable) {
    for (const BuiltinScene& entry : builtinScenes()) {
        int count = 0;
        for (const BuiltinScene& other : builtinScenes()) count += other.name == entry.name;
        EXPECT_EQ(count, 1) << entry.name;
        EXPECT_EQ(findScene(entry.name).name, entry.name);
    }
    EXPECT_THROW(findScene("no_such_scene"), Error);
}

TEST(SceneJson, FindSceneLoadsFilesAndNamesThemAfterTheFile) {
    const Scene s = findScene(std::string(PERPDOT_TEST_DATA) + "/unnamed_scene.json");
    EXPECT_EQ(s.name, "unnamed_scene");
    EXPECT_EQ(s.steps, 30);
    ASSERT_EQ(s.bodies.size(), 3u);
    EXPECT_EQ(s.bodies[2].name, "body2");
    EXPECT_EQ(s.actions[0].body, "body1");
}

TEST(SceneJson, DefaultsAreApplied) {
    const Scene s = parseScene(R"({"format": "perpdot-scene/1",
        "bodies": [{"shapes": [{"type": "circle", "radius": 0.25}]}, {"name": "b", "shapes": [{"type": "polygon",
        "vertices": [[0, 0], [0, 1], [1, 0]]}]}],
        "actions": [{"type": "force", "body": "b", "value": [1, 2], "first_step": 3}]})");
    const Scene defaults;
    EXPECT_EQ(s.gravity, (Vec2{0.0f, -10.0f}));
    EXPECT_EQ(s.timestep, 1.0f / 60.0f);
    EXPECT_EQ(s.steps, 600);
    EXPECT_FALSE(s.solver.substeps.has_value());
    EXPECT_EQ(s.solver.velocityIterations, 8);
    EXPECT_EQ(s.solver.positionIterations, 3);
    EXPECT_TRUE(s.name.empty());
    ASSERT_EQ(s.bodies.size(), 2u);
    const SceneBody& b0 = s.bodies[0];
    EXPECT_EQ(b0.name, "body0");
    EXPECT_EQ(b0.type, BodyType::Dynamic);
    EXPECT_EQ(b0.position, (Vec2{}));
    EXPECT_EQ(b0.gravityScale, 1.0f);
    EXPECT_TRUE(b0.allowSleep);
    EXPECT_FALSE(b0.bullet);
    ASSERT_EQ(b0.shapes.size(), 1u);
    const SceneShape& circle = b0.shapes[0];
    EXPECT_EQ(circle.kind, SceneShape::Kind::Circle);
    EXPECT_EQ(circle.radius, 0.25f);
    EXPECT_EQ(circle.density, 1.0f);
    EXPECT_EQ(circle.friction, 0.6f);
    EXPECT_EQ(circle.restitution, 0.0f);
    EXPECT_EQ(circle.filter, Filter{});
    EXPECT_EQ(s.bodies[1].shapes[0].radius, 0.0f);  // polygons are sharp unless rounded
    ASSERT_EQ(s.actions.size(), 1u);
    EXPECT_EQ(s.actions[0].firstStep, 3);
    EXPECT_EQ(s.actions[0].lastStep, 3);  // defaults to first_step
    EXPECT_FALSE(s.actions[0].point.has_value());
    EXPECT_EQ(defaults.enableSleep, s.enableSleep);
}

// Every feature of the format, written and read back.
TEST(SceneJson, EveryFieldRoundTrips) {
    const Scene s = parseScene(R"({"format": "perpdot-scene/1", "name": "all", "description": "every key",
        "gravity": [0.5, -9.81], "timestep": 0.01, "steps": 12, "solver": {"substeps": 6, "velocity_iterations": 10,
        "position_iterations": 4},
        "bodies": [
          {"name": "ground", "type": "static", "shapes": [{"type": "chain", "vertices": [[-5, 0], [0, -1], [5, 0]], "loop": true},
                                                          {"type": "segment", "v1": [-5, 2], "v2": [5, 2.5], "friction": 0.2}]},
          {"name": "a", "type": "kinematic", "position": [1, 2], "angle": 0.3, "linear_velocity": [1, 0], "angular_velocity": -1,
           "awake": false},
          {"name": "b", "position": [3, 2], "linear_damping": 0.1, "angular_damping": 0.2, "gravity_scale": 0.5,
           "fixed_rotation": true, "bullet": true, "allow_sleep": false, "enabled": false,
           "shapes": [{"type": "box", "half_extents": [1, 0.25], "center": [0.1, 0.2], "angle": 0.5, "density": 2,
                       "restitution": 0.5, "sensor": true, "filter": {"category": 2, "mask": 5, "group": -3}},
                      {"type": "polygon", "vertices": [[0, 0], [1, 1], [1, 0]], "radius": 0.05},
                      {"type": "circle", "radius": 0.3, "center": [0, 1], "enabled": false}]}],
        "joints": [
          {"type": "revolute", "body_a": "a", "body_b": "b", "anchor": [2, 2], "enable_limit": true, "lower_angle": -1,
           "upper_angle": 1, "enable_motor": true, "motor_speed": 2, "max_motor_torque": 10, "collide_connected": true},
          {"type": "distance", "body_a": "a", "body_b": "b", "anchor": [1, 2], "anchor_b": [3, 2], "length": 2.5,
           "min_length": 1, "max_length": 3, "hertz": 4, "damping_ratio": 0.5},
          {"type": "prismatic", "body_a": "ground", "body_b": "b", "local_anchor_a": [0, 1], "local_anchor_b": [0, 0],
           "axis": [0, 1], "enable_limit": true, "lower": -1, "upper": 2, "max_motor_force": 50},
          {"type": "weld", "body_a": "a", "body_b": "b", "anchor": [2, 2], "hertz": 5, "damping_ratio": 0.7},
          {"type": "wheel", "body_a": "a", "body_b": "b", "anchor": [3, 2], "axis": [0, 1], "hertz": 3, "max_motor_torque": 4},
          {"type": "motor", "body_a": "a", "body_b": "b", "linear_offset": [1, 1], "angular_offset": 0.5, "max_force": 20,
           "max_torque": 30},
          {"type": "friction", "body_a": "ground", "body_b": "b", "anchor": [3, 2], "max_force": 3}],
        "actions": [
          {"type": "force", "body": "b", "value": [1, 2], "point": [3, 3], "first_step": 1, "last_step": 5},
          {"type": "impulse", "body": "b", "value": [0, -1]},
          {"type": "torque", "body": "b", "value": 2.5, "first_step": 2, "last_step": 4},
          {"type": "angular_impulse", "body": "b", "value": -0.5, "first_step": 7}]})");
    EXPECT_EQ(s.gravity, (Vec2{0.5f, -9.81f}));
    EXPECT_EQ(s.solver.substeps, 6);
    ASSERT_EQ(s.bodies.size(), 3u);
    EXPECT_EQ(s.bodies[1].type, BodyType::Kinematic);
    EXPECT_FALSE(s.bodies[1].awake);
    EXPECT_TRUE(s.bodies[2].awake);
    EXPECT_EQ(s.bodies[2].shapes[0].filter, (Filter{2, 5, -3}));
    EXPECT_TRUE(s.bodies[0].shapes[0].loop);
    EXPECT_FALSE(s.bodies[2].enabled);
    EXPECT_TRUE(s.bodies[1].enabled);
    EXPECT_FALSE(s.bodies[2].shapes[2].enabled);
    EXPECT_TRUE(s.bodies[2].shapes[1].enabled);
    ASSERT_EQ(s.joints.size(), 7u);
    EXPECT_EQ(s.joints[6].type, JointType::Friction);
    EXPECT_EQ(s.joints[6].maxForce, 3.0f);
    EXPECT_EQ(s.joints[6].maxTorque, 0.0f);
    EXPECT_EQ(s.joints[1].length, 2.5f);
    EXPECT_EQ(s.joints[1].anchorB, (Vec2{3.0f, 2.0f}));
    EXPECT_EQ(s.joints[2].localAnchorA, (Vec2{0.0f, 1.0f}));
    EXPECT_EQ(s.joints[5].type, JointType::Motor);
    ASSERT_EQ(s.actions.size(), 4u);
    EXPECT_EQ(s.actions[2].scalar, 2.5f);
    EXPECT_EQ(s.actions[0].point, (Vec2{3.0f, 3.0f}));
    EXPECT_TRUE(parseScene(toJson(s)) == s);
}

TEST(SceneJson, FloatsAreWrittenShortAndExact) {
    Scene s;
    s.timestep = 1.0f / 60.0f;
    s.gravity = {0.1f, -9.8f};
    const std::string text = toJson(s);
    EXPECT_NE(text.find("0.016666668"), std::string::npos) << text;
    EXPECT_NE(text.find("[0.1,-9.8]"), std::string::npos) << text;
    EXPECT_EQ(parseScene(text).timestep, s.timestep);
}

TEST(SceneJson, LoadErrorsNameTheFileAndThePath) {
    const std::string path = std::string(PERPDOT_TEST_DATA) + "/bad_polygon.json";
    try {
        loadScene(path);
        FAIL() << "bad_polygon.json was accepted";
    } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_EQ(message.rfind(path + ": bodies[1].shapes[0].vertices: ", 0), 0u) << message;
    }
    EXPECT_THROW(loadScene(tempPath("does_not_exist.json")), Error);
}

struct InvalidScene {
    const char* what;
    std::string json;
    std::string expectedPrefix;  // the message must start with this
};

// A valid scene with `bodies` (and optional extra top-level members) spliced in.
std::string sceneWith(const std::string& bodies, const std::string& extra = "") {
    return R"({"format": "perpdot-scene/1", "bodies": [)" + bodies + "]" + extra + "}";
}
const std::string box = R"({"name": "box", "shapes": [{"type": "box", "half_extents": [0.5, 0.5]}]})";
const std::string two = box + R"(, {"name": "ball", "shapes": [{"type": "circle", "radius": 0.5}]})";
std::string withShape(const std::string& shape) { return sceneWith(R"({"shapes": [)" + shape + "]}"); }
std::string withJoint(const std::string& joint) { return sceneWith(two, R"(, "joints": [)" + joint + "]"); }
std::string withAction(const std::string& action) { return sceneWith(two, R"(, "actions": [)" + action + "]"); }

TEST(SceneJson, InvalidScenesAreRefusedWithTheirPath) {
    const InvalidScene cases[] = {
        {"unknown top-level key", sceneWith(box, R"(, "gravty": [0, -10])"), "gravty: unknown key"},
        {"unknown body key", sceneWith(R"({"positon": [0, 1]})"), "bodies[0].positon: unknown key"},
        {"unknown shape key", withShape(R"({"type": "circle", "radius": 1, "centre": [0, 0]})"),
         "bodies[0].shapes[0].centre: unknown key"},
        {"key of another shape type", withShape(R"({"type": "circle", "radius": 1, "half_extents": [1, 1]})"),
         "bodies[0].shapes[0].half_extents: unknown key"},
        {"vector given as string", sceneWith(R"({"position": "up"})"), "bodies[0].position: expected a vector"},
        {"vector of three", sceneWith(R"({"position": [1, 2, 3]})"), "bodies[0].position: expected a vector"},
        {"bool for a number", sceneWith(R"({"angle": true})"), "bodies[0].angle: expected a number"},
        {"number for a bool", sceneWith(R"({"bullet": 1})"), "bodies[0].bullet: expected true or false"},
        {"string for enabled", withShape(R"({"type": "circle", "radius": 1, "enabled": "no"})"),
         "bodies[0].shapes[0].enabled: expected true or false"},
        {"string element", sceneWith(R"({"position": [0, "1"]})"), "bodies[0].position[1]: expected a number"},
        {"shapes not an array", sceneWith(R"({"shapes": {"type": "circle"}})"), "bodies[0].shapes: expected an array"},
        {"body not an object", sceneWith("42"), "bodies[0]: expected an object"},
        {"root not an object", "[1, 2]", "(root): expected an object"},
        {"non-convex polygon", withShape(R"({"type": "polygon", "vertices": [[0,0], [2,0], [1,0.2], [2,2], [0,2]]})"),
         "bodies[0].shapes[0].vertices: "},
        {"9 vertices", withShape(R"({"type": "polygon", "vertices": [[1,0], [0.77,0.64], [0.17,0.98], [-0.5,0.87],
          [-0.94,0.34], [-0.94,-0.34], [-0.5,-0.87], [0.17,-0.98], [0.77,-0.64]]})"),
         "bodies[0].shapes[0].vertices: "},
        {"2 vertices", withShape(R"({"type": "polygon", "vertices": [[0,0], [1,0]]})"), "bodies[0].shapes[0].vertices: "},
        {"polygon without vertices", withShape(R"({"type": "polygon"})"),
         "bodies[0].shapes[0].vertices: missing required key"},
        {"negative density", withShape(R"({"type": "circle", "radius": 1, "density": -1})"),
         "bodies[0].shapes[0].density: must not be negative"},
        {"zero radius", withShape(R"({"type": "circle", "radius": 0})"), "bodies[0].shapes[0].radius: must be positive"},
        {"negative half extent", withShape(R"({"type": "box", "half_extents": [1, -1]})"),
         "bodies[0].shapes[0].half_extents: must be positive"},
        {"chain of one vertex", withShape(R"({"type": "chain", "vertices": [[0, 0]]})"),
         "bodies[0].shapes[0].vertices: a chain needs at least 2"},
        {"chain with a repeated vertex", withShape(R"({"type": "chain", "vertices": [[0, 0], [1, 0], [1, 0]]})"),
         "bodies[0].shapes[0].vertices[2]: coincides"},
        {"degenerate segment", withShape(R"({"type": "segment", "v1": [1, 1], "v2": [1, 1]})"), "bodies[0].shapes[0]: "},
        {"unknown shape type", withShape(R"({"type": "triangle"})"), "bodies[0].shapes[0].type: unknown type \"triangle\""},
        {"shape without type", withShape(R"({"radius": 1})"), "bodies[0].shapes[0].type: missing required key"},
        {"unknown body type", sceneWith(R"({"type": "dinamic"})"), "bodies[0].type: unknown type \"dinamic\""},
        {"filter mask too large", withShape(R"({"type": "circle", "radius": 1, "filter": {"mask": 70000}})"),
         "bodies[0].shapes[0].filter.mask: must be in"},
        {"duplicate names", sceneWith(box + ", " + box), "bodies[1].name: duplicate body name \"box\""},
        {"explicit name equal to a default one", sceneWith(R"({}, {"name": "body0"})"), "bodies[1].name: duplicate"},
        {"empty name", sceneWith(R"({"name": ""})"), "bodies[0].name: must not be empty"},
        {"joint naming a missing body", withJoint(R"({"type": "revolute", "body_a": "box", "body_b": "wheel"})"),
         "joints[0].body_b: no body named \"wheel\""},
        {"joint on one body", withJoint(R"({"type": "weld", "body_a": "box", "body_b": "box"})"), "joints[0].body_b: "},
        {"joint key of another type", withJoint(R"({"type": "revolute", "body_a": "box", "body_b": "ball", "axis": [1, 0]})"),
         "joints[0].axis: unknown key"},
        {"negative friction force", withJoint(R"({"type": "friction", "body_a": "box", "body_b": "ball", "max_force": -1})"),
         "joints[0].max_force: must not be negative"},
        {"friction joint with a motor key", withJoint(R"({"type": "friction", "body_a": "box", "body_b": "ball", "linear_offset": [0, 1]})"),
         "joints[0].linear_offset: unknown key"},
        {"unknown joint type", withJoint(R"({"type": "rope", "body_a": "box", "body_b": "ball"})"),
         "joints[0].type: unknown type \"rope\""},
        {"distance joint with one world anchor",
         withJoint(R"({"type": "distance", "body_a": "box", "body_b": "ball", "anchor": [0, 0]})"),
         "joints[0].anchor_b: missing required key"},
        {"half a pair of local anchors",
         withJoint(R"({"type": "weld", "body_a": "box", "body_b": "ball", "local_anchor_a": [0, 0]})"),
         "joints[0].local_anchor_b: missing required key"},
        {"limit upside down",
         withJoint(R"({"type": "revolute", "body_a": "box", "body_b": "ball", "lower_angle": 1, "upper_angle": -1})"),
         "joints[0].upper_angle: must not be less than lower_angle"},
        {"zero axis", withJoint(R"({"type": "prismatic", "body_a": "box", "body_b": "ball", "axis": [0, 0]})"),
         "joints[0].axis: must not be zero"},
        {"action on a missing body", withAction(R"({"type": "force", "body": "crate", "value": [1, 0]})"),
         "actions[0].body: no body named \"crate\""},
        {"action range backwards", withAction(R"({"type": "torque", "body": "box", "value": 1, "first_step": 5, "last_step": 4})"),
         "actions[0].last_step: must not be less than first_step"},
        {"torque given as a vector", withAction(R"({"type": "torque", "body": "box", "value": [1, 0]})"),
         "actions[0].value: expected a number"},
        {"point on a torque", withAction(R"({"type": "torque", "body": "box", "value": 1, "point": [0, 0]})"),
         "actions[0].point: unknown key"},
        {"negative first step", withAction(R"({"type": "impulse", "body": "box", "value": [1, 0], "first_step": -1})"),
         "actions[0].first_step: must be in"},
        {"unknown action type", withAction(R"({"type": "push", "body": "box", "value": [1, 0]})"),
         "actions[0].type: unknown type \"push\""},
        {"bad format string", R"({"format": "perpdot-scene/2"})", "format: expected \"perpdot-scene/1\""},
        {"missing format", R"({"bodies": []})", "format: missing required key"},
        {"timestep 0", sceneWith(box, R"(, "timestep": 0)"), "timestep: must be positive"},
        {"negative timestep", sceneWith(box, R"(, "timestep": -0.01)"), "timestep: must be positive"},
        {"absurd timestep", sceneWith(box, R"(, "timestep": 60)"), "timestep: must be positive and at most"},
        {"steps as a string", sceneWith(box, R"(, "steps": "600")"), "steps: expected an integer"},
        {"fractional steps", sceneWith(box, R"(, "steps": 1.5)"), "steps: expected an integer"},
        {"negative steps", sceneWith(box, R"(, "steps": -1)"), "steps: must be in"},
        {"absurd steps", sceneWith(box, R"(, "steps": 100000000000)"), "steps: must be in"},
        {"substeps 0", sceneWith(box, R"(, "solver": {"substeps": 0})"), "solver.substeps: must be in"},
        {"unknown solver key", sceneWith(box, R"(, "solver": {"iterations": 4})"), "solver.iterations: unknown key"},
        {"float overflow", sceneWith(box, R"(, "gravity": [0, -1e39])"), "gravity[1]: number is not finite"},
        {"double overflow", sceneWith(R"({"position": [1e400, 0]})"), "(root): number overflow parsing '1e400'"},
        {"duplicate key", withShape(R"({"type": "circle", "radius": 1, "radius": 2})"),
         "bodies[0].shapes[0].radius: duplicate key"},
        {"duplicate key after arrays", sceneWith(R"({"shapes": [{"type": "chain", "vertices": [[0, 0], [1, 0]]}]},
          {"position": [0, 1], "angle": 0, "position": [1, 1]})"), "bodies[1].position: duplicate key"},
        {"duplicate top-level key", sceneWith(box, R"(, "steps": 5, "steps": 6)"), "steps: duplicate key"},
        {"malformed JSON", "{\n  \"format\": \"perpdot-scene/1\",\n  \"bodies\": [}\n}", "(root): parse error at line 3"},
        {"trailing garbage", R"({"format": "perpdot-scene/1"} x)", "(root): parse error at line 1"},
        {"empty text", "", "(root): parse error"},
    };
    for (const InvalidScene& c : cases) {
        const std::string message = errorOf(c.json);
        EXPECT_EQ(message.rfind(c.expectedPrefix, 0), 0u) << c.what << "\n  got: " << message;
    }
}

}  // namespace
}  // namespace perpdot
