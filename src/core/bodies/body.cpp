// Bodies: creation, mass from shapes, state access, and forces at points (τ = perpDot(P - CM, F)).
#include <cmath>
#include <string>
#include <utility>

#include "core/contacts/contact_world.hpp"
#include "core/world/world_impl.hpp"

namespace perpdot {

namespace {

void requireFinite(bool ok, const char* what) {
    if (!ok) throw Error(std::string("BodyDef.") + what + " must be finite");
}

}  // namespace

World::Impl::Impl(const WorldDef& d) : def(d), joints(makeJointStore()), workers(d) {
    if (!isFinite(def.gravity)) throw Error("WorldDef.gravity must be finite");
    if (def.substeps < 1 || def.substeps > 64) throw Error("WorldDef.substeps must be 1..64");
    // Box2D v3's checks of its b2WorldDef: every rate, ratio, speed and threshold finite and >= 0
    // (a hertz of 0 is a rigid row), the speed limit > 0.
    const std::pair<float, const char*> atLeastZero[] = {
        {def.contactHertz, "contactHertz"},
        {def.contactDampingRatio, "contactDampingRatio"},
        {def.jointHertz, "jointHertz"},
        {def.jointDampingRatio, "jointDampingRatio"},
        {def.contactPushMaxVelocity, "contactPushMaxVelocity"},
        {def.restitutionThreshold, "restitutionThreshold"},
        {def.hitEventThreshold, "hitEventThreshold"},
        {def.contactReuseDistance, "contactReuseDistance"}};
    for (const auto& [value, name] : atLeastZero)
        if (!(std::isfinite(value) && value >= 0.0f)) throw Error(std::string("WorldDef.") + name + " must be finite and >= 0");
    if (!(std::isfinite(def.maxLinearSpeed) && def.maxLinearSpeed > 0.0f)) throw Error("WorldDef.maxLinearSpeed must be finite and > 0");
}

Body& World::Impl::body(BodyId id, const char* call) {
    return const_cast<Body&>(static_cast<const Impl*>(this)->body(id, call));
}

const Body& World::Impl::body(BodyId id, const char* call) const { return checkedItem(bodies, id, identity, "BodyId", call); }

// m, c and I from the shapes' area integrals, combined with the parallel-axis theorem.
void World::Impl::updateMass(int index) {
    broadphase.forgetBoxRoom(index);  // the centre of mass or the shapes changed
    Body& b = bodies[index];
    const Vec2 oldCenter = b.center;
    b.mass = b.invMass = b.inertia = b.invInertia = 0.0f;
    b.localCenter = {};
    if (b.type == BodyType::Dynamic) {
        std::vector<MassData> parts;
        for (int s : b.shapes) {
            const ShapeData& shape = shapes[s];
            if (shape.density <= 0.0f) continue;
            if (auto* c = std::get_if<Circle>(&shape.geometry)) parts.push_back(computeMass(*c, shape.density));
            if (auto* p = std::get_if<Polygon>(&shape.geometry)) parts.push_back(computeMass(*p, shape.density));
            if (auto* c = std::get_if<Capsule>(&shape.geometry)) parts.push_back(computeMass(*c, shape.density));
        }
        const MassData total = combineMass(parts);
        // A dynamic body always has positive mass, as in Box2D.
        b.mass = total.mass > 0.0f ? total.mass : 1.0f;
        b.invMass = 1.0f / b.mass;
        b.localCenter = total.center;
        if (total.rotationalInertia > 0.0f && !b.fixedRotation) {
            b.inertia = total.rotationalInertia;
            b.invInertia = 1.0f / b.inertia;
        }
    }
    b.center = transformPoint(b.xf, b.localCenter);
    // Keep the velocity of the material points: v_newCM = v + ω perp(Δc).
    b.v += b.w * perp(b.center - oldCenter);
}

BodyId World::createBody(const BodyDef& def) {
    Impl& w = *impl_;
    checkUnlocked(w.locked, "createBody");
    requireFinite(isFinite(def.position), "position");
    requireFinite(std::isfinite(def.angle), "angle");
    requireFinite(isFinite(def.linearVelocity), "linearVelocity");
    requireFinite(std::isfinite(def.angularVelocity), "angularVelocity");
    requireFinite(std::isfinite(def.gravityScale), "gravityScale");
    if (!(def.linearDamping >= 0.0f && std::isfinite(def.linearDamping))) throw Error("BodyDef.linearDamping must be finite and >= 0");
    if (!(def.angularDamping >= 0.0f && std::isfinite(def.angularDamping))) throw Error("BodyDef.angularDamping must be finite and >= 0");

    const int index = w.bodies.create();
    Body& b = w.bodies[index];
    b.type = def.type;
    b.angle = def.angle;
    b.xf = {def.position, Rot::fromAngle(def.angle)};
    b.center = def.position;
    if (def.type != BodyType::Static) {
        b.v = def.linearVelocity;
        b.w = def.angularVelocity;
    }
    b.linearDamping = def.linearDamping;
    b.angularDamping = def.angularDamping;
    b.gravityScale = def.gravityScale;
    b.fixedRotation = def.fixedRotation;
    b.bullet = def.bullet;
    b.allowSleep = def.allowSleep;
    b.awake = def.type != BodyType::Static && (def.awake || !def.allowSleep);
    b.userData = def.userData;
    w.updateMass(index);
    return w.bodyId(index);
}

void World::destroyBody(BodyId id) {
    Impl& w = *impl_;
    checkUnlocked(w.locked, "destroyBody");
    Body& b = w.body(id);
    const std::vector<std::pair<JointId, void*>> goodbyes = destroyJointsOf(w, id.index);
    wakeIsland(w.bodies, id.index);  // its island mates lose a support
    destroyContactsOf(contactWorld(w), id.index, -1);
    for (int s : b.shapes) {
        w.broadphase.destroyProxies(w.shapes, s);
        w.broadphase.collision.clearGeometry(s);
        w.shapes.destroy(s);
    }
    b.shapes.clear();
    w.bodies.destroy(id.index);
    for (const auto& [joint, userData] : goodbyes) w.jointDestroyed(joint, userData);  // Box2D's SayGoodbye
}

bool World::isValid(BodyId id) const { return isLiveHandle(impl_->bodies, id, impl_->identity); }

std::vector<BodyId> World::bodies() const {
    std::vector<BodyId> ids;
    impl_->bodies.forEachLive([&](int i, const Body&) { ids.push_back(impl_->bodyId(i)); });
    return ids;
}

int World::bodyCount() const { return impl_->bodies.size(); }

BodyType World::bodyType(BodyId id) const { return impl_->body(id).type; }
Vec2 World::position(BodyId id) const { return impl_->body(id).xf.p; }
float World::angle(BodyId id) const { return impl_->body(id).angle; }
Transform World::transform(BodyId id) const { return impl_->body(id).xf; }
Vec2 World::worldCenter(BodyId id) const { return impl_->body(id).center; }
Vec2 World::localCenter(BodyId id) const { return impl_->body(id).localCenter; }
Vec2 World::linearVelocity(BodyId id) const { return impl_->body(id).v; }
float World::angularVelocity(BodyId id) const { return impl_->body(id).w; }
float World::mass(BodyId id) const { return impl_->body(id).mass; }
float World::rotationalInertia(BodyId id) const { return impl_->body(id).inertia; }
bool World::isAwake(BodyId id) const { return impl_->body(id).awake; }
float World::gravityScale(BodyId id) const { return impl_->body(id).gravityScale; }
void* World::userData(BodyId id) const { return impl_->body(id).userData; }

Vec2 World::pointVelocity(BodyId id, Vec2 worldPoint) const {
    const Body& b = impl_->body(id);
    return perpdot::pointVelocity(b.v, b.w, worldPoint - b.center);
}

void World::setTransform(BodyId id, Vec2 position, float angle) {
    Impl& w = *impl_;
    checkUnlocked(w.locked, "setTransform");
    if (!isFinite(position) || !std::isfinite(angle)) throw Error("setTransform: position and angle must be finite");
    Body& b = w.body(id);
    b.xf = {position, Rot::fromAngle(angle)};
    b.angle = angle;
    b.center = transformPoint(b.xf, b.localCenter);
    w.broadphase.synchronizeProxies(w.shapes, w.bodies, id.index, b.xf, {});
    wakeIsland(w.bodies, id.index);
}

void World::setLinearVelocity(BodyId id, Vec2 v) {
    checkUnlocked(impl_->locked, "setLinearVelocity");
    if (!isFinite(v)) throw Error("setLinearVelocity: velocity must be finite");
    Body& b = impl_->body(id);
    if (b.type == BodyType::Static) return;
    b.v = v;
    if (dot(v, v) > 0.0f) wakeIsland(impl_->bodies, id.index);
}

void World::setAngularVelocity(BodyId id, float omega) {
    checkUnlocked(impl_->locked, "setAngularVelocity");
    if (!std::isfinite(omega)) throw Error("setAngularVelocity: ω must be finite");
    Body& b = impl_->body(id);
    if (b.type == BodyType::Static || b.fixedRotation) return;
    b.w = omega;
    if (omega != 0.0f) wakeIsland(impl_->bodies, id.index);
}

void World::setAwake(BodyId id, bool awake) {
    checkUnlocked(impl_->locked, "setAwake");
    Body& b = impl_->body(id);
    if (awake) {
        wakeIsland(impl_->bodies, id.index);
    } else if (b.type != BodyType::Static) {
        b.awake = false;
        b.v = {};
        b.w = 0.0f;
        b.sleepTime = 0.0f;
    }
}

void World::setGravityScale(BodyId id, float scale) {
    checkUnlocked(impl_->locked, "setGravityScale");
    if (!std::isfinite(scale)) throw Error("setGravityScale: scale must be finite");
    impl_->body(id).gravityScale = scale;
}

void World::setLinearDamping(BodyId id, float damping) {
    checkUnlocked(impl_->locked, "setLinearDamping");
    if (!(damping >= 0.0f && std::isfinite(damping))) throw Error("setLinearDamping: damping must be finite and >= 0");
    impl_->body(id).linearDamping = damping;
}

void World::setAngularDamping(BodyId id, float damping) {
    checkUnlocked(impl_->locked, "setAngularDamping");
    if (!(damping >= 0.0f && std::isfinite(damping))) throw Error("setAngularDamping: damping must be finite and >= 0");
    impl_->body(id).angularDamping = damping;
}

// Forces accumulate until the next step: F, and τ = perpDot(P - CM, F) about the centre of mass.
void World::applyForce(BodyId id, Vec2 force, Vec2 worldPoint) {
    checkUnlocked(impl_->locked, "applyForce");
    if (!isFinite(force) || !isFinite(worldPoint)) throw Error("applyForce: force and point must be finite");
    Body& b = impl_->body(id);
    if (b.type != BodyType::Dynamic) return;
    wakeIsland(impl_->bodies, id.index);
    b.force += force;
    b.torque += perpDot(worldPoint - b.center, force);
}

void World::applyForceToCenter(BodyId id, Vec2 force) { applyForce(id, force, impl_->body(id).center); }

void World::applyTorque(BodyId id, float torque) {
    checkUnlocked(impl_->locked, "applyTorque");
    if (!std::isfinite(torque)) throw Error("applyTorque: torque must be finite");
    Body& b = impl_->body(id);
    if (b.type != BodyType::Dynamic) return;
    wakeIsland(impl_->bodies, id.index);
    b.torque += torque;
}

// An impulse J at P changes momentum at once: Δv = J/m, Δω = perpDot(P - CM, J)/I.
void World::applyLinearImpulse(BodyId id, Vec2 impulse, Vec2 worldPoint) {
    checkUnlocked(impl_->locked, "applyLinearImpulse");
    if (!isFinite(impulse) || !isFinite(worldPoint)) throw Error("applyLinearImpulse: impulse and point must be finite");
    Body& b = impl_->body(id);
    if (b.type != BodyType::Dynamic) return;
    wakeIsland(impl_->bodies, id.index);
    b.v += b.invMass * impulse;
    b.w += b.invInertia * perpDot(worldPoint - b.center, impulse);
}

void World::applyLinearImpulseToCenter(BodyId id, Vec2 impulse) {
    applyLinearImpulse(id, impulse, impl_->body(id).center);
}

void World::applyAngularImpulse(BodyId id, float impulse) {
    checkUnlocked(impl_->locked, "applyAngularImpulse");
    if (!std::isfinite(impulse)) throw Error("applyAngularImpulse: impulse must be finite");
    Body& b = impl_->body(id);
    if (b.type != BodyType::Dynamic) return;
    wakeIsland(impl_->bodies, id.index);
    b.w += b.invInertia * impulse;
}

}  // namespace perpdot
