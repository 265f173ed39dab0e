// The persistent contact cache: new pairs from moved proxies, manifolds from the narrowphase,
// and warm-start impulses carried from one step to the next by Box2D's feature ids.
#include <algorithm>
#include <cmath>
#include <tuple>

#include "core/contacts/contact_cache.hpp"
#include "core/contacts/contact_world.hpp"
#include "core/contacts/manifold_reuse.hpp"
#include "core/base/radix_sort.hpp"
#include "core/world/events.hpp"

namespace perpdot {

namespace {

// Box2D v3's rules: rolling resistance is the larger coefficient times the larger rounding
// radius (a lever arm), and the surfaces' tangent speeds add.
// Flat surfaces meet at vertices, which are points of the bodies: their manifold may be kept
// (manifold_reuse.hpp). A round surface's contact point rolls over it as the body turns.
bool isFlat(const ShapeData& s) { return roundingRadius(s) == 0.0f; }

float mixRollingResistance(const ShapeData& a, const ShapeData& b) {
    const float resistance = std::max(a.rollingResistance, b.rollingResistance);
    return resistance > 0.0f ? resistance * std::max(roundingRadius(a), roundingRadius(b)) : 0.0f;
}

// A new manifold for `c`: its points inherit the accumulated impulses of the old points with the
// same feature id, and the bodies' pose is remembered for keeping it (manifold_reuse.hpp).
void takeManifold(Contact& c, const collide::Manifold& m, const Body& ba, const Body& bb, bool keepable) {
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
    rememberManifoldPose(c, ba, bb, keepable);
}

// Whether two overlapping proxies may have a contact (bodies, sensors, shape types, filters,
// joints); reads only, so the pair-finding workers ask it.
bool pairWanted(const Pool<Body>& bodies, const ShapeStore& shapes, const collide::CollisionSystem& collision,
                const JointStore& joints, int proxyA, int proxyB) {
    const ShapeData& sa = shapes[collision.proxyKey(proxyA).shape];
    const ShapeData& sb = shapes[collision.proxyKey(proxyB).shape];
    if (sa.body == sb.body) return false;
    const BodyType ta = bodies[sa.body].type, tb = bodies[sb.body].type;
    // A contact needs a dynamic body; a sensor also sees a kinematic one (a character mover
    // entering a trigger zone).
    const bool sensorSeesKinematic = (sa.sensor || sb.sensor) && (ta == BodyType::Kinematic || tb == BodyType::Kinematic);
    if (ta != BodyType::Dynamic && tb != BodyType::Dynamic && !sensorSeesKinematic) return false;
    // A sensor sees shapes that are not sensors and want to be seen.
    if (sa.sensor && sb.sensor) return false;
    if ((sa.sensor && !sb.enableSensorEvents) || (sb.sensor && !sa.enableSensorEvents)) return false;
    return collide::CollisionSystem::canCollide(sa.type, sb.type) && shouldCollide(sa.filter, sb.filter) &&
           jointAllowsCollision(bodies, joints, sa.body, sb.body);
}

// A contact for a wanted pair, unless it has one.
void addPair(const ContactWorld& w, const NewPair& pair) {
    ContactCache& cache = w.contactCache;
    int proxyA = pair.proxyA, proxyB = pair.proxyB;
    const uint64_t key = proxyPairKey(proxyA, proxyB);
    // The game's rule (World::setShouldCollide) judges pairs that have no contact yet.
    if (w.shouldCollide && !cache.pairs.contains(key) &&
        !w.shouldCollide(handleAt<ShapeId>(w.shapes, pair.a.shape, w.identity), handleAt<ShapeId>(w.shapes, pair.b.shape, w.identity)))
        return;
    if (!cache.pairs.insert(key)) return;  // one lookup: found twice, or has its contact
    collide::ChildKey keyA = pair.a, keyB = pair.b;
    const ShapeData* sa = &w.shapes[keyA.shape];
    const ShapeData* sb = &w.shapes[keyB.shape];

    if (collide::CollisionSystem::mustSwap(sa->type, sb->type)) {
        std::swap(keyA, keyB);
        std::swap(proxyA, proxyB);
        std::swap(sa, sb);
    }
    const int index = cache.contacts.create();
    Contact& c = cache.contacts[index];
    c.pairKey = key;
    c.proxyA = proxyA;
    c.proxyB = proxyB;
    c.a = keyA;
    c.b = keyB;
    bindShapes(cache, index, *sa, *sb, contactSkin(w.def, w.bodies[sa->body].type, w.bodies[sb->body].type));
    c.sensor = sa->sensor || sb->sensor;
    if (!c.sensor) mixMaterials(c, *sa, *sb);
    cache.bodyLists.link(cache.contacts, index, 0, c.bodyA);
    cache.bodyLists.link(cache.contacts, index, 1, c.bodyB);
}

// The narrowphase of one contact, with the bodies' poses alone: whether its fat AABBs still
// overlap (else it is to be destroyed), a sensor's overlap, or its kept manifold or a new one.
// Events, the pre-solve callback and waking are left to updateContacts.
Narrowphase collideContact(Contact& c, const Pool<Body>& bodies, const ShapeStore& shapes, const collide::CollisionSystem& collision,
                           float reuseDistance) {
    const Body& ba = bodies[c.bodyA];
    const Body& bb = bodies[c.bodyB];
    if (!overlaps(collision.fatAABB(c.proxyA), collision.fatAABB(c.proxyB))) return Narrowphase::Apart;
    if (c.sensor) return collision.testOverlap(c.a, ba.xf, c.b, bb.xf) ? Narrowphase::Overlapping : Narrowphase::Separate;
    const bool wasTouching = c.touching;
    // The shapes' reach is only used without points: a contact with points reads no shape.
    auto reach = [&] {
        const ShapeData &sa = shapes[c.a.shape], &sb = shapes[c.b.shape];
        return std::max(sa.maxExtent + length(ba.localCenter), sb.maxExtent + length(bb.localCenter));
    };
    const ReuseLimits limits{.distance = reuseDistance,
                             .reach = c.pointCount > 0 ? 0.0f : reach(),
                             .margin = collide::collisionSkin(c.typeA, c.typeB, c.skin) + collide::collisionSkin(c.typeB, c.typeA, c.skin),
                             .skinOffset = collide::skinOffset(c.typeA, c.typeB, c.skin) + collide::skinOffset(c.typeB, c.typeA, c.skin)};
    if (!reuseManifold(c, ba, bb, limits))
        takeManifold(c, collision.collide(c.a, ba.xf, c.b, bb.xf, c.skin), ba, bb, c.turnsA && c.turnsB);
    c.touching = c.pointCount > 0;
    return wasTouching ? Narrowphase::WasTouching : Narrowphase::WasNotTouching;
}

// Whether the one-by-one pass of updateContacts has nothing to do for a contact the workers
// collided: no begin or end event, no pre-solve call, no sleeper to wake. Awake flags only turn
// on in that pass, so a body awake (or static) now needs no waking there. `preSolve`: the world
// has a pre-solve callback.
bool isQuiet(const Pool<Body>& bodies, const ShapeStore& shapes, bool preSolve, const Contact& c, Narrowphase result) {
    if (result != Narrowphase::WasTouching && result != Narrowphase::WasNotTouching) return false;
    if (c.touching != (result == Narrowphase::WasTouching)) return false;
    if (!c.touching) return true;
    if (preSolve && (shapes[c.a.shape].enablePreSolveEvents || shapes[c.b.shape].enablePreSolveEvents)) return false;
    const Body& ba = bodies[c.bodyA];
    const Body& bb = bodies[c.bodyB];
    return (ba.awake || ba.type == BodyType::Static) && (bb.awake || bb.type == BodyType::Static);
}

// A contact's entry in ContactCache::touchingPoints.
uint8_t touchingPoints(const Contact& c) { return c.touching ? static_cast<uint8_t>(c.pointCount) : 0; }

// Spreads the 16 bits of v (below 2^16) to the even bits: half a Morton code.
uint32_t spreadBits(uint32_t v) {
    v = (v | (v << 8)) & 0x00FF00FFu;
    v = (v | (v << 4)) & 0x0F0F0F0Fu;
    v = (v | (v << 2)) & 0x33333333u;
    v = (v | (v << 1)) & 0x55555555u;
    return v;
}

// A Morton coordinate: v in [0, 65535], clamped (NaN: 0; a box at the float range's edge).
uint32_t cellOf(float v) { return v >= 0.0f ? (v < 65535.0f ? static_cast<uint32_t>(v) : 65535u) : 0u; }

// Splits the moved proxies that look for pairs (those whose filter accepts some shape: pairWanted
// would refuse all that others find) into groups for one tree query each: in the Morton order of
// their boxes' centres, the next proxy joins the group while the union box stays within twice
// the members' own area.
void groupMovedProxies(const ContactWorld& w, ContactCache& cache) {
    const collide::CollisionSystem& collision = w.broadphase.collision;
    std::vector<std::pair<uint32_t, int>>& order = cache.mortonOrder;
    order.clear();
    order.reserve(w.broadphase.movedProxies.size());
    AABB bounds{};
    for (int proxy : w.broadphase.movedProxies) {
        if (w.shapes.pairsWithNothing(w.shapes[collision.proxyKey(proxy).shape].filter)) continue;
        const AABB box = collision.fatAABB(proxy);
        bounds = order.empty() ? box : combine(bounds, box);
        order.emplace_back(0u, proxy);
    }
    const Vec2 size = bounds.upper - bounds.lower;
    const float scale = 65535.0f / std::max(std::max(size.x, size.y), 1e-6f);
    for (std::pair<uint32_t, int>& entry : order) {
        const AABB box = collision.fatAABB(entry.second);
        const Vec2 cell = scale * (0.5f * (box.lower + box.upper) - bounds.lower);
        entry.first = spreadBits(cellOf(cell.x)) | (spreadBits(cellOf(cell.y)) << 1);
    }
    radixSort(order, cache.mortonScratch);
    cache.queried.clear();
    cache.groupStarts.clear();
    cache.queried.reserve(order.size());
    cache.groupStarts.reserve(order.size() + 1);
    auto area = [](const AABB& box) { return (box.upper.x - box.lower.x) * (box.upper.y - box.lower.y); };
    AABB all{};
    float areas = 0.0f;
    int members = 0;
    for (const auto& [code, proxy] : order) {
        const AABB box = collision.fatAABB(proxy);
        const AABB joined = combine(all, box);
        if (members > 0 && members < collide::CollisionSystem::groupSize && area(joined) <= 2.0f * (areas + area(box))) {
            all = joined;
            areas += area(box);
            ++members;
        } else {
            cache.groupStarts.push_back(static_cast<int>(cache.queried.size()));
            all = box;
            areas = area(box);
            members = 1;
        }
        cache.queried.push_back(proxy);
    }
    cache.groupStarts.push_back(static_cast<int>(cache.queried.size()));
}

}  // namespace

void updatePairs(const ContactWorld& w) {
    ContactCache& cache = w.contactCache;
    collide::CollisionSystem& collision = w.broadphase.collision;
    groupMovedProxies(w, cache);
    // The workers query the tree side by side, each into its own list.
    // Their lists hold as many pairs as the contact pool has slots: more would grow the pool anyway.
    const size_t most = static_cast<size_t>(cache.contacts.capacity());
    cache.newPairsOf.resize(static_cast<size_t>(w.workers.count()));
    for (std::vector<NewPair>& found : cache.newPairsOf) {
        found.clear();
        found.reserve(most);
    }
    const int groups = static_cast<int>(cache.groupStarts.size()) - 1;
    w.workers.parallelFor(groups, 4, [&](int begin, int end, int worker) {
        std::vector<NewPair>& found = cache.newPairsOf[static_cast<size_t>(worker)];
        for (int g = begin; g < end; ++g) {
            const int first = cache.groupStarts[static_cast<size_t>(g)];
            const int count = cache.groupStarts[static_cast<size_t>(g) + 1] - first;
            // Pairs that have a contact are most of what a large moving proxy finds: those whose
            // boxes overlapped at the last update (updateContacts destroys only contacts whose boxes
            // are apart) are dropped by the query, before the sort. Of the others, the few that have
            // a contact (two sleepers' boxes are not checked) are dropped by addPair's one lookup:
            // looking here too would miss the cache twice per new pair.
            collision.queryNewPairs(&cache.queried[static_cast<size_t>(first)], count, [&](int proxy, int other) {
                if (!pairWanted(w.bodies, w.shapes, collision, w.joints, proxy, other)) return;
                NewPair p{collision.proxyKey(proxy), collision.proxyKey(other), proxy, other};
                if (std::tie(p.b.shape, p.b.child) < std::tie(p.a.shape, p.a.child)) {
                    std::swap(p.a, p.b);
                    std::swap(p.proxyA, p.proxyB);
                }
                found.push_back(p);
            });
        }
    });
    std::vector<NewPair>& newPairs = cache.newPairs;
    newPairs.clear();
    newPairs.reserve(most);
    for (const std::vector<NewPair>& found : cache.newPairsOf) newPairs.insert(newPairs.end(), found.begin(), found.end());
    for (int proxy : w.broadphase.movedProxies) collision.clearMoved(proxy);
    w.broadphase.movedProxies.clear();
    // The tree's internal shape and the workers' split decide the order pairs are found in.
    // Contacts are created in the order of their child keys instead, so that contact order (and
    // the solver's) depends on the world's state alone: a world restored from a snapshot, with a
    // rebuilt tree, or stepped by any number of workers, steps bit for bit alike.
    std::sort(newPairs.begin(), newPairs.end(), [](const NewPair& x, const NewPair& y) {
        return std::tie(x.a.shape, x.a.child, x.b.shape, x.b.child) < std::tie(y.a.shape, y.a.child, y.b.shape, y.b.child);
    });
    // Each pair's lookup misses the cache: ask for the slot a few pairs ahead.
    constexpr size_t ahead = 8;
    for (size_t i = 0; i < newPairs.size(); ++i) {
        if (i + ahead < newPairs.size()) cache.pairs.prefetch(proxyPairKey(newPairs[i + ahead].proxyA, newPairs[i + ahead].proxyB));
        addPair(w, newPairs[i]);
    }
}

collide::Skin contactSkin(const WorldDef& def, BodyType a, BodyType b) {
    if (def.box2dSkin) return collide::Skin::Box2D;
    return a == BodyType::Dynamic && b == BodyType::Dynamic ? collide::Skin::None : collide::Skin::Kept;
}

void bindShapes(ContactCache& cache, int contact, const ShapeData& a, const ShapeData& b, collide::Skin skin) {
    Contact& c = cache.contacts[contact];
    c.bodyA = a.body;
    c.bodyB = b.body;
    c.turnsA = isFlat(a);
    c.turnsB = isFlat(b);
    c.typeA = a.type;
    c.typeB = b.type;
    c.skin = skin;
    const auto capacity = static_cast<size_t>(cache.contacts.capacity());
    cache.bodiesOf.resize(capacity);
    cache.touchingPoints.resize(capacity);
    cache.bodiesOf[static_cast<size_t>(contact)] = {a.body, b.body};
    cache.touchingPoints[static_cast<size_t>(contact)] = touchingPoints(c);
}

namespace {

// Starts loading a contact's first line (its pair key) and its last (its places in the bodies' lists).
void prefetchContact(const Contact& c) {
    __builtin_prefetch(&c.pairKey, 1);
    __builtin_prefetch(&c.edges[1], 1);
}

// Starts loading what releaseContact writes besides the contact: its pair's slot and its neighbours.
void prefetchRelease(const ContactCache& cache, int index) {
    const Contact& c = cache.contacts[index];
    cache.pairs.prefetch(c.pairKey);
    for (const Edge& e : c.edges)
        for (int key : {e.prev, e.next})
            if (key >= 0) __builtin_prefetch(&cache.contacts[key >> 1].edges[key & 1], 1);
}

// The contact leaves the pair set, its bodies' lists and the pool.
void releaseContact(ContactCache& cache, int index) {
    const Contact& c = cache.contacts[index];
    cache.pairs.erase(c.pairKey);
    cache.bodyLists.unlink(cache.contacts, index, 0, c.bodyA);
    cache.bodyLists.unlink(cache.contacts, index, 1, c.bodyB);
    cache.contacts.destroy(index);
}

// Its end event, if it touched or overlapped; it does no more.
void reportEnd(const ContactWorld& w, Contact& c) {
    if (c.touching || c.overlapping) reportTouch(w.events, w.shapes, w.identity, c, false);
    c.touching = c.overlapping = false;
}

}  // namespace

void destroyContact(const ContactWorld& w, int index) {
    reportEnd(w, w.contactCache.contacts[index]);
    releaseContact(w.contactCache, index);
}

void releaseApartContacts(ContactCache& cache) {
    const std::vector<int>& apart = cache.apart;
    // Each contact misses the cache, and so do its pair's slot and its neighbours in the bodies'
    // lists: ask for the contact two distances ahead, for the rest at one.
    constexpr size_t ahead = 8;
    for (size_t i = 0; i < apart.size(); ++i) {
        if (i + 2 * ahead < apart.size()) prefetchContact(cache.contacts[apart[i + 2 * ahead]]);
        if (i + ahead < apart.size()) prefetchRelease(cache, apart[i + ahead]);
        releaseContact(cache, apart[i]);
    }
    cache.apart.clear();
}

void mixMaterials(Contact& c, const ShapeData& a, const ShapeData& b) {
    c.friction = mixFriction(a.friction, b.friction);
    c.restitution = mixRestitution(a.restitution, b.restitution);
    c.rollingResistance = mixRollingResistance(a, b);
    c.tangentSpeed = a.tangentSpeed + b.tangentSpeed;
}

void remixMaterials(ContactCache& cache, const ShapeStore& shapes, int shape) {
    cache.bodyLists.forEach(cache.contacts, shapes[shape].body, [&](int index, int) {
        Contact& c = cache.contacts[index];
        if (!c.sensor && (c.a.shape == shape || c.b.shape == shape)) mixMaterials(c, shapes[c.a.shape], shapes[c.b.shape]);
    });
}

void destroyContactsOf(const ContactWorld& w, int bodyIndex, int shapeIndex) {
    const ContactCache& cache = w.contactCache;
    cache.bodyLists.forEach(cache.contacts, bodyIndex, [&](int index, int) {
        const Contact& c = cache.contacts[index];
        if (shapeIndex < 0 || c.a.shape == shapeIndex || c.b.shape == shapeIndex) {
            // The other body loses a support: wake it.
            const int other = c.bodyA == bodyIndex ? c.bodyB : c.bodyA;
            if (c.touching) wakeIsland(w.bodies, other);
            destroyContact(w, index);
        }
    });
}

// Narrowphase for every contact with an awake body: the workers run collideContact on those
// whose bodies were awake as the step began; then, in pool order, events are raised and sleepers
// woken, and the contacts found apart end (the worker that re-fits the tree releases them beside
// the solve: releaseApartContacts). Quiet contacts skip that pass. A woken body's contacts wait for the
// next step's narrowphase, as in Box2D v3: this step its island's kept manifolds are solved, and
// a sleeper it touches but never touched before wakes one step later. Waking spreads one contact
// a step through bodies that fell asleep apart (Box2D 2.4's pass collided them at once, and a
// block of 9,600 boxes made asleep woke whole in the step the first one was hit).
void updateContacts(const ContactWorld& w) {
    ContactCache& cache = w.contactCache;
    const int count = cache.contacts.capacity();
    cache.narrowphase.resize(static_cast<size_t>(count));
    cache.touchingPoints.resize(static_cast<size_t>(count));  // a restored pool's free slots at its end
    cache.bodiesOf.resize(static_cast<size_t>(count));
    w.workers.parallelFor(count, 64, [&](int begin, int end, int) {
        const Pool<Body>& bodies = w.bodies;
        const ShapeStore& shapes = w.shapes;
        const collide::CollisionSystem& collision = w.broadphase.collision;
        const float reuseDistance = w.def.contactReuseDistance;
        const bool preSolve = static_cast<bool>(w.preSolve);
        for (int index = begin; index < end; ++index) {
            // A free slot, or a contact whose bodies both sleep (its points are as they were): the
            // contact is not even read.
            auto asleep = [&](int body) { return !bodies[body].awake; };
            if (!cache.contacts.isLive(index)) {
                cache.narrowphase[index] = Narrowphase::Skipped;
                cache.touchingPoints[index] = 0;
                continue;
            }
            if (asleep(cache.bodiesOf[index][0]) && asleep(cache.bodiesOf[index][1])) {
                cache.narrowphase[index] = Narrowphase::Skipped;
                continue;
            }
            Contact& c = cache.contacts[index];
            Narrowphase result = collideContact(c, bodies, shapes, collision, reuseDistance);
            if (isQuiet(bodies, shapes, preSolve, c, result)) {
                if (!c.touching) c.rollingImpulse = c.restSink = 0.0f;
                result = Narrowphase::Quiet;
            }
            cache.narrowphase[index] = result;
            cache.touchingPoints[index] = touchingPoints(c);
        }
    });
    std::vector<int>& unquiet = cache.unquiet;
    unquiet.clear();
    for (int index = 0; index < count; ++index)
        if (cache.narrowphase[index] != Narrowphase::Quiet && cache.narrowphase[index] != Narrowphase::Skipped) unquiet.push_back(index);
    cache.apart.clear();  // (a step that threw before releasing them finds them apart again)
    cache.beganTouching = 0;
    // Each contact misses the cache: ask for it a few ahead.
    constexpr size_t ahead = 8;
    for (size_t i = 0; i < unquiet.size(); ++i) {
        if (i + ahead < unquiet.size()) prefetchContact(cache.contacts[unquiet[i + ahead]]);
        const int index = unquiet[i];
        const Narrowphase result = cache.narrowphase[index];
        Contact& c = cache.contacts[index];
        Body& ba = w.bodies[c.bodyA];
        Body& bb = w.bodies[c.bodyB];
        if (result == Narrowphase::Apart) {
            reportEnd(w, c);
            cache.touchingPoints[index] = 0;
            cache.apart.push_back(index);
            continue;
        }
        if (c.sensor) {
            const bool overlapping = result == Narrowphase::Overlapping;
            if (overlapping != c.overlapping) {
                c.overlapping = overlapping;
                reportTouch(w.events, w.shapes, w.identity, c, overlapping);
            }
            continue;
        }
        const ShapeData& sa = w.shapes[c.a.shape];
        const ShapeData& sb = w.shapes[c.b.shape];
        if (c.touching && w.preSolve && (sa.enablePreSolveEvents || sb.enablePreSolveEvents) &&
            !w.preSolve(handleAt<ShapeId>(w.shapes, c.a.shape, w.identity), handleAt<ShapeId>(w.shapes, c.b.shape, w.identity),
                        contactData(w.shapes, w.identity, c))) {
            c.pointCount = 0;  // disabled for this step, and its manifold is not kept
            c.touching = false;
            c.reuseValid = false;
        }
        if (!c.touching) c.rollingImpulse = c.restSink = 0.0f;  // no warm start, no rest sink for a parted pair
        cache.touchingPoints[index] = touchingPoints(c);
        if (c.touching != (result == Narrowphase::WasTouching)) reportTouch(w.events, w.shapes, w.identity, c, c.touching);
        cache.beganTouching += c.touching && result != Narrowphase::WasTouching ? 1 : 0;
        // An awake body touching a sleeping one wakes the sleeper's island.
        if (c.touching) {
            if (!ba.awake && ba.type != BodyType::Static && bb.awake) wakeIsland(w.bodies, c.bodyA);
            if (!bb.awake && bb.type != BodyType::Static && ba.awake) wakeIsland(w.bodies, c.bodyB);
        }
    }
}

}  // namespace perpdot
