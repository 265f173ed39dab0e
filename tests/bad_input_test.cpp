// Bad scene input that the format tests (scene_json_test.cpp) leave out: NaN, infinities and huge
// magnitudes in every kind of field. Each is refused with a message that starts with its JSON path;
// the limits are scene_limits.hpp's, and values just inside them still load and simulate.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "perpdot/error.hpp"
#include "perpdot/scene.hpp"

namespace perpdot {
namespace {

std::string errorOf(const std::string& json) {
    try {
        buildWorld(parseScene(json));
    } catch (const Error& e) {
        return e.what();
    }
    return "(accepted)";
}

std::string sceneWith(const std::string& body, const std::string& extra = "") {
    return R"({"format": "perpdot-scene/1", "bodies": [)" + body + "]" + extra + "}";
}
std::string bodyWith(const std::string& members) {
    return sceneWith(R"({"shapes": [{"type": "circle", "radius": 0.5}])" + members + "}");
}
std::string shapeWith(const std::string& shape) { return sceneWith(R"({"shapes": [)" + shape + "]}"); }

struct Case {
    const char* what;
    std::string json;
    std::string expectedPrefix;
};

TEST(BadInput, NonFiniteAndHugeValuesAreRefusedWithTheirPath) {
    const Case cases[] = {
        {"NaN literal", bodyWith(R"(, "position": [NaN, 0])"), "(root): parse error"},
        {"Infinity literal", bodyWith(R"(, "angle": Infinity)"), "(root): parse error"},
        {"NaN as a string", bodyWith(R"(, "angle": "nan")"), "bodies[0].angle: expected a number"},
        {"vertex overflowing a float", shapeWith(R"({"type": "polygon", "vertices": [[0, 0], [1e39, 0], [0, 1]]})"),
         "bodies[0].shapes[0].vertices[1][0]: number is not finite"},
        {"huge position", bodyWith(R"(, "position": [0, 1e30])"), "bodies[0].position[1]: must be at most"},
        {"huge angle", bodyWith(R"(, "angle": -1e20)"), "bodies[0].angle: must be at most"},
        {"huge velocity", bodyWith(R"(, "linear_velocity": [1e30, 0])"), "bodies[0].linear_velocity[0]: must be at most"},
        {"huge angular velocity", bodyWith(R"(, "angular_velocity": 1e9)"), "bodies[0].angular_velocity: must be at most"},
        {"huge damping", bodyWith(R"(, "linear_damping": 1e9)"), "bodies[0].linear_damping: must be at most"},
        {"huge gravity scale", bodyWith(R"(, "gravity_scale": -1e30)"), "bodies[0].gravity_scale: must be at most"},
        {"huge radius", shapeWith(R"({"type": "circle", "radius": 1e30})"), "bodies[0].shapes[0].radius: must be at most"},
        {"huge circle centre", shapeWith(R"({"type": "circle", "radius": 1, "center": [1e30, 0]})"),
         "bodies[0].shapes[0].center[0]: must be at most"},
        {"huge box", shapeWith(R"({"type": "box", "half_extents": [1e30, 1]})"),
         "bodies[0].shapes[0].half_extents[0]: must be at most"},
        {"huge polygon vertex", shapeWith(R"({"type": "polygon", "vertices": [[0, 0], [1e7, 0], [0, 1]]})"),
         "bodies[0].shapes[0].vertices[1][0]: must be at most"},
        {"huge polygon rounding", shapeWith(R"({"type": "polygon", "vertices": [[0, 0], [1, 0], [0, 1]], "radius": 1e30})"),
         "bodies[0].shapes[0].radius: must be at most"},
        {"huge segment end", shapeWith(R"({"type": "segment", "v1": [0, 0], "v2": [0, -1e30]})"),
         "bodies[0].shapes[0].v2[1]: must be at most"},
        {"huge chain vertex", shapeWith(R"({"type": "chain", "vertices": [[0, 0], [1e30, 1e30]]})"),
         "bodies[0].shapes[0].vertices[1][0]: must be at most"},
        {"huge density", shapeWith(R"({"type": "circle", "radius": 1, "density": 1e38})"), "bodies[0].shapes[0].density: must be at most"},
        {"huge friction", shapeWith(R"({"type": "circle", "radius": 1, "friction": 1e30})"), "bodies[0].shapes[0].friction: must be at most"},
        {"huge restitution", shapeWith(R"({"type": "circle", "radius": 1, "restitution": 1e30})"),
         "bodies[0].shapes[0].restitution: must be at most"},
        {"negative density", shapeWith(R"({"type": "box", "half_extents": [1, 1], "density": -0.5})"), "bodies[0].shapes[0].density: must not be negative"},
        {"huge gravity", sceneWith(R"({"shapes": []})", R"(, "gravity": [0, -1e30])"), "gravity[1]: must be at most"},
        {"box of zero width", shapeWith(R"({"type": "box", "half_extents": [0, 1]})"), "bodies[0].shapes[0].half_extents: must be positive"},
        {"sliver polygon", shapeWith(R"({"type": "polygon", "vertices": [[0, 0], [1, 0], [2, 1e-7]]})"), "bodies[0].shapes[0].vertices: "},
        {"polygon turning both ways", shapeWith(R"({"type": "polygon", "vertices": [[0, 0], [1, 1], [0, 1], [1, 0]]})"),
         "bodies[0].shapes[0].vertices: "},
    };
    for (const Case& c : cases) {
        const std::string message = errorOf(c.json);
        EXPECT_EQ(message.rfind(c.expectedPrefix, 0), 0u) << c.what << "\n  got: " << message;
    }
}

// The limits sit far from any real scene: values just inside them load and step without NaN.
TEST(BadInput, ValuesJustInsideTheLimitsAreAccepted) {
    const std::string json = sceneWith(
        R"({"position": [-99999, 99999], "linear_velocity": [9999, 0], "angular_velocity": 9999,
            "shapes": [{"type": "circle", "radius": 0.5, "density": 999999, "friction": 999}]})",
        R"(, "gravity": [0, -9999])");
    SceneWorld built = buildWorld(parseScene(json));
    for (int i = 0; i < 10; ++i) built.step();
    const Vec2 p = built.world.position(built.bodies[0]);
    EXPECT_TRUE(std::isfinite(p.x) && std::isfinite(p.y));
    EXPECT_GT(p.x, -99999.0f);  // it moved right at about 9999 m/s
}

}  // namespace
}  // namespace perpdot
