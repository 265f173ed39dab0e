// Reading `perpdot-scene/1` (docs/scene-format.md): defaults, strict keys, and validation.
// Every error is a perpdot::Error whose message starts with the JSON path of the offending value.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <set>
#include <span>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>

#include <nlohmann/json.hpp>

#include "perpdot/error.hpp"
#include "perpdot/scene.hpp"
#include "scene/scene_keys.hpp"
#include "scene/scene_limits.hpp"

namespace perpdot {
namespace {

using nlohmann::json;
using scene_keys::KeyList;

[[noreturn]] void fail(const std::string& path, const std::string& message) {
    throw Error((path.empty() ? std::string("(root)") : path) + ": " + message);
}

std::string member(const std::string& path, std::string_view key) {
    return path.empty() ? std::string(key) : path + "." + std::string(key);
}

std::string element(const std::string& path, size_t index) { return path + "[" + std::to_string(index) + "]"; }

// A JSON object being read: typed getters with defaults; keys outside the allowed lists are errors.
class Object {
public:
    Object(const json& j, std::string path) : j_(j), path_(std::move(path)) {
        if (!j_.is_object()) fail(path_, std::string("expected an object, got ") + j_.type_name());
    }

    const std::string& path() const { return path_; }
    bool has(std::string_view key) const { return j_.contains(key); }

    // Keys outside every one of `lists` (scene_keys.hpp) are errors.
    void allowOnly(std::initializer_list<KeyList> lists) const {
        for (const auto& item : j_.items()) {
            const auto known = [&](KeyList keys) { return std::find(keys.begin(), keys.end(), item.key()) != keys.end(); };
            if (std::none_of(lists.begin(), lists.end(), known)) fail(member(path_, item.key()), "unknown key");
        }
    }

    const json& required(std::string_view key) const {
        if (!has(key)) fail(member(path_, key), "missing required key");
        return j_.at(std::string(key));
    }

    float number(std::string_view key, float fallback) const { return has(key) ? numberAt(key) : fallback; }
    float numberAt(std::string_view key) const { return toFloat(required(key), member(path_, key)); }
    // A number that must be >= 0 (densities, radii, stiffness...).
    float nonNegative(std::string_view key, float fallback) const {
        const float value = number(key, fallback);
        if (value < 0.0f) fail(member(path_, key), "must not be negative");
        return value;
    }
    // A number or vector no larger than `limit` in magnitude (scene_limits.hpp).
    float bounded(std::string_view key, float fallback, float limit) const {
        return within(number(key, fallback), limit, member(path_, key));
    }
    float nonNegative(std::string_view key, float fallback, float limit) const {
        return within(nonNegative(key, fallback), limit, member(path_, key));
    }
    Vec2 boundedVec(std::string_view key, Vec2 fallback, float limit) const {
        const Vec2 v = vec(key, fallback);
        within(v.x, limit, element(member(path_, key), 0));
        within(v.y, limit, element(member(path_, key), 1));
        return v;
    }

    Vec2 vec(std::string_view key, Vec2 fallback) const { return has(key) ? vecAt(key) : fallback; }
    Vec2 vecAt(std::string_view key) const { return toVec(required(key), member(path_, key)); }

    bool boolean(std::string_view key, bool fallback) const {
        if (!has(key)) return fallback;
        const json& v = j_.at(std::string(key));
        if (!v.is_boolean()) fail(member(path_, key), std::string("expected true or false, got ") + v.type_name());
        return v.get<bool>();
    }

