// The field list of every struct of the world a snapshot holds (field_list.hpp); the format version
// and the math types' lists are in math_fields.hpp. The joint types' data are the exception: each
// type's list is in its joint_<type>.cpp, beside its stages (joint_type.hpp).
//
// To add a member to one of these structs: add it to the struct's list with .since(N), where N
// is formatVersion + 1, and set formatVersion (math_fields.hpp) to N (docs/reliability.md, "Adding a field"). The
// size checks below fail the build when a struct changes and nobody looked at its list. Members
// not listed are links rebuilt on reading (lists, edges, proxies), per-step scratch or userData.
#pragma once

#include <tuple>

#include "collide/collision.hpp"
#include "core/bodies/body_store.hpp"
#include "core/contacts/contact_cache.hpp"
#include "core/joints/joint_store.hpp"
#include "core/shapes/shape_store.hpp"
#include "core/snapshot/math_fields.hpp"
#include "perpdot/events.hpp"
#include "perpdot/world.hpp"

namespace perpdot {

// --- world ---

// Not listed: workerCount and the task interface (the restoring world keeps its own threads).
static_assert(reviewedLayout<WorldDef, 88>);
constexpr auto fields(const WorldDef*) {
    using D = WorldDef;
    return std::tuple{field("gravity", &D::gravity),
                      field("substeps", &D::substeps),
                      field("contactHertz", &D::contactHertz),
                      field("contactDampingRatio", &D::contactDampingRatio),
                      field("jointHertz", &D::jointHertz),
                      field("jointDampingRatio", &D::jointDampingRatio),
                      field("contactPushMaxVelocity", &D::contactPushMaxVelocity),
                      field("restitutionThreshold", &D::restitutionThreshold),
                      field("maxLinearSpeed", &D::maxLinearSpeed),
                      field("hitEventThreshold", &D::hitEventThreshold),
                      field("enableSleep", &D::enableSleep),
                      field("enableWarmStarting", &D::enableWarmStarting),
                      field("enableContinuous", &D::enableContinuous),
                      field("contactReuseDistance", &D::contactReuseDistance).since(4),
                      field("box2dSkin", &D::box2dSkin).since(4)};
}

// Not listed: generation and alive (written by the pool), userData, shapes (written as a list,
// like the body's contact list, which the contact cache's bodyLists holds).
static_assert(reviewedLayout<Body, 144>);
constexpr auto fields(const Body*) {
    return std::tuple{field("type", &Body::type),
                      field("xf", &Body::xf),
                      field("angle", &Body::angle),
                      field("localCenter", &Body::localCenter),
                      field("center", &Body::center),
                      field("v", &Body::v),
                      field("w", &Body::w),
                      field("force", &Body::force),
                      field("torque", &Body::torque),
                      field("mass", &Body::mass),
                      field("invMass", &Body::invMass),
                      field("inertia", &Body::inertia),
                      field("invInertia", &Body::invInertia),
                      field("linearDamping", &Body::linearDamping),
                      field("angularDamping", &Body::angularDamping),
                      field("gravityScale", &Body::gravityScale),
                      field("sleepTime", &Body::sleepTime),
                      field("fixedRotation", &Body::fixedRotation),
                      field("bullet", &Body::bullet),
                      field("allowSleep", &Body::allowSleep),
                      field("awake", &Body::awake),
                      field("jointCount", &Body::jointCount),
                      field("islandNext", &Body::islandNext),
                      field("enabled", &Body::enabled).since(5)};
}

constexpr auto fields(const Filter*) {
    return std::tuple{field("category", &Filter::category), field("mask", &Filter::mask), field("group", &Filter::group)};
}

// Not listed: generation, alive, userData; body, type and geometry (written before the list,
// type as the geometry's tag); proxies (written as their fat boxes).
static_assert(reviewedLayout<ShapeData, 176>);
constexpr auto fields(const ShapeData*) {
    using S = ShapeData;
    return std::tuple{field("density", &S::density),
                      field("friction", &S::friction),
                      field("restitution", &S::restitution),
                      field("rollingResistance", &S::rollingResistance),
                      field("tangentSpeed", &S::tangentSpeed),
                      field("minExtent", &S::minExtent),
                      field("maxExtent", &S::maxExtent),
                      field("sensor", &S::sensor),
                      field("enableContactEvents", &S::enableContactEvents),
                      field("enableHitEvents", &S::enableHitEvents),
                      field("enableSensorEvents", &S::enableSensorEvents),
                      field("enablePreSolveEvents", &S::enablePreSolveEvents),
                      field("filter", &S::filter),
                      field("enabled", &S::enabled).since(5)};
}

// --- contacts: any float bits (see Field::anyBits) ---

namespace collide {
constexpr auto fields(const ChildKey*) { return std::tuple{field("shape", &ChildKey::shape), field("child", &ChildKey::child)}; }
}  // namespace collide

static_assert(reviewedLayout<ContactPointState, 48>);
constexpr auto fields(const ContactPointState*) {
    using P = ContactPointState;
    return std::tuple{field("point", &P::point).anyBits(),
                      field("anchorA", &P::anchorA).anyBits(),
                      field("anchorB", &P::anchorB).anyBits(),
                      field("separation", &P::separation).anyBits(),
                      field("normalImpulse", &P::normalImpulse).anyBits(),
                      field("tangentImpulse", &P::tangentImpulse).anyBits(),
                      field("maxNormalImpulse", &P::maxNormalImpulse).anyBits(),
                      field("id", &P::id),
                      field("baseSeparation", &P::baseSeparation).anyBits().since(4)};
}

// Not listed: alive (written by the pool); pairKey, proxies, bodies, turnsA, turnsB, typeA, typeB, skin (derived
// from the child keys and the bodies' types); points (the first pointCount, written after the list); edges (written as body lists);
// reuseRotA, reuseRotB (R of the reuse angles, derived on reading).
static_assert(reviewedLayout<Contact, 232>);
constexpr auto fields(const Contact*) {
    using C = Contact;
    return std::tuple{field("touching", &C::touching),
                      field("sensor", &C::sensor),
                      field("overlapping", &C::overlapping),
                      field("a", &C::a),
                      field("b", &C::b),
                      field("friction", &C::friction).anyBits(),
                      field("restitution", &C::restitution).anyBits(),
                      field("rollingResistance", &C::rollingResistance).anyBits(),
                      field("tangentSpeed", &C::tangentSpeed).anyBits(),
                      field("rollingImpulse", &C::rollingImpulse).anyBits(),
                      field("normal", &C::normal).anyBits(),
                      field("pointCount", &C::pointCount),
                      field("restSink", &C::restSink).anyBits().since(6),
                      field("reuseValid", &C::reuseValid).since(4),
                      field("reuseOffset", &C::reuseOffset).anyBits().since(4),
                      field("reuseAngleA", &C::reuseAngleA).anyBits().since(4),
                      field("reuseAngleB", &C::reuseAngleB).anyBits().since(4)};
}

// --- joints: any float bits ---

// Not listed: generation, alive, edges (written as body lists), userData; data (its type's list,
// in the type's file: JointKind::write and read).
static_assert(reviewedLayout<Joint, 144>);
constexpr auto fields(const Joint*) {
    return std::tuple{field("type", &Joint::type),
                      field("collideConnected", &Joint::collideConnected),
                      field("bodyA", &Joint::bodyA),
                      field("bodyB", &Joint::bodyB),
                      field("localAnchorA", &Joint::localAnchorA).anyBits(),
                      field("localAnchorB", &Joint::localAnchorB).anyBits(),
                      field("referenceAngle", &Joint::referenceAngle).anyBits(),
                      field("breakForce", &Joint::breakForce).anyBits().since(4),
                      field("breakTorque", &Joint::breakTorque).anyBits().since(4),
                      field("destroyOnBreak", &Joint::destroyOnBreak).since(4)};
}

// --- events raised between steps (since format 3) ---

template <class Tag>
constexpr auto fields(const Id<Tag>*) {
    return std::tuple{field("index", &Id<Tag>::index), field("generation", &Id<Tag>::generation)};
}
constexpr auto fields(const ContactEndTouchEvent*) {
    return std::tuple{field("shapeA", &ContactEndTouchEvent::shapeA), field("shapeB", &ContactEndTouchEvent::shapeB)};
}
constexpr auto fields(const SensorEndTouchEvent*) {
    return std::tuple{field("sensorShape", &SensorEndTouchEvent::sensorShape),
                      field("visitorShape", &SensorEndTouchEvent::visitorShape)};
}

}  // namespace perpdot
