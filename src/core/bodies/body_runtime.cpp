// Bodies changed at run time, as Box2D's b2Body setters change them: type, fixed rotation, bullet,
// sleep, mass properties, user data, the kinematic target pose; and each body's contacts and joints.
#include <cmath>
#include <string>

#include "core/contacts/contact_world.hpp"
#include "core/joints/joint_store.hpp"
#include "core/world/events.hpp"
#include "core/world/world_impl.hpp"

namespace perpdot {

// A body changes kind: its contacts end (the pairs are found again, with the new kind's rules,
// from the next step), its proxies move to the tree of the new kind, its mass comes from its
// shapes, and it wakes (made static, it stops).
void World::setType(BodyId id, BodyType type) {
    Impl& w = *impl_;
    checkUnlocked(w.locked, "World::setType");
    Body& b = w.body(id);
    if (b.type == type) return;
    wakeIsland(w.bodies, id.index);  // leaves the island ring it slept in
    destroyContactsOf(contactWorld(w), id.index, -1);
    for (int s : b.shapes) w.broadphase.destroyProxies(w.shapes, s);
    b.type = type;
    for (int s : b.shapes) w.broadphase.createProxies(w.shapes, w.bodies, s);
    b.force = {};
    b.torque = 0.0f;
    if (type == BodyType::Static) {
        b.v = {};
        b.w = 0.0f;
    }
    w.updateMass(id.index);
    b.sleepTime = 0.0f;
    b.awake = type != BodyType::Static && b.enabled;
}

void World::setFixedRotation(BodyId id, bool fixedRotation) {
    Impl& w = *impl_;
    checkUnlocked(w.locked, "World::setFixedRotation");
    Body& b = w.body(id);
    b.fixedRotation = fixedRotation;
    if (fixedRotation) b.w = 0.0f;
    w.updateMass(id.index);
    wakeIsland(w.bodies, id.index);
}

bool World::isFixedRotation(BodyId id) const { return impl_->body(id).fixedRotation; }

void World::setBullet(BodyId id, bool bullet) {
    checkUnlocked(impl_->locked, "World::setBullet");
    impl_->body(id).bullet = bullet;
}

bool World::isBullet(BodyId id) const { return impl_->body(id).bullet; }

void World::setAllowSleep(BodyId id, bool allowSleep) {
    checkUnlocked(impl_->locked, "World::setAllowSleep");
    impl_->body(id).allowSleep = allowSleep;
    if (!allowSleep) wakeIsland(impl_->bodies, id.index);
}

bool World::allowsSleep(BodyId id) const { return impl_->body(id).allowSleep; }

MassData World::massData(BodyId id) const {
    const Body& b = impl_->body(id);
    return {b.mass, b.localCenter, b.inertia};
}

// Box2D's SetMassData: m (≤ 0: 1 kg), centre and I about it; the material points keep their
// velocity: v_newCM = v + ω perp(Δc).
void World::setMassData(BodyId id, const MassData& m) {
    Impl& w = *impl_;
    checkUnlocked(w.locked, "World::setMassData");
    Body& b = w.body(id);
    if (!std::isfinite(m.mass) || !isFinite(m.center) || !std::isfinite(m.rotationalInertia) || m.mass < 0.0f ||
        m.rotationalInertia < 0.0f)
        throw Error("World::setMassData: mass and rotational inertia must be finite and >= 0, the centre finite");
    if (b.type != BodyType::Dynamic) return;
    w.broadphase.forgetBoxRoom(id.index);
    b.mass = m.mass > 0.0f ? m.mass : 1.0f;
    b.invMass = 1.0f / b.mass;
    b.inertia = b.invInertia = 0.0f;
    if (m.rotationalInertia > 0.0f && !b.fixedRotation) {
        b.inertia = m.rotationalInertia;
        b.invInertia = 1.0f / b.inertia;
    }
    const Vec2 oldCenter = b.center;
    b.localCenter = m.center;
    b.center = transformPoint(b.xf, b.localCenter);
    b.v += b.w * perp(b.center - oldCenter);
    wakeIsland(w.bodies, id.index);
}

void World::resetMassData(BodyId id) {
    checkUnlocked(impl_->locked, "World::resetMassData");
    impl_->body(id);
    impl_->updateMass(id.index);
}

std::vector<ContactData> World::bodyContacts(BodyId id) const {
    const Impl& w = *impl_;
    w.body(id);
    std::vector<ContactData> out;
    const ContactCache& cache = w.contactCache;
    cache.bodyLists.forEach(cache.contacts, id.index, [&](int index, int) {
        if (cache.contacts[index].touching) out.push_back(contactData(w.shapes, w.identity, cache.contacts[index]));
    });
    return out;
}

std::vector<JointId> World::bodyJoints(BodyId id) const {
    const Impl& w = *impl_;
    w.body(id);
    std::vector<JointId> out;
    const JointStore& store = *w.joints;
    store.bodyLists.forEach(store.joints, id.index, [&](int index, int) { out.push_back(jointId(w, store.joints[index])); });
    return out;
}

// Box2D v3's target transform: the velocity that carries the centre of mass, and the angle, to the
// target in one step of h: v = (c_target − c)/h, ω = (θ_target − θ)/h.
void World::setTargetTransform(BodyId id, Vec2 position, float angle, float timeStep) {
    Impl& w = *impl_;
    checkUnlocked(w.locked, "World::setTargetTransform");
    if (!isFinite(position) || !std::isfinite(angle)) throw Error("World::setTargetTransform: position and angle must be finite");
    if (!(timeStep > 0.0f) || !std::isfinite(timeStep))
        throw Error("World::setTargetTransform: the time step must be finite and > 0, not " + std::to_string(timeStep));
    Body& b = w.body(id);
    if (b.type == BodyType::Static) return;
    const Vec2 targetCenter = position + rotate(Rot::fromAngle(angle), b.localCenter);
    const float invH = 1.0f / timeStep;
    b.v = invH * (targetCenter - b.center);
    b.w = b.fixedRotation ? 0.0f : invH * (angle - b.angle);
    wakeIsland(w.bodies, id.index);
}

void World::setUserData(BodyId id, void* userData) { impl_->body(id).userData = userData; }

// Out of the simulation: no contacts, no proxies, not stepped (it is not awake, and wake() passes
// it by), its joints not solved; its pose and velocity wait for it to come back.
void World::setEnabled(BodyId id, bool enabled) {
    Impl& w = *impl_;
    checkUnlocked(w.locked, "World::setEnabled");
    Body& b = w.body(id);
    if (b.enabled == enabled) return;
    if (enabled) {
        b.enabled = true;
        for (int s : b.shapes) w.broadphase.createProxies(w.shapes, w.bodies, s);
        wakeIsland(w.bodies, id.index);
        return;
    }
    wakeIsland(w.bodies, id.index);  // leaves the island ring it slept in; its joint partners lose it
    for (JointId joint : bodyJoints(id)) {
        const BodyId a = jointBodyA(joint), other = a == id ? jointBodyB(joint) : a;
        wakeIsland(w.bodies, other.index);
    }
    destroyContactsOf(contactWorld(w), id.index, -1);
    for (int s : b.shapes) w.broadphase.destroyProxies(w.shapes, s);
    b.enabled = false;
    b.awake = false;
    b.sleepTime = 0.0f;
}

bool World::isEnabled(BodyId id) const { return impl_->body(id).enabled; }

}  // namespace perpdot