    long long integer(std::string_view key, long long fallback, long long lo, long long hi) const {
        if (!has(key)) return fallback;
        const json& v = j_.at(std::string(key));
        const std::string path = member(path_, key);
        if (!v.is_number_integer()) fail(path, std::string("expected an integer, got ") + v.type_name());
        // nlohmann stores non-negative integers as unsigned; compare those as unsigned (2^64 - 1 > hi).
        const bool inRange = v.is_number_unsigned()
                                 ? v.get<unsigned long long>() <= static_cast<unsigned long long>(hi) &&
                                       static_cast<long long>(v.get<unsigned long long>()) >= lo
                                 : (v.get<long long>() >= lo && v.get<long long>() <= hi);
        if (!inRange) fail(path, "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
        return v.get<long long>();
    }

    std::string string(std::string_view key, std::string fallback) const {
        if (!has(key)) return fallback;
        const json& v = j_.at(std::string(key));
        if (!v.is_string()) fail(member(path_, key), std::string("expected a string, got ") + v.type_name());
        return v.get<std::string>();
    }
    std::string requiredString(std::string_view key) const {
        required(key);
        return string(key, {});
    }

    // The array at `key` (empty if absent), each element with its path.
    std::vector<std::pair<const json*, std::string>> array(std::string_view key) const {
        std::vector<std::pair<const json*, std::string>> items;
        if (!has(key)) return items;
        const json& v = j_.at(std::string(key));
        const std::string path = member(path_, key);
        if (!v.is_array()) fail(path, std::string("expected an array, got ") + v.type_name());
        for (size_t i = 0; i < v.size(); ++i) items.emplace_back(&v[i], element(path, i));
        return items;
    }

    // Polygon and chain vertices, each coordinate within maxCoordinate.
    std::vector<Vec2> points(std::string_view key) const {
        std::vector<Vec2> result;
        for (const auto& [item, path] : array(key)) {
            const Vec2 v = toVec(*item, path);
            within(v.x, maxCoordinate, element(path, 0));
            within(v.y, maxCoordinate, element(path, 1));
            result.push_back(v);
        }
        return result;
    }

    // JSON numbers are doubles; anything that overflows a float (1e39) becomes inf and is refused.
    static float toFloat(const json& v, const std::string& path) {
        if (!v.is_number()) fail(path, std::string("expected a number, got ") + v.type_name());
        const float value = static_cast<float>(v.get<double>());
        if (!std::isfinite(value)) fail(path, "number is not finite in single precision");
        return value;
    }

    static float within(float value, float limit, const std::string& path) {
        if (std::fabs(value) > limit) {
            std::ostringstream text;
            text << "must be at most " << limit << " in magnitude, got " << value;
            fail(path, text.str());
        }
        return value;
    }

    static Vec2 toVec(const json& v, const std::string& path) {
        if (!v.is_array() || v.size() != 2) fail(path, "expected a vector [x, y]");
        return {toFloat(v[0], element(path, 0)), toFloat(v[1], element(path, 1))};
    }

private:
    const json& j_;
    std::string path_;
};

// Looks `text` up in a table of (name, value) pairs; the error lists the accepted names.
template <class T, size_t N>
T enumValue(const std::string& text, const std::pair<const char*, T> (&table)[N], const std::string& path) {
    std::string accepted;
    for (const auto& [name, value] : table) {
        if (text == name) return value;
        accepted += std::string(accepted.empty() ? "" : ", ") + "\"" + name + "\"";
    }
    fail(path, "unknown type \"" + text + "\" (expected one of " + accepted + ")");
}

constexpr std::pair<const char*, BodyType> bodyTypes[] = {
    {"static", BodyType::Static}, {"kinematic", BodyType::Kinematic}, {"dynamic", BodyType::Dynamic}};
constexpr std::pair<const char*, SceneShape::Kind> shapeKinds[] = {
    {"circle", SceneShape::Kind::Circle}, {"box", SceneShape::Kind::Box}, {"polygon", SceneShape::Kind::Polygon},
    {"segment", SceneShape::Kind::Segment}, {"chain", SceneShape::Kind::Chain}, {"capsule", SceneShape::Kind::Capsule}};
constexpr std::pair<const char*, JointType> jointTypes[] = {
    {"revolute", JointType::Revolute}, {"prismatic", JointType::Prismatic}, {"distance", JointType::Distance},
    {"weld", JointType::Weld}, {"wheel", JointType::Wheel}, {"motor", JointType::Motor},
    {"friction", JointType::Friction}, {"gear", JointType::Gear}, {"pulley", JointType::Pulley}};
constexpr std::pair<const char*, SceneAction::Kind> actionKinds[] = {
    {"force", SceneAction::Kind::Force}, {"impulse", SceneAction::Kind::Impulse},
    {"torque", SceneAction::Kind::Torque}, {"angular_impulse", SceneAction::Kind::AngularImpulse},
    {"explosion", SceneAction::Kind::Explosion}};

Filter readFilter(const Object& o) {
    o.allowOnly({scene_keys::filter});
    Filter f;
    f.category = static_cast<uint16_t>(o.integer("category", f.category, 0, 0xFFFF));
    f.mask = static_cast<uint16_t>(o.integer("mask", f.mask, 0, 0xFFFF));
    f.group = static_cast<int16_t>(o.integer("group", f.group, -32768, 32767));
    return f;
}

SceneShape readShape(const Object& o) {
    SceneShape s;
    const std::string type = o.requiredString("type");
    s.kind = enumValue(type, shapeKinds, member(o.path(), "type"));
    const KeyList common = scene_keys::shape;
    switch (s.kind) {
        case SceneShape::Kind::Circle:
            o.allowOnly({common, scene_keys::circle});
            s.radius = o.bounded("radius", 0.0f, maxCoordinate);
            if (s.radius <= 0.0f) fail(member(o.path(), "radius"), "must be positive");
            s.center = o.boundedVec("center", {}, maxCoordinate);
            break;
        case SceneShape::Kind::Box:
            o.allowOnly({common, scene_keys::box});
            o.required("half_extents");
            s.halfExtents = o.boundedVec("half_extents", {}, maxCoordinate);
            if (s.halfExtents.x <= 0.0f || s.halfExtents.y <= 0.0f) fail(member(o.path(), "half_extents"), "must be positive");
            s.center = o.boundedVec("center", {}, maxCoordinate);
            s.angle = o.number("angle", 0.0f);
            break;
        case SceneShape::Kind::Polygon:
            o.allowOnly({common, scene_keys::polygon});
            o.required("vertices");
            s.vertices = o.points("vertices");
            s.radius = o.nonNegative("radius", 0.0f, maxCoordinate);
            try {
                makePolygon(s.vertices, s.radius);  // the library's own check: 3..8 points, strictly convex
            } catch (const Error& e) {
                fail(member(o.path(), "vertices"), e.what());
            }
            break;
        case SceneShape::Kind::Segment:
            o.allowOnly({common, scene_keys::segment});
            o.required("v1");
            o.required("v2");
            s.v1 = o.boundedVec("v1", {}, maxCoordinate);
            s.v2 = o.boundedVec("v2", {}, maxCoordinate);
            if (distance(s.v1, s.v2) <= minEdgeLength) fail(o.path(), "segment is degenerate (v1 == v2)");
            break;
        case SceneShape::Kind::Capsule:
            o.allowOnly({common, scene_keys::capsule});
            o.required("center1");
            o.required("center2");
            o.required("radius");
            s.v1 = o.boundedVec("center1", {}, maxCoordinate);
            s.v2 = o.boundedVec("center2", {}, maxCoordinate);
            s.radius = o.bounded("radius", 0.0f, maxCoordinate);
            if (s.radius <= 0.0f) fail(member(o.path(), "radius"), "must be positive");
            if (distance(s.v1, s.v2) <= minEdgeLength) fail(member(o.path(), "center2"), "is within 0.005 m of center1 (use a circle)");
            break;
        case SceneShape::Kind::Chain: {
            o.allowOnly({common, scene_keys::chain});
            o.required("vertices");
            s.vertices = o.points("vertices");
            s.loop = o.boolean("loop", false);
            const size_t minCount = s.loop ? 3 : 2;
            if (s.vertices.size() < minCount)
                fail(member(o.path(), "vertices"), "a " + std::string(s.loop ? "loop" : "chain") + " needs at least " +
                                                       std::to_string(minCount) + " vertices");
            for (size_t i = 1; i < s.vertices.size(); ++i)
                if (distance(s.vertices[i - 1], s.vertices[i]) <= minEdgeLength)
                    fail(element(member(o.path(), "vertices"), i), "coincides with the previous vertex");
            const std::string solid = o.string("solid", "left");
            if (solid != "left" && solid != "right") fail(member(o.path(), "solid"), "expected \"left\" or \"right\", got \"" + solid + "\"");
            s.solid = solid == "right" ? ChainSide::Right : ChainSide::Left;
            for (const auto& [key, ghost] : {std::pair{"prev_vertex", &s.prevVertex}, std::pair{"next_vertex", &s.nextVertex}}) {
                if (!o.has(key)) continue;
                if (s.loop) fail(member(o.path(), key), "a loop takes no ghost vertices");
                const Vec2 g = o.vecAt(key);
                if (std::fabs(g.x) > maxCoordinate || std::fabs(g.y) > maxCoordinate)
                    fail(member(o.path(), key), "must be at most " + std::to_string(maxCoordinate) + " in magnitude");
                *ghost = g;
            }
            break;
        }
    }
    s.density = o.nonNegative("density", s.density, maxDensity);
    s.friction = o.nonNegative("friction", s.friction, maxMaterial);
    s.restitution = o.nonNegative("restitution", s.restitution, maxMaterial);
    s.sensor = o.boolean("sensor", s.sensor);
    s.enabled = o.boolean("enabled", s.enabled);
    if (o.has("filter")) s.filter = readFilter(Object(o.required("filter"), member(o.path(), "filter")));
    return s;
}

SceneMass readMass(const Object& o) {
    o.allowOnly({scene_keys::massData});
    SceneMass m;
    m.mass = o.nonNegative("mass", m.mass, maxDensity);
    m.center = o.boundedVec("center", {}, maxCoordinate);
    m.rotationalInertia = o.nonNegative("rotational_inertia", m.rotationalInertia, maxDensity * maxCoordinate);
    return m;
}

SceneBody readBody(const Object& o, size_t index) {
    o.allowOnly({scene_keys::body});
    SceneBody b;
    b.name = o.string("name", defaultBodyName(index));
    if (b.name.empty()) fail(member(o.path(), "name"), "must not be empty");
    b.type = enumValue(o.string("type", "dynamic"), bodyTypes, member(o.path(), "type"));
    b.position = o.boundedVec("position", {}, maxCoordinate);
    b.angle = o.bounded("angle", 0.0f, maxCoordinate);
    b.linearVelocity = o.boundedVec("linear_velocity", {}, maxSpeed);
    b.angularVelocity = o.bounded("angular_velocity", 0.0f, maxSpeed);
    b.linearDamping = o.nonNegative("linear_damping", 0.0f, maxMaterial);
    b.angularDamping = o.nonNegative("angular_damping", 0.0f, maxMaterial);
    b.gravityScale = o.bounded("gravity_scale", 1.0f, maxMaterial);
    b.fixedRotation = o.boolean("fixed_rotation", false);
    b.bullet = o.boolean("bullet", false);
    b.allowSleep = o.boolean("allow_sleep", true);
    b.awake = o.boolean("awake", true);
    b.enabled = o.boolean("enabled", true);
    for (const auto& [item, path] : o.array("shapes")) b.shapes.push_back(readShape(Object(*item, path)));
    if (o.has("mass_data")) b.massData = readMass(Object(o.required("mass_data"), member(o.path(), "mass_data")));
    return b;
}

// Keys each joint type accepts besides the common ones (scene-format.md, "Joints").
KeyList jointKeys(JointType type) {
    switch (type) {
        case JointType::Revolute: return scene_keys::revolute;
        case JointType::Distance: return scene_keys::distance;
        case JointType::Prismatic: return scene_keys::prismatic;
        case JointType::Weld: return scene_keys::weld;
        case JointType::Wheel: return scene_keys::wheel;
        case JointType::Motor: return scene_keys::motor;
        case JointType::Friction: return scene_keys::friction;
        case JointType::Gear: return scene_keys::gear;
        case JointType::Pulley: return scene_keys::pulley;
        default: break;  // not in the file format (mouse joints)
    }
    return {};
}

void readAnchors(const Object& o, SceneJoint& j) {
    if (o.has("anchor") && (o.has("local_anchor_a") || o.has("local_anchor_b")))
        fail(member(o.path(), "anchor"), "give either a world anchor or local anchors, not both");
    if (o.has("local_anchor_a") != o.has("local_anchor_b"))
        fail(member(o.path(), o.has("local_anchor_a") ? "local_anchor_b" : "local_anchor_a"),
             "missing required key (local anchors come in pairs)");
    if (o.has("anchor")) j.anchor = o.vecAt("anchor");
    if (o.has("anchor_b")) {
        if (!j.anchor) fail(member(o.path(), "anchor_b"), "needs \"anchor\" as body A's world anchor");
        j.anchorB = o.vecAt("anchor_b");
    } else if ((j.type == JointType::Distance || j.type == JointType::Pulley) && j.anchor) {
        fail(member(o.path(), "anchor_b"), "missing required key (a " + std::string(j.type == JointType::Distance ? "distance" : "pulley") +
                                               " joint has two world anchors)");
    }
    if (o.has("local_anchor_a")) {
        j.localAnchorA = o.vecAt("local_anchor_a");
        j.localAnchorB = o.vecAt("local_anchor_b");
    }
}

void requireOrdered(const Object& o, std::string_view lowKey, float low, std::string_view highKey, float high) {
    if (low > high) fail(member(o.path(), highKey), "must not be less than " + std::string(lowKey));
}

// A gear names two earlier revolute or prismatic joints by index; its bodies are theirs body B.
void readGear(const Object& o, SceneJoint& j, const std::vector<SceneJoint>& earlier) {
    const auto readIndex = [&](const char* key, const std::string& body, const char* bodyKey) {
        const std::string path = member(o.path(), key);
        o.required(key);
        const int index = static_cast<int>(o.integer(key, -1, 0, maxSceneSteps));
        if (index >= static_cast<int>(earlier.size()))
            fail(path, "must be the index of an earlier joint (this is joint " + std::to_string(earlier.size()) + ")");
        const SceneJoint& geared = earlier[index];
        if (geared.type != JointType::Revolute && geared.type != JointType::Prismatic)
            fail(path, "must name a revolute or prismatic joint");
        if (geared.bodyB != body)
            fail(member(o.path(), bodyKey), "must be the geared joint's body_b, \"" + geared.bodyB + "\"");
        return index;
    };
    j.jointA = readIndex("joint_a", j.bodyA, "body_a");
    j.jointB = readIndex("joint_b", j.bodyB, "body_b");
    j.ratio = o.bounded("ratio", 1.0f, maxCoordinate);
    if (j.ratio == 0.0f) fail(member(o.path(), "ratio"), "must not be 0");
}

void readPulley(const Object& o, SceneJoint& j) {
    o.required("ground_anchor_a");
    o.required("ground_anchor_b");
    j.groundAnchorA = o.boundedVec("ground_anchor_a", {}, maxCoordinate);
    j.groundAnchorB = o.boundedVec("ground_anchor_b", {}, maxCoordinate);
    for (auto [key, length] : {std::pair{"length_a", &j.lengthA}, std::pair{"length_b", &j.lengthB}}) {
        if (!o.has(key)) continue;
        *length = o.bounded(key, 0.0f, maxCoordinate);
        if (!(**length > 0.0f)) fail(member(o.path(), key), "must be positive");
    }
    j.ratio = o.bounded("ratio", 1.0f, maxCoordinate);
    if (!(j.ratio > 0.0f)) fail(member(o.path(), "ratio"), "must be positive");
}

SceneJoint readJoint(const Object& o, const std::set<std::string>& bodyNames, const std::vector<SceneJoint>& earlier) {
    SceneJoint j;
    const std::string type = o.requiredString("type");
    j.type = enumValue(type, jointTypes, member(o.path(), "type"));
    const bool anchored = j.type != JointType::Motor && j.type != JointType::Gear;
    if (anchored)
        o.allowOnly({scene_keys::joint, scene_keys::jointAnchors, jointKeys(j.type)});
    else
        o.allowOnly({scene_keys::joint, jointKeys(j.type)});
    for (const char* key : {"body_a", "body_b"}) {
        const std::string name = o.requiredString(key);
        if (!bodyNames.contains(name)) fail(member(o.path(), key), "no body named \"" + name + "\"");
        (key == std::string_view("body_a") ? j.bodyA : j.bodyB) = name;
    }
    if (j.bodyA == j.bodyB) fail(member(o.path(), "body_b"), "a joint needs two different bodies");
    j.collideConnected = o.boolean("collide_connected", false);
    if (anchored) readAnchors(o, j);

    j.enableLimit = o.boolean("enable_limit", false);
    j.lowerAngle = o.number("lower_angle", 0.0f);
    j.upperAngle = o.number("upper_angle", 0.0f);
    requireOrdered(o, "lower_angle", j.lowerAngle, "upper_angle", j.upperAngle);
    j.lower = o.number("lower", 0.0f);
    j.upper = o.number("upper", 0.0f);
    requireOrdered(o, "lower", j.lower, "upper", j.upper);
    j.enableMotor = o.boolean("enable_motor", false);
    j.motorSpeed = o.number("motor_speed", 0.0f);
    j.maxMotorTorque = o.nonNegative("max_motor_torque", 0.0f);
    j.maxMotorForce = o.nonNegative("max_motor_force", 0.0f);
    if (o.has("length")) j.length = o.nonNegative("length", 0.0f);
    j.minLength = o.nonNegative("min_length", j.minLength);
    j.maxLength = o.nonNegative("max_length", j.maxLength);
    requireOrdered(o, "min_length", j.minLength, "max_length", j.maxLength);
    j.hertz = o.nonNegative("hertz", 0.0f);
    j.dampingRatio = o.nonNegative("damping_ratio", 0.0f);
    j.axis = o.vec("axis", j.axis);
    if (length(j.axis) < 1.0e-6f) fail(member(o.path(), "axis"), "must not be zero");
    j.linearOffset = o.vec("linear_offset", {});
    j.angularOffset = o.number("angular_offset", 0.0f);
    // A motor drives with 1 N and 1 N·m unless told (b2MotorJointDef); a friction joint, like
    // b2FrictionJointDef, holds nothing unless told.
    const float defaultMax = j.type == JointType::Friction ? 0.0f : 1.0f;
    j.maxForce = o.nonNegative("max_force", defaultMax);
    j.maxTorque = o.nonNegative("max_torque", defaultMax);
    if (o.has("break_force")) j.breakForce = o.nonNegative("break_force", 0.0f);
    if (o.has("break_torque")) j.breakTorque = o.nonNegative("break_torque", 0.0f);
    j.destroyOnBreak = o.boolean("destroy_on_break", true);
    if (j.type == JointType::Gear) readGear(o, j, earlier);
    if (j.type == JointType::Pulley) readPulley(o, j);
    return j;
}

// The steps an action applies to: first_step .. last_step, inclusive.
void readStepRange(const Object& o, SceneAction& a) {
    a.firstStep = static_cast<int>(o.integer("first_step", 0, 0, maxSceneSteps));
    a.lastStep = static_cast<int>(o.integer("last_step", a.firstStep, 0, maxSceneSteps));
    if (a.lastStep < a.firstStep) fail(member(o.path(), "last_step"), "must not be less than first_step");
}

// World::explode at `point`: `value` N·s at the centre falling off to nothing at `radius`.
SceneAction readExplosion(const Object& o) {
    o.allowOnly({scene_keys::explosion});
    SceneAction a{.kind = SceneAction::Kind::Explosion};
    a.point = o.boundedVec("point", {}, maxCoordinate);
    if (!o.has("point")) fail(member(o.path(), "point"), "missing required key (the explosion's centre)");
    a.radius = o.nonNegative("radius", 0.0f, maxCoordinate);
    if (!(a.radius > 0.0f)) fail(member(o.path(), "radius"), "must be > 0");
    a.scalar = o.nonNegative("value", 0.0f, maxCoordinate);
    if (!o.has("value")) fail(member(o.path(), "value"), "missing required key (the impulse at the centre, N·s)");
    a.blockedByStatic = o.boolean("blocked_by_static", false);
    readStepRange(o, a);
    return a;
}

SceneAction readAction(const Object& o, const std::set<std::string>& bodyNames) {
    SceneAction a;
    a.kind = enumValue(o.requiredString("type"), actionKinds, member(o.path(), "type"));
    if (a.kind == SceneAction::Kind::Explosion) {
        if (o.has("body")) fail(member(o.path(), "body"), "an explosion acts on every shape in its radius: it takes no body");
        return readExplosion(o);
    }
    const bool linear = a.kind == SceneAction::Kind::Force || a.kind == SceneAction::Kind::Impulse;
    if (linear)
        o.allowOnly({scene_keys::action, scene_keys::actionPoint});
    else
        o.allowOnly({scene_keys::action});
    a.body = o.requiredString("body");
    if (!bodyNames.contains(a.body)) fail(member(o.path(), "body"), "no body named \"" + a.body + "\"");
    if (linear) {
        a.value = o.vecAt("value");
        if (o.has("point")) a.point = o.vecAt("point");
    } else {
        a.scalar = o.numberAt("value");
    }
    readStepRange(o, a);
    return a;
}

void readSolver(const Object& o, SceneSolver& solver) {
    o.allowOnly({scene_keys::solver});
    if (o.has("substeps")) solver.substeps = static_cast<int>(o.integer("substeps", 0, 1, maxSubsteps));
    solver.velocityIterations = static_cast<int>(o.integer("velocity_iterations", solver.velocityIterations, 1, maxIterations));
    solver.positionIterations = static_cast<int>(o.integer("position_iterations", solver.positionIterations, 0, maxIterations));
    solver.box2dSkin = o.boolean("box2d_skin", false);
}

Scene readScene(const Object& o) {
    o.allowOnly({scene_keys::root});
    const std::string format = o.requiredString("format");
    if (format != sceneFormat) fail("format", "expected \"" + std::string(sceneFormat) + "\", got \"" + format + "\"");
    Scene s;
    s.name = o.string("name", "");
    s.description = o.string("description", "");
    s.gravity = o.boundedVec("gravity", s.gravity, maxGravity);
    s.timestep = o.number("timestep", s.timestep);
    if (!(s.timestep > 0.0f && s.timestep <= maxTimestep))
        fail("timestep", "must be positive and at most " + std::to_string(int(maxTimestep)) + " s");
    s.steps = static_cast<int>(o.integer("steps", s.steps, 0, maxSceneSteps));
    if (o.has("solver")) readSolver(Object(o.required("solver"), "solver"), s.solver);

    std::set<std::string> names;
    for (const auto& [item, path] : o.array("bodies")) {
        s.bodies.push_back(readBody(Object(*item, path), s.bodies.size()));
        if (!names.insert(s.bodies.back().name).second)
            fail(member(path, "name"), "duplicate body name \"" + s.bodies.back().name + "\"");
    }
    for (const auto& [item, path] : o.array("joints")) s.joints.push_back(readJoint(Object(*item, path), names, s.joints));
    for (const auto& [item, path] : o.array("actions")) s.actions.push_back(readAction(Object(*item, path), names));
    return s;
}

// nlohmann keeps the last of two equal keys; a scene file with "position" twice is a mistake, so
// the parser's callback tracks the keys of every open object, and the JSON path for the message.
class DuplicateKeyCheck {
public:
    bool operator()(int, json::parse_event_t event, json& parsed) {
        using Event = json::parse_event_t;
        switch (event) {
            case Event::object_start:
            case Event::array_start:
                enterValue();
                open_.push_back({event == Event::array_start});
                break;
            case Event::object_end:
            case Event::array_end: open_.pop_back(); break;
            case Event::key: {
                Frame& object = open_.back();
                object.key = parsed.get<std::string>();
                if (!object.keys.insert(object.key).second) fail(path(), "duplicate key");
                break;
            }
            case Event::value: enterValue(); break;
        }
        return true;
    }

private:
    struct Frame {
        bool isArray = false;
        size_t index = 0;  // arrays: elements begun so far
        std::string key{};  // objects: the current key
        std::set<std::string> keys{};
    };

    void enterValue() {
        if (!open_.empty() && open_.back().isArray) ++open_.back().index;
    }

    std::string path() const {
        std::string result;
        for (const Frame& f : open_) result = f.isArray ? element(result, f.index - 1) : member(result, f.key);
        return result;
    }

    std::vector<Frame> open_;
};

}  // namespace

std::string defaultBodyName(size_t index) { return "body" + std::to_string(index); }

Scene parseScene(std::string_view text) {
    json document;
    try {
        document = json::parse(text, DuplicateKeyCheck());
    } catch (const json::exception& e) {
        // nlohmann's message reads "[json.exception.parse_error.101] parse error at line 3, column 5: ...",
        // or "[json.exception.out_of_range.406] number overflow parsing '1e400'".
        std::string message = e.what();
        if (const size_t end = message.find("] "); message.starts_with("[json.exception") && end != std::string::npos)
            message.erase(0, end + 2);
        throw Error("(root): " + message);
    }
    return readScene(Object(document, ""));
}

Scene loadScene(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(path + ": cannot open scene file");
    std::ostringstream text;
    text << in.rdbuf();
    try {
        return parseScene(text.str());
    } catch (const Error& e) {
        throw Error(path + ": " + e.what());
    }
}

}  // namespace perpdot
