// The World's joint calls at run time: limits, motors, springs, lengths and force bounds written
// into the joint's type data (which snapshots carry: they survive restore bit for bit), the joint
// coordinates read from the bodies' motion, and user data.
#include <cmath>
#include <string>

#include "core/joints/joint_distance.hpp"
#include "core/joints/joint_motor.hpp"
#include "core/joints/joint_mouse.hpp"
#include "core/joints/joint_prismatic.hpp"
#include "core/joints/joint_revolute.hpp"
#include "core/joints/joint_weld.hpp"
#include "core/joints/joint_wheel.hpp"
#include "core/bodies/body_store.hpp"
#include "core/world/handle_check.hpp"

namespace perpdot {

namespace {

[[noreturn]] void wrongType(const char* call, const char* types) {
    throw Error(std::string("World::") + call + ": the joint is not a " + types + " joint");
}

void requireAtLeastZero(float value, const char* call, const char* what) {
    if (!(value >= 0.0f) || !std::isfinite(value))
        throw Error(std::string("World::") + call + ": " + what + " must be finite and >= 0");
}

// The live joint of `id` for a setter: the world must not be stepping; its bodies wake.
Joint& jointToChange(World::Impl& world, JointId id, const char* call) {
    const JointWorld w = jointWorld(world);
    checkUnlocked(w.locked, call);
    Joint& j = checkedJoint(world, id);
    wakeIsland(w.bodies, j.bodyA);
    wakeIsland(w.bodies, j.bodyB);
    return j;
}

// The fields several joint types share, by type: null where the type has none.
struct LimitFields {
    bool* enable = nullptr;
    float *lower = nullptr, *upper = nullptr, *lowerImpulse = nullptr, *upperImpulse = nullptr;
};
LimitFields limitsOf(Joint& j) {
    if (j.type == JointType::Revolute) {
        RevoluteJoint& r = j.data.as<RevoluteJoint>();
        return {&r.enableLimit, &r.lowerAngle, &r.upperAngle, &r.lowerImpulse, &r.upperImpulse};
    }
    if (j.type == JointType::Prismatic) {
        PrismaticJoint& p = j.data.as<PrismaticJoint>();
        return {&p.enableLimit, &p.lower, &p.upper, &p.lowerImpulse, &p.upperImpulse};
    }
    return {};
}

struct MotorFields {
    bool* enable = nullptr;
    float *speed = nullptr, *maxTorque = nullptr, *maxForce = nullptr, *impulse = nullptr;
};
MotorFields motorOf(Joint& j) {
    switch (j.type) {
        case JointType::Revolute: {
            RevoluteJoint& r = j.data.as<RevoluteJoint>();
            return {&r.enableMotor, &r.motorSpeed, &r.maxMotorTorque, nullptr, &r.motorImpulse};
        }
        case JointType::Wheel: {
            WheelJoint& s = j.data.as<WheelJoint>();
            return {&s.enableMotor, &s.motorSpeed, &s.maxMotorTorque, nullptr, &s.motorImpulse};
        }
        case JointType::Prismatic: {
            PrismaticJoint& p = j.data.as<PrismaticJoint>();
            return {&p.enableMotor, &p.motorSpeed, nullptr, &p.maxMotorForce, &p.motorImpulse};
        }
        default: return {};
    }
}

struct SpringFields {
    float *hertz = nullptr, *dampingRatio = nullptr;
};
SpringFields springOf(Joint& j) {
    switch (j.type) {
        case JointType::Wheel: return {&j.data.as<WheelJoint>().hertz, &j.data.as<WheelJoint>().dampingRatio};
        case JointType::Distance: return {&j.data.as<DistanceJoint>().hertz, &j.data.as<DistanceJoint>().dampingRatio};
        case JointType::Weld: return {&j.data.as<WeldJoint>().hertz, &j.data.as<WeldJoint>().dampingRatio};
        case JointType::Mouse: return {&j.data.as<MouseJoint>().hertz, &j.data.as<MouseJoint>().dampingRatio};
        default: return {};
    }
}

// Motor and friction joints share their data (joint_motor.cpp); the mouse joint has a force bound too.
struct BoundFields {
    float *maxForce = nullptr, *maxTorque = nullptr;
};
BoundFields boundsOf(Joint& j) {
    if (j.type == JointType::Motor || j.type == JointType::Friction)
        return {&j.data.as<MotorJoint>().maxForce, &j.data.as<MotorJoint>().maxTorque};
    if (j.type == JointType::Mouse) return {&j.data.as<MouseJoint>().maxForce, nullptr};
    return {};
}

DistanceJoint& distanceOf(Joint& j, const char* call) {
    if (j.type != JointType::Distance) wrongType(call, "distance");
    return j.data.as<DistanceJoint>();
}

// A read-only view of a joint, for the getters (the field helpers above take a mutable joint).
Joint& joint(const World::Impl& w, JointId id) { return checkedJoint(w, id); }

template <class T>
T* require(T* field, const char* call, const char* types) {
    if (field == nullptr) wrongType(call, types);
    return field;
}

// The world axis of a prismatic or wheel joint (A's local axis turned with A), and its anchors.
struct AxisFrame {
    Vec2 axis, pA, pB;
};
AxisFrame axisFrame(const JointWorld& w, const Joint& j, const char* call) {
    Vec2 localAxis;
    if (j.type == JointType::Prismatic) localAxis = j.data.as<PrismaticJoint>().localAxisA;
    else if (j.type == JointType::Wheel) localAxis = j.data.as<WheelJoint>().localAxisA;
    else wrongType(call, "prismatic or wheel");
    const Transform& xfA = w.bodies[j.bodyA].xf;
    return {rotate(xfA.q, localAxis), transformPoint(xfA, j.localAnchorA), transformPoint(w.bodies[j.bodyB].xf, j.localAnchorB)};
}

// v + ω perp(P − c) of a body at world point P.
Vec2 velocityAt(const Body& b, Vec2 point) { return b.v + b.w * perp(point - b.center); }

}  // namespace

// --- limits ---

void World::enableLimit(JointId id, bool enable) {
    Joint& j = jointToChange(*impl_, id, "enableLimit");
    const LimitFields f = limitsOf(j);
    if (!require(f.enable, "enableLimit", "revolute or prismatic")) return;
    if (*f.enable != enable) *f.lowerImpulse = *f.upperImpulse = 0.0f;
    *f.enable = enable;
}

bool World::isLimitEnabled(JointId id) const { return *require(limitsOf(joint(*impl_, id)).enable, "isLimitEnabled", "revolute or prismatic"); }

void World::setLimits(JointId id, float lower, float upper) {
    if (!std::isfinite(lower) || !std::isfinite(upper) || lower > upper)
        throw Error("World::setLimits: need finite lower <= upper");
    const LimitFields f = limitsOf(jointToChange(*impl_, id, "setLimits"));
    *require(f.lower, "setLimits", "revolute or prismatic") = lower;
    *f.upper = upper;
}

float World::lowerLimit(JointId id) const { return *require(limitsOf(joint(*impl_, id)).lower, "lowerLimit", "revolute or prismatic"); }
float World::upperLimit(JointId id) const { return *require(limitsOf(joint(*impl_, id)).upper, "upperLimit", "revolute or prismatic"); }

// --- motors ---

void World::enableMotor(JointId id, bool enable) {
    const MotorFields f = motorOf(jointToChange(*impl_, id, "enableMotor"));
    if (*require(f.enable, "enableMotor", "revolute, prismatic or wheel") != enable) *f.impulse = 0.0f;
    *f.enable = enable;
}

bool World::isMotorEnabled(JointId id) const {
    return *require(motorOf(joint(*impl_, id)).enable, "isMotorEnabled", "revolute, prismatic or wheel");
}

float World::motorSpeed(JointId id) const { return *require(motorOf(joint(*impl_, id)).speed, "motorSpeed", "revolute, prismatic or wheel"); }

void World::setMaxMotorTorque(JointId id, float torque) {
    requireAtLeastZero(torque, "setMaxMotorTorque", "torque");
    *require(motorOf(jointToChange(*impl_, id, "setMaxMotorTorque")).maxTorque, "setMaxMotorTorque", "revolute or wheel") = torque;
}

float World::maxMotorTorque(JointId id) const { return *require(motorOf(joint(*impl_, id)).maxTorque, "maxMotorTorque", "revolute or wheel"); }

void World::setMaxMotorForce(JointId id, float force) {
    requireAtLeastZero(force, "setMaxMotorForce", "force");
    *require(motorOf(jointToChange(*impl_, id, "setMaxMotorForce")).maxForce, "setMaxMotorForce", "prismatic") = force;
}

float World::maxMotorForce(JointId id) const { return *require(motorOf(joint(*impl_, id)).maxForce, "maxMotorForce", "prismatic"); }

// The motor's accumulated impulse is what each substep applied: / hs (jointReactionForce).
float World::motorTorque(JointId id) const {
    Joint& j = joint(*impl_, id);
    require(motorOf(j).maxTorque, "motorTorque", "revolute or wheel");
    return jointWorld(*impl_).joints.invHs * *motorOf(j).impulse;
}

float World::motorForce(JointId id) const {
    Joint& j = joint(*impl_, id);
    require(motorOf(j).maxForce, "motorForce", "prismatic");
    return jointWorld(*impl_).joints.invHs * *motorOf(j).impulse;
}

// --- springs ---

void World::setSpringHertz(JointId id, float hertz) {
    requireAtLeastZero(hertz, "setSpringHertz", "hertz");
    Joint& j = jointToChange(*impl_, id, "setSpringHertz");
    if (j.type == JointType::Mouse && hertz == 0.0f) throw Error("World::setSpringHertz: a mouse joint needs hertz > 0");
    *require(springOf(j).hertz, "setSpringHertz", "wheel, distance, weld or mouse") = hertz;
}

void World::setSpringDampingRatio(JointId id, float dampingRatio) {
    requireAtLeastZero(dampingRatio, "setSpringDampingRatio", "dampingRatio");
    *require(springOf(jointToChange(*impl_, id, "setSpringDampingRatio")).dampingRatio, "setSpringDampingRatio",
             "wheel, distance, weld or mouse") = dampingRatio;
}

float World::springHertz(JointId id) const { return *require(springOf(joint(*impl_, id)).hertz, "springHertz", "wheel, distance, weld or mouse"); }
float World::springDampingRatio(JointId id) const {
    return *require(springOf(joint(*impl_, id)).dampingRatio, "springDampingRatio", "wheel, distance, weld or mouse");
}

// --- distance joint lengths ---

void World::setLength(JointId id, float length) {
    if (!(length > 0.0f) || !std::isfinite(length)) throw Error("World::setLength: length must be finite and > 0");
    distanceOf(jointToChange(*impl_, id, "setLength"), "setLength").length = length;
}

void World::setLengthRange(JointId id, float minLength, float maxLength) {
    if (!std::isfinite(minLength) || std::isnan(maxLength) || minLength < 0.0f || minLength > maxLength)
        throw Error("World::setLengthRange: need finite 0 <= minLength <= maxLength");
    DistanceJoint& s = distanceOf(jointToChange(*impl_, id, "setLengthRange"), "setLengthRange");
    s.minLength = minLength;
    s.maxLength = maxLength;
}

float World::restLength(JointId id) const { return distanceOf(joint(*impl_, id), "restLength").length; }
float World::minLength(JointId id) const { return distanceOf(joint(*impl_, id), "minLength").minLength; }
float World::maxLength(JointId id) const { return distanceOf(joint(*impl_, id), "maxLength").maxLength; }

float World::currentLength(JointId id) const {
    distanceOf(joint(*impl_, id), "currentLength");
    return distance(jointAnchorA(id), jointAnchorB(id));
}

// --- motor, friction and mouse joints' bounds; the motor joint's target ---

void World::setMaxForce(JointId id, float force) {
    requireAtLeastZero(force, "setMaxForce", "force");
    *require(boundsOf(jointToChange(*impl_, id, "setMaxForce")).maxForce, "setMaxForce", "motor, friction or mouse") = force;
}

void World::setMaxTorque(JointId id, float torque) {
    requireAtLeastZero(torque, "setMaxTorque", "torque");
    *require(boundsOf(jointToChange(*impl_, id, "setMaxTorque")).maxTorque, "setMaxTorque", "motor or friction") = torque;
}

float World::maxForce(JointId id) const { return *require(boundsOf(joint(*impl_, id)).maxForce, "maxForce", "motor, friction or mouse"); }
float World::maxTorque(JointId id) const { return *require(boundsOf(joint(*impl_, id)).maxTorque, "maxTorque", "motor or friction"); }

// The motor joint keeps its linear offset as anchor A and its angular offset as the reference angle.
void World::setLinearOffset(JointId id, Vec2 offset) {
    requireFinite(isFinite(offset), "World::setLinearOffset: offset");
    Joint& j = jointToChange(*impl_, id, "setLinearOffset");
    if (j.type != JointType::Motor) wrongType("setLinearOffset", "motor");
    j.localAnchorA = offset;
}

void World::setAngularOffset(JointId id, float offset) {
    requireFinite(std::isfinite(offset), "World::setAngularOffset: offset");
    Joint& j = jointToChange(*impl_, id, "setAngularOffset");
    if (j.type != JointType::Motor) wrongType("setAngularOffset", "motor");
    j.referenceAngle = offset;
}

// --- joint coordinates ---

float World::jointAngle(JointId id) const {
    const Joint& j = joint(*impl_, id);
    if (j.type != JointType::Revolute && j.type != JointType::Weld && j.type != JointType::Prismatic)
        wrongType("jointAngle", "revolute, weld or prismatic");
    const Pool<Body>& bodies = jointWorld(*impl_).bodies;
    return bodies[j.bodyB].angle - bodies[j.bodyA].angle - j.referenceAngle;
}

float World::jointAngularSpeed(JointId id) const {
    const Joint& j = joint(*impl_, id);
    if (j.type != JointType::Revolute && j.type != JointType::Weld && j.type != JointType::Prismatic && j.type != JointType::Wheel)
        wrongType("jointAngularSpeed", "revolute, weld, prismatic or wheel");
    const Pool<Body>& bodies = jointWorld(*impl_).bodies;
    return bodies[j.bodyB].w - bodies[j.bodyA].w;
}

float World::jointTranslation(JointId id) const {
    const AxisFrame f = axisFrame(jointWorld(*impl_), joint(*impl_, id), "jointTranslation");
    return dot(f.pB - f.pA, f.axis);
}

// d/dt [(pB − pA)·axis] = (vB(pB) − vA(pA))·axis + (pB − pA)·(ωA perp(axis)).
float World::jointLinearSpeed(JointId id) const {
    const Joint& j = joint(*impl_, id);
    const JointWorld w = jointWorld(*impl_);
    const AxisFrame f = axisFrame(w, j, "jointLinearSpeed");
    const Body& a = w.bodies[j.bodyA];
    const Body& b = w.bodies[j.bodyB];
    return dot(velocityAt(b, f.pB) - velocityAt(a, f.pA), f.axis) + dot(f.pB - f.pA, a.w * perp(f.axis));
}

// --- user data ---

void* World::userData(JointId id) const { return joint(*impl_, id).userData; }

void World::setUserData(JointId id, void* userData) { checkedJoint(*impl_, id).userData = userData; }

}  // namespace perpdot
