// The persistent contact cache: new pairs from moved proxies, manifolds from the narrowphase,
// and warm-start impulses carried from one step to the next by Box2D's feature ids.
#include <algorithm>
#include <cmath>

#include "core/world_impl.hpp"

namespace perpdot {

namespace {

uint64_t pairKey(int proxyA, int proxyB) {
    const auto lo = static_cast<uint32_t>(std::min(proxyA, proxyB));
    const auto hi = static_cast<uint32_t>(std::max(proxyA, proxyB));
    return (static_cast<uint64_t>(lo) << 32) | hi;
}

// Box2D's mixing rules, so cross-checks compare like with like.
float mixFriction(float a, float b) { return std::sqrt(a * b); }
float mixRestitution(float a, float b) { return std::max(a, b); }

void linkEdge(World::Impl& w, int contact, int side, int bodyIndex) {
    const int key = 2 * contact + side;
    Body& b = w.bodies[bodyIndex];
    ContactEdge& e = w.contacts[contact].edges[side];
    e.prev = -1;
    e.next = b.contactHead;
    if (b.contactHead >= 0) w.contacts[b.contactHead >> 1].edges[b.contactHead & 1].prev = key;
    b.contactHead = key;
}

void unlinkEdge(World::Impl& w, int contact, int side, int bodyIndex) {
    ContactEdge& e = w.contacts[contact].edges[side];
    if (e.prev >= 0) w.contacts[e.prev >> 1].edges[e.prev & 1].next = e.next;
    else w.bodies[bodyIndex].contactHead = e.next;
    if (e.next >= 0) w.contacts[e.next >> 1].edges[e.next & 1].prev = e.prev;
    e = {};
}

}  // namespace

void World::Impl::updatePairs() {
    // Every proxy that moved out of its fat AABB (or is new) looks for overlapping proxies.
    for (int proxy : movedProxies) {
        collision.query(collision.fatAABB(proxy), [&](int other) {
            // When both moved, only the pair's lower proxy reports it.
            if (other == proxy || (other < proxy && collision.wasMoved(other))) return true;
            addPair(proxy, other);
            return true;
        });
    }
    for (int proxy : movedProxies) collision.clearMoved(proxy);
    movedProxies.clear();
}

void World::Impl::addPair(int proxyA, int proxyB) {
    collide::ChildKey keyA = collision.proxyKey(proxyA), keyB = collision.proxyKey(proxyB);
    const ShapeData* sa = &shapes[keyA.shape];
    const ShapeData* sb = &shapes[keyB.shape];
    if (sa->body == sb->body) return;
    const Body& ba = bodies[sa->body];
    const Body& bb = bodies[sb->body];
    if (ba.type != BodyType::Dynamic && bb.type != BodyType::Dynamic) return;
    if (sa->sensor || sb->sensor) return;
    if (!collide::CollisionSystem::canCollide(sa->type, sb->type)) return;
    if (!shouldCollide(sa->filter, sb->filter)) return;
    if (!jointAllowsCollision(*this, sa->body, sb->body)) return;
    const uint64_t key = pairKey(proxyA, proxyB);
    if (pairs.contains(key)) return;

    if (collide::CollisionSystem::mustSwap(sa->type, sb->type)) {
        std::swap(keyA, keyB);
        std::swap(proxyA, proxyB);
        std::swap(sa, sb);
    }
    int index;
    if (!freeContacts.empty()) {
        index = freeContacts.back();
        freeContacts.pop_back();
    } else {
        index = static_cast<int>(contacts.size());
        contacts.emplace_back();
    }
    Contact& c = contacts[index];
    c = Contact{};
    c.alive = true;
    c.pairKey = key;
    c.proxyA = proxyA;
    c.proxyB = proxyB;
    c.a = keyA;
    c.b = keyB;
    c.bodyA = sa->body;
    c.bodyB = sb->body;
    linkEdge(*this, index, 0, c.bodyA);
    linkEdge(*this, index, 1, c.bodyB);
    pairs.emplace(key, index);
}

void World::Impl::destroyContact(int index) {
    Contact& c = contacts[index];
    pairs.erase(c.pairKey);
    unlinkEdge(*this, index, 0, c.bodyA);
    unlinkEdge(*this, index, 1, c.bodyB);
    c.alive = false;
    freeContacts.push_back(index);
}

void World::Impl::destroyContactsOf(int bodyIndex, int shapeIndex) {
    for (int edge = bodies[bodyIndex].contactHead; edge >= 0;) {
        const int index = edge >> 1;
        const int next = contacts[index].edges[edge & 1].next;
        const Contact& c = contacts[index];
        if (shapeIndex < 0 || c.a.shape == shapeIndex || c.b.shape == shapeIndex) {
            // The other body loses a support: wake it.
            const int other = c.bodyA == bodyIndex ? c.bodyB : c.bodyA;
            if (c.touching) wake(other);
            destroyContact(index);
        }
        edge = next;
    }
}

// Narrowphase for every contact with an awake body: a new manifold, whose points inherit the
// accumulated impulses of the old points with the same feature id.
void World::Impl::updateContacts() {
    for (int index = 0; index < static_cast<int>(contacts.size()); ++index) {
        Contact& c = contacts[index];
        if (!c.alive) continue;
        Body& ba = bodies[c.bodyA];
        Body& bb = bodies[c.bodyB];
        if (!ba.awake && !bb.awake) continue;
        if (!overlaps(collision.fatAABB(c.proxyA), collision.fatAABB(c.proxyB))) {
            destroyContact(index);
            continue;
        }
        const collide::Manifold m = collision.collide(c.a, ba.xf, c.b, bb.xf);
        const ShapeData& sa = shapes[c.a.shape];
        const ShapeData& sb = shapes[c.b.shape];
        c.friction = mixFriction(sa.friction, sb.friction);
        c.restitution = mixRestitution(sa.restitution, sb.restitution);

        ContactPointState next[2];
        for (int i = 0; i < m.pointCount; ++i) {
            ContactPointState& p = next[i];
            p.point = m.points[i].point;
            p.separation = m.points[i].separation;
            p.id = m.points[i].id;
            p.anchorA = p.point - ba.center;
            p.anchorB = p.point - bb.center;
            for (int j = 0; j < c.pointCount; ++j) {
                if (c.points[j].id == p.id) {
                    p.normalImpulse = c.points[j].normalImpulse;
                    p.tangentImpulse = c.points[j].tangentImpulse;
                    break;
                }
            }
        }
        c.normal = m.normal;
        c.pointCount = m.pointCount;
        c.points[0] = next[0];
        c.points[1] = next[1];
        c.touching = m.pointCount > 0;
        // An awake body touching a sleeping one wakes the sleeper's island.
        if (c.touching) {
            if (!ba.awake && ba.type != BodyType::Static && bb.awake) wake(c.bodyA);
            if (!bb.awake && bb.type != BodyType::Static && ba.awake) wake(c.bodyB);
        }
    }
}

}  // namespace perpdot
