// A Scene built into perpdot's World, and the scene's scripted actions applied step by step.
#include "scene/build_world.hpp"

#include <cmath>
#include <limits>
#include <string>
#include <unordered_map>
#include <utility>

#include "perpdot/error.hpp"

namespace perpdot {
namespace {

BodyDef bodyDef(const SceneBody& b) {
    return {.type = b.type,
            .position = b.position,
            .angle = b.angle,
            .linearVelocity = b.linearVelocity,
            .angularVelocity = b.angularVelocity,
            .linearDamping = b.linearDamping,
            .angularDamping = b.angularDamping,
            .gravityScale = b.gravityScale,
            .fixedRotation = b.fixedRotation,
            .bullet = b.bullet,
            .allowSleep = b.allowSleep,
            .awake = b.awake};
}

ShapeId createShape(World& world, BodyId body, const SceneShape& s) {
    const ShapeDef def{.density = s.density, .friction = s.friction, .restitution = s.restitution,
                       .sensor = s.sensor, .filter = s.filter};
    switch (s.kind) {
        case SceneShape::Kind::Circle: return world.createShape(body, def, Circle{s.center, s.radius});
        case SceneShape::Kind::Box:
            return world.createShape(body, def, makeBox(s.halfExtents.x, s.halfExtents.y, s.center, s.angle));
        case SceneShape::Kind::Polygon: return world.createShape(body, def, makePolygon(s.vertices, s.radius));
        case SceneShape::Kind::Segment: return world.createShape(body, def, Segment{s.v1, s.v2});
        case SceneShape::Kind::Capsule: return world.createShape(body, def, Capsule{s.v1, s.v2, s.radius});
        case SceneShape::Kind::Chain: break;
    }
    return world.createShape(body, def, Chain{s.vertices, s.loop, s.solid, s.prevVertex, s.nextVertex});
}

// The joint's bodies, their local anchors and reference angle, resolved from the scene's world data.
struct JointFrame {
    BodyId bodyA{}, bodyB{};
    Transform frameA{}, frameB{};
    Vec2 localAnchorA{}, localAnchorB{};
    float referenceAngle = 0.0f;  // θB - θA at creation: the joint's zero angle
};

JointFrame jointFrame(const SceneJoint& j, const World& world, const Scene& scene, const std::vector<BodyId>& bodies,
                      const std::unordered_map<std::string, size_t>& index) {
    const auto body = [&](const std::string& name) -> size_t {
        const auto it = index.find(name);
        if (it == index.end()) throw Error("no body named \"" + name + "\"");
        return it->second;
    };
    const size_t a = body(j.bodyA), b = body(j.bodyB);
    JointFrame f{.bodyA = bodies[a], .bodyB = bodies[b]};
    f.frameA = world.transform(f.bodyA);
    f.frameB = world.transform(f.bodyB);
    if (j.anchor) {
        f.localAnchorA = invTransformPoint(f.frameA, *j.anchor);
        f.localAnchorB = invTransformPoint(f.frameB, j.anchorB.value_or(*j.anchor));
    } else {
        f.localAnchorA = j.localAnchorA.value_or(Vec2{});
        f.localAnchorB = j.localAnchorB.value_or(Vec2{});
    }
    f.referenceAngle = scene.bodies[b].angle - scene.bodies[a].angle;
    return f;
}

// `built`: the scene's joints created so far (a gear names two of them).
JointId createJoint(World& world, const SceneJoint& j, const JointFrame& f, const std::vector<JointId>& built) {
    const Vec2 localAxisA = invRotate(f.frameA.q, normalize(j.axis));
    switch (j.type) {
        case JointType::Revolute:
            return world.createJoint(RevoluteJointDef{
                .bodyA = f.bodyA, .bodyB = f.bodyB, .localAnchorA = f.localAnchorA, .localAnchorB = f.localAnchorB,
                .referenceAngle = f.referenceAngle, .enableLimit = j.enableLimit, .lowerAngle = j.lowerAngle,
                .upperAngle = j.upperAngle, .enableMotor = j.enableMotor, .motorSpeed = j.motorSpeed,
                .maxMotorTorque = j.maxMotorTorque, .collideConnected = j.collideConnected});
        case JointType::Prismatic:
            return world.createJoint(PrismaticJointDef{
                .bodyA = f.bodyA, .bodyB = f.bodyB, .localAnchorA = f.localAnchorA, .localAnchorB = f.localAnchorB,
                .localAxisA = localAxisA, .referenceAngle = f.referenceAngle, .enableLimit = j.enableLimit,
                .lower = j.lower, .upper = j.upper, .enableMotor = j.enableMotor, .motorSpeed = j.motorSpeed,
                .maxMotorForce = j.maxMotorForce, .collideConnected = j.collideConnected});
        case JointType::Distance: {
            const Vec2 worldA = transformPoint(f.frameA, f.localAnchorA), worldB = transformPoint(f.frameB, f.localAnchorB);
            return world.createJoint(DistanceJointDef{
                .bodyA = f.bodyA, .bodyB = f.bodyB, .localAnchorA = f.localAnchorA, .localAnchorB = f.localAnchorB,
                .length = j.length.value_or(distance(worldA, worldB)), .minLength = j.minLength,
                .maxLength = j.maxLength, .hertz = j.hertz, .dampingRatio = j.dampingRatio,
                .collideConnected = j.collideConnected});
        }
        case JointType::Weld:
            return world.createJoint(WeldJointDef{
                .bodyA = f.bodyA, .bodyB = f.bodyB, .localAnchorA = f.localAnchorA, .localAnchorB = f.localAnchorB,
                .referenceAngle = f.referenceAngle, .hertz = j.hertz, .dampingRatio = j.dampingRatio,
                .collideConnected = j.collideConnected});
        case JointType::Wheel:
            return world.createJoint(WheelJointDef{
                .bodyA = f.bodyA, .bodyB = f.bodyB, .localAnchorA = f.localAnchorA, .localAnchorB = f.localAnchorB,
                .localAxisA = localAxisA, .hertz = j.hertz, .dampingRatio = j.dampingRatio,
                .enableMotor = j.enableMotor, .motorSpeed = j.motorSpeed, .maxMotorTorque = j.maxMotorTorque,
                .collideConnected = j.collideConnected});
        case JointType::Motor:
            return world.createJoint(MotorJointDef{
                .bodyA = f.bodyA, .bodyB = f.bodyB, .linearOffset = j.linearOffset,
                .angularOffset = j.angularOffset, .maxForce = j.maxForce, .maxTorque = j.maxTorque,
                .collideConnected = j.collideConnected});
        case JointType::Friction:
            return world.createJoint(FrictionJointDef{
                .bodyA = f.bodyA, .bodyB = f.bodyB, .localAnchorA = f.localAnchorA, .localAnchorB = f.localAnchorB,
                .maxForce = j.maxForce, .maxTorque = j.maxTorque, .collideConnected = j.collideConnected});
        case JointType::Gear: {
            const auto geared = [&](int index) {
                if (index < 0 || index >= static_cast<int>(built.size())) throw Error("gear: no earlier joint " + std::to_string(index));
                return built[index];
            };
            return world.createJoint(GearJointDef{.jointA = geared(j.jointA), .jointB = geared(j.jointB), .ratio = j.ratio,
                                                  .collideConnected = j.collideConnected});
        }
        case JointType::Pulley: {
            const Vec2 worldA = transformPoint(f.frameA, f.localAnchorA), worldB = transformPoint(f.frameB, f.localAnchorB);
            return world.createJoint(PulleyJointDef{
                .bodyA = f.bodyA, .bodyB = f.bodyB, .groundAnchorA = j.groundAnchorA, .groundAnchorB = j.groundAnchorB,
                .localAnchorA = f.localAnchorA, .localAnchorB = f.localAnchorB,
                .lengthA = j.lengthA.value_or(distance(j.groundAnchorA, worldA)),
                .lengthB = j.lengthB.value_or(distance(j.groundAnchorB, worldB)), .ratio = j.ratio,
                .collideConnected = j.collideConnected});
        }
        default: break;  // mouse joints, and types the format does not have
    }
    throw Error("mouse joints cannot be part of a scene, nor joints of a type the format does not have");
}

std::string element(const char* list, size_t i) { return std::string(list) + "[" + std::to_string(i) + "]"; }

}  // namespace

SceneBodies addToWorld(World& world, const Scene& scene) {
    SceneBodies built;
    std::unordered_map<std::string, size_t> index;
    for (size_t i = 0; i < scene.bodies.size(); ++i) {
        const SceneBody& b = scene.bodies[i];
        std::string path = element("bodies", i);
        try {
            if (!index.emplace(b.name, i).second) throw Error("duplicate body name \"" + b.name + "\"");
            built.bodies.push_back(world.createBody(bodyDef(b)));
            for (size_t k = 0; k < b.shapes.size(); ++k) {
                path = element("bodies", i) + "." + element("shapes", k);
                const ShapeId shape = createShape(world, built.bodies.back(), b.shapes[k]);
                if (!b.shapes[k].enabled) world.setEnabled(shape, false);
            }
            if (b.massData) {
                path = element("bodies", i) + ".mass_data";
                world.setMassData(built.bodies.back(), {b.massData->mass, b.massData->center, b.massData->rotationalInertia});
            }
            if (!b.enabled) world.setEnabled(built.bodies.back(), false);
        } catch (const Error& e) {
            throw Error(path + ": " + e.what());
        }
    }
    for (size_t i = 0; i < scene.joints.size(); ++i) {
        try {
            const SceneJoint& j = scene.joints[i];
            built.joints.push_back(createJoint(world, j, jointFrame(j, world, scene, built.bodies, index), built.joints));
            if (j.breakForce || j.breakTorque) {
                constexpr float never = std::numeric_limits<float>::infinity();
                world.setJointBreakLimits(built.joints.back(), j.breakForce.value_or(never), j.breakTorque.value_or(never), j.destroyOnBreak);
            }
        } catch (const Error& e) {
            throw Error(element("joints", i) + ": " + e.what());
        }
    }
    for (size_t i = 0; i < scene.actions.size(); ++i) {
        const SceneAction& a = scene.actions[i];
        if (a.kind == SceneAction::Kind::Explosion) {
            // World::explode checks radius and impulse when it runs; the centre is the scene's to give.
            if (!a.point || !isFinite(*a.point)) throw Error(element("actions", i) + ".point: an explosion needs a finite centre");
            if (!(a.radius > 0.0f) || !std::isfinite(a.radius)) throw Error(element("actions", i) + ".radius: must be > 0 and finite");
            if (!(a.scalar >= 0.0f) || !std::isfinite(a.scalar)) throw Error(element("actions", i) + ".value: must be >= 0 and finite");
        } else if (!index.contains(a.body)) {
            throw Error(element("actions", i) + ".body: no body named \"" + a.body + "\"");
        }
    }
    return built;
}

SceneWorld buildWorld(const Scene& scene, int workerCount) {
    WorldDef def{.gravity = scene.gravity, .enableSleep = scene.enableSleep, .workerCount = workerCount};
    if (scene.solver.substeps) def.substeps = *scene.solver.substeps;
    def.box2dSkin = scene.solver.box2dSkin;
    SceneWorld built{.world = World(def), .scene = scene};
    SceneBodies added = addToWorld(built.world, scene);
    built.bodies = std::move(added.bodies);
    built.joints = std::move(added.joints);
    return built;
}

void SceneWorld::applyActions(int step) {
    for (const SceneAction& a : scene.actions) {
        if (step < a.firstStep || step > a.lastStep) continue;
        if (a.kind == SceneAction::Kind::Explosion) {
            world.explode({.position = *a.point, .radius = a.radius, .impulse = a.scalar, .blockedByStatic = a.blockedByStatic});
            continue;
        }
        size_t i = 0;
        while (scene.bodies[i].name != a.body) ++i;  // buildWorld checked that the body exists
        const BodyId body = bodies[i];
        const Vec2 point = a.point.value_or(world.worldCenter(body));
        switch (a.kind) {
            case SceneAction::Kind::Force: world.applyForce(body, a.value, point); break;
            case SceneAction::Kind::Impulse: world.applyLinearImpulse(body, a.value, point); break;
            case SceneAction::Kind::Torque: world.applyTorque(body, a.scalar); break;
            case SceneAction::Kind::AngularImpulse: world.applyAngularImpulse(body, a.scalar); break;
            case SceneAction::Kind::Explosion: break;  // above
        }
    }
}

void SceneWorld::step() {
    if (beforeStep) beforeStep(*this);
    applyActions(stepIndex);
    world.step(scene.timestep);
    ++stepIndex;
}

}  // namespace perpdot
