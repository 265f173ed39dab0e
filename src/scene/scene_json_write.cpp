// Writing `perpdot-scene/1`: keys at their default value are left out, floats are written with
// the fewest digits that read back to the same float, and each body, joint and action is one
// line so that large scenes stay readable and diff well.
#include <charconv>
#include <cstdlib>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "perpdot/error.hpp"
#include "perpdot/scene.hpp"
#include "scene/scene_limits.hpp"

namespace perpdot {
namespace {

using Json = nlohmann::ordered_json;

// The shortest decimal of a float, as the double nearest to it: 0.1f is written 0.1, not
// 0.100000001490116; reading it back as double then float gives the same float.
double shortest(float value) {
    char text[32];
    const auto end = std::to_chars(text, text + sizeof text - 1, value).ptr;
    *end = '\0';
    const double decimal = std::strtod(text, nullptr);
    return static_cast<float>(decimal) == value ? decimal : static_cast<double>(value);
}

Json vec(Vec2 v) { return Json::array({shortest(v.x), shortest(v.y)}); }

Json points(const std::vector<Vec2>& vertices) {
    Json array = Json::array();
    for (Vec2 v : vertices) array.push_back(vec(v));
    return array;
}

// Sets o[key] unless value equals the default.
template <class T>
void put(Json& o, const char* key, const T& value, const T& fallback) {
    if (value == fallback) return;
    if constexpr (std::is_same_v<T, float>)
        o[key] = shortest(value);
    else if constexpr (std::is_same_v<T, Vec2>)
        o[key] = vec(value);
    else
        o[key] = value;
}

const char* name(BodyType type) {
    switch (type) {
        case BodyType::Static: return "static";
        case BodyType::Kinematic: return "kinematic";
        case BodyType::Dynamic: break;
    }
    return "dynamic";
}

const char* name(JointType type) {
    switch (type) {
        case JointType::Revolute: return "revolute";
        case JointType::Prismatic: return "prismatic";
        case JointType::Distance: return "distance";
        case JointType::Weld: return "weld";
        case JointType::Wheel: return "wheel";
        case JointType::Motor: return "motor";
        case JointType::Friction: return "friction";
        case JointType::Gear: return "gear";
        case JointType::Pulley: return "pulley";
        default: break;  // mouse joints, and types the format does not have (docs/joints.md)
    }
    throw Error("mouse joints are interactive and cannot be saved in a scene; nor can joints of a type the format does not have");
}

const char* name(SceneAction::Kind kind) {
    switch (kind) {
        case SceneAction::Kind::Force: return "force";
        case SceneAction::Kind::Impulse: return "impulse";
        case SceneAction::Kind::Torque: return "torque";
        case SceneAction::Kind::Explosion: return "explosion";
        case SceneAction::Kind::AngularImpulse: break;
    }
    return "angular_impulse";
}

Json shapeJson(const SceneShape& s) {
    const SceneShape d;
    Json o;
    switch (s.kind) {
        case SceneShape::Kind::Circle:
            o["type"] = "circle";
            o["radius"] = shortest(s.radius);
            put(o, "center", s.center, d.center);
            break;
        case SceneShape::Kind::Box:
            o["type"] = "box";
            o["half_extents"] = vec(s.halfExtents);
            put(o, "center", s.center, d.center);
            put(o, "angle", s.angle, d.angle);
            break;
        case SceneShape::Kind::Polygon:
            o["type"] = "polygon";
            o["vertices"] = points(s.vertices);
            put(o, "radius", s.radius, 0.0f);
            break;
        case SceneShape::Kind::Segment:
            o["type"] = "segment";
            o["v1"] = vec(s.v1);
            o["v2"] = vec(s.v2);
            break;
        case SceneShape::Kind::Capsule:
            o["type"] = "capsule";
            o["center1"] = vec(s.v1);
            o["center2"] = vec(s.v2);
            o["radius"] = shortest(s.radius);
            break;
        case SceneShape::Kind::Chain:
            o["type"] = "chain";
            o["vertices"] = points(s.vertices);
            put(o, "loop", s.loop, d.loop);
            if (s.solid != d.solid) o["solid"] = "right";
            if (s.prevVertex) o["prev_vertex"] = vec(*s.prevVertex);
            if (s.nextVertex) o["next_vertex"] = vec(*s.nextVertex);
            break;
    }
    put(o, "density", s.density, d.density);
    put(o, "friction", s.friction, d.friction);
    put(o, "restitution", s.restitution, d.restitution);
    put(o, "sensor", s.sensor, d.sensor);
    put(o, "enabled", s.enabled, d.enabled);
    if (s.filter != d.filter)
        o["filter"] = Json{{"category", s.filter.category}, {"mask", s.filter.mask}, {"group", s.filter.group}};
    return o;
}

Json bodyJson(const SceneBody& b, size_t index) {
    const SceneBody d;
    Json o;
    put(o, "name", b.name, defaultBodyName(index));
    if (b.type != d.type) o["type"] = name(b.type);
    put(o, "position", b.position, d.position);
    put(o, "angle", b.angle, d.angle);
    put(o, "linear_velocity", b.linearVelocity, d.linearVelocity);
    put(o, "angular_velocity", b.angularVelocity, d.angularVelocity);
    put(o, "linear_damping", b.linearDamping, d.linearDamping);
    put(o, "angular_damping", b.angularDamping, d.angularDamping);
    put(o, "gravity_scale", b.gravityScale, d.gravityScale);
    put(o, "fixed_rotation", b.fixedRotation, d.fixedRotation);
    put(o, "bullet", b.bullet, d.bullet);
    put(o, "allow_sleep", b.allowSleep, d.allowSleep);
    put(o, "awake", b.awake, d.awake);
    put(o, "enabled", b.enabled, d.enabled);
    if (!b.shapes.empty()) {
        Json shapes = Json::array();
        for (const SceneShape& s : b.shapes) shapes.push_back(shapeJson(s));
        o["shapes"] = std::move(shapes);
    }
    if (b.massData) {
        const SceneMass md;
        Json m = Json::object();
        put(m, "mass", b.massData->mass, md.mass);
        put(m, "center", b.massData->center, md.center);
        put(m, "rotational_inertia", b.massData->rotationalInertia, md.rotationalInertia);
        o["mass_data"] = std::move(m);
    }
    return o;
}

// Only the keys the joint's type accepts (the reader refuses the others).
Json jointJson(const SceneJoint& j) {
    const SceneJoint d;
    Json o;
    o["type"] = name(j.type);
    o["body_a"] = j.bodyA;
    o["body_b"] = j.bodyB;
    if (j.anchor) o["anchor"] = vec(*j.anchor);
    if (j.anchorB) o["anchor_b"] = vec(*j.anchorB);
    if (j.localAnchorA) o["local_anchor_a"] = vec(*j.localAnchorA);
    if (j.localAnchorB) o["local_anchor_b"] = vec(*j.localAnchorB);
    put(o, "collide_connected", j.collideConnected, d.collideConnected);
    if (j.breakForce) o["break_force"] = shortest(*j.breakForce);
    if (j.breakTorque) o["break_torque"] = shortest(*j.breakTorque);
    put(o, "destroy_on_break", j.destroyOnBreak, d.destroyOnBreak);
    const bool hasLimit = j.type == JointType::Revolute || j.type == JointType::Prismatic;
    const bool hasMotor = hasLimit || j.type == JointType::Wheel;
    const bool hasSpring = j.type == JointType::Distance || j.type == JointType::Weld || j.type == JointType::Wheel;
    if (hasLimit) put(o, "enable_limit", j.enableLimit, d.enableLimit);
    if (j.type == JointType::Revolute) {
        put(o, "lower_angle", j.lowerAngle, d.lowerAngle);
        put(o, "upper_angle", j.upperAngle, d.upperAngle);
    }
    if (j.type == JointType::Prismatic) {
        put(o, "lower", j.lower, d.lower);
        put(o, "upper", j.upper, d.upper);
    }
    if (hasMotor) {
        put(o, "enable_motor", j.enableMotor, d.enableMotor);
        put(o, "motor_speed", j.motorSpeed, d.motorSpeed);
    }
    if (j.type == JointType::Prismatic) put(o, "max_motor_force", j.maxMotorForce, d.maxMotorForce);
    if (j.type == JointType::Revolute || j.type == JointType::Wheel)
        put(o, "max_motor_torque", j.maxMotorTorque, d.maxMotorTorque);
    if (j.type == JointType::Prismatic || j.type == JointType::Wheel) put(o, "axis", j.axis, d.axis);
    if (j.type == JointType::Distance) {
        if (j.length) o["length"] = shortest(*j.length);
        put(o, "min_length", j.minLength, d.minLength);
        put(o, "max_length", j.maxLength, d.maxLength);
    }
    if (hasSpring) {
        put(o, "hertz", j.hertz, d.hertz);
        put(o, "damping_ratio", j.dampingRatio, d.dampingRatio);
    }
    if (j.type == JointType::Motor) {
        put(o, "linear_offset", j.linearOffset, d.linearOffset);
        put(o, "angular_offset", j.angularOffset, d.angularOffset);
        put(o, "max_force", j.maxForce, d.maxForce);
        put(o, "max_torque", j.maxTorque, d.maxTorque);
    }
    if (j.type == JointType::Friction) {  // always written: the reader's default (0) is not SceneJoint's
        o["max_force"] = shortest(j.maxForce);
        o["max_torque"] = shortest(j.maxTorque);
    }
    if (j.type == JointType::Gear) {
        o["joint_a"] = j.jointA;
        o["joint_b"] = j.jointB;
    }
    if (j.type == JointType::Pulley) {
        o["ground_anchor_a"] = vec(j.groundAnchorA);
        o["ground_anchor_b"] = vec(j.groundAnchorB);
        if (j.lengthA) o["length_a"] = shortest(*j.lengthA);
        if (j.lengthB) o["length_b"] = shortest(*j.lengthB);
    }
    if (j.type == JointType::Gear || j.type == JointType::Pulley) put(o, "ratio", j.ratio, d.ratio);
    return o;
}

Json actionJson(const SceneAction& a) {
    Json o;
    o["type"] = name(a.kind);
    switch (a.kind) {
        case SceneAction::Kind::Explosion:
            o["point"] = vec(a.point.value_or(Vec2{}));
            o["radius"] = shortest(a.radius);
            o["value"] = shortest(a.scalar);
            if (a.blockedByStatic) o["blocked_by_static"] = true;
            break;
        case SceneAction::Kind::Force:
        case SceneAction::Kind::Impulse:
            o["body"] = a.body;
            o["value"] = vec(a.value);
            if (a.point) o["point"] = vec(*a.point);
            break;
        case SceneAction::Kind::Torque:
        case SceneAction::Kind::AngularImpulse:
            o["body"] = a.body;
            o["value"] = shortest(a.scalar);
            break;
    }
    o["first_step"] = a.firstStep;
    put(o, "last_step", a.lastStep, a.firstStep);
    return o;
}

// `"key": [ one compact element per line ]`
template <class T, class ToJson>
void writeList(std::string& out, const char* key, const std::vector<T>& items, ToJson toJson) {
    out += ",\n  \"" + std::string(key) + "\": [";
    for (size_t i = 0; i < items.size(); ++i) out += (i ? ",\n    " : "\n    ") + toJson(items[i], i).dump();
    out += items.empty() ? "]" : "\n  ]";
}

}  // namespace

std::string toJson(const Scene& scene) {
    Json header;
    header["format"] = sceneFormat;
    header["name"] = scene.name;
    if (!scene.description.empty()) header["description"] = scene.description;
    header["gravity"] = vec(scene.gravity);
    header["timestep"] = shortest(scene.timestep);
    header["steps"] = scene.steps;
    Json solver;
    if (scene.solver.substeps) solver["substeps"] = *scene.solver.substeps;
    solver["velocity_iterations"] = scene.solver.velocityIterations;
    solver["position_iterations"] = scene.solver.positionIterations;
    if (scene.solver.box2dSkin) solver["box2d_skin"] = true;
    header["solver"] = std::move(solver);

    std::string out = "{";
    for (auto it = header.begin(); it != header.end(); ++it)
        out += std::string(it == header.begin() ? "\n  " : ",\n  ") + Json(it.key()).dump() + ": " + it.value().dump();
    writeList(out, "bodies", scene.bodies, bodyJson);
    writeList(out, "joints", scene.joints, [](const SceneJoint& j, size_t) { return jointJson(j); });
    writeList(out, "actions", scene.actions, [](const SceneAction& a, size_t) { return actionJson(a); });
    out += "\n}\n";
    return out;
}

void saveScene(const Scene& scene, const std::string& path) {
    const std::string text = toJson(scene);
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out) throw Error(path + ": cannot open for writing");
    out << text;
    if (!out.flush()) throw Error(path + ": write failed");
}

}  // namespace perpdot
