// World snapshots: versioned bytes of everything a step reads — settings, bodies, shapes with
// their broadphase proxies (fat AABBs, move buffer), the contact cache with its warm-start
// impulses, joints (snapshot_joints.cpp), free lists and generations — so that restore + N steps equals N steps, bit for bit.
//
// The Box2D tree itself cannot be saved: restore re-creates one proxy per shape child with the
// saved fat AABB, and contacts and the move buffer name proxies by child key (shape, child), not
// by the tree's proxy ids. Nothing depends on the tree's shape or its numbering (updatePairs sorts
// new pairs by child keys), so the rebuilt tree behaves like the original, and the bytes of a
// snapshot depend on the world's state alone. The reader checks every count, index and link before the world is
// touched: corrupt bytes give perpdot::Error and leave the world as it was.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <unordered_set>

#include "core/contacts/manifold_reuse.hpp"
#include "core/snapshot/snapshot.hpp"
#include "core/snapshot/snapshot_fields.hpp"
#include "core/world/world_impl.hpp"

namespace perpdot {

namespace {

constexpr uint8_t magic[8] = {'P', 'E', 'R', 'P', 'D', 'O', 'T', 'S'};

// --- settings ---

WorldDef readDef(ByteReader& in) {
    WorldDef d;
    // Worlds saved before format 4 rested on Box2D's skin and rebuilt every manifold.
    if (in.version < 4) {
        d.box2dSkin = true;
        d.contactReuseDistance = 0.0f;
    }
    readFields(in, d);
    if (d.substeps < 1 || d.substeps > 64) in.fail("substeps " + std::to_string(d.substeps) + " is outside [1, 64]");
    return d;
}

// --- bodies ---

// Bitwise equality of two transforms (a derived one must reproduce the stored one exactly).
bool sameBits(float a, float b) { return std::bit_cast<uint32_t>(a) == std::bit_cast<uint32_t>(b); }
bool sameBits(const Transform& a, const Transform& b) {
    return sameBits(a.p.x, b.p.x) && sameBits(a.p.y, b.p.y) && sameBits(a.q.c, b.q.c) && sameBits(a.q.s, b.q.s);
}

// futureOnly: a transform that is exactly the one the pose derives (every body a step or a
// continuous pass has moved) is written as zeros — a zero rotation is no transform — and derived
// again on reading, so a compact snapshot does not pay for the pose twice.
void writeBody(ByteWriter& out, const World::Impl& w, int index, bool futureOnly) {
    Body b = w.bodies[index];
    if (futureOnly && sameBits(b.xf, b.derivedTransform())) b.xf = {{0.0f, 0.0f}, {0.0f, 0.0f}};
    writeFields(out, b);
    out.u32(static_cast<uint32_t>(b.shapes.size()));
    for (int s : b.shapes) out.i32(s);
    // The contact list as the sequence of its edge keys (contact*2 + side), head first.
    const ContactCache& cache = w.contactCache;
    const std::vector<int> edges = cache.bodyLists.keys(cache.contacts, index);
    out.u32(static_cast<uint32_t>(edges.size()));
    for (int e : edges) out.i32(e);
}

// Reads a live body, appending its contact edges to `edges`; its shape list and contact edges are
// checked against the other pools later.
void readBody(ByteReader& in, Body& b, std::vector<int>& edges, int bodyCount, int shapeLimit, int edgeLimit) {
    readFields(in, b);
    if (b.xf.q.c == 0.0f && b.xf.q.s == 0.0f) b.xf = b.derivedTransform();
    if (b.type > BodyType::Dynamic) in.fail("body type " + std::to_string(static_cast<int>(b.type)) + " is unknown");
    if (b.mass < 0 || b.invMass < 0 || b.inertia < 0 || b.invInertia < 0) in.fail("negative mass or inertia");
    if (b.jointCount < 0 || b.jointCount > 0x3FFFFFFF) in.fail("joint count " + std::to_string(b.jointCount) + " is out of range");
    if (b.islandNext < -1 || b.islandNext >= bodyCount) in.fail("island link " + std::to_string(b.islandNext) + " is out of range");
    // The centre of mass is its shapes' centroid, so within their range of the origin, and the step
    // derives the origin from it: c − R·localCenter. Beyond that range, or away from
    // transformPoint(xf, localCenter), the origin of the next step differs from the one saved or
    // overflows (a fuzzed 1.7e38 m centre with a −1.7e38 m local centre: an infinite origin).
    if (!withinShapeRange(b.localCenter)) in.fail("body local centre is beyond the shape range (maxShapeCoordinate)");
    const Vec2 fromOrigin = transformPoint(b.xf, b.localCenter);
    const float tolerance = 1e-4f * (1.0f + std::fabs(b.center.x) + std::fabs(b.center.y) + std::fabs(b.localCenter.x) + std::fabs(b.localCenter.y));
    if (!(std::fabs(fromOrigin.x - b.center.x) <= tolerance && std::fabs(fromOrigin.y - b.center.y) <= tolerance))
        in.fail("body centre of mass is not where its origin and local centre put it");
    b.shapes.resize(in.count(4, "body shape"));
    for (int& s : b.shapes) s = in.integer(0, shapeLimit - 1, "shape index");
    const int edgeCount = in.count(4, "contact edge");
    for (int k = 0; k < edgeCount; ++k) edges.push_back(in.integer(0, edgeLimit - 1, "contact edge"));
}

// --- shapes ---

void writeGeometry(ByteWriter& out, const ShapeData& s) {
    out.u8(static_cast<uint8_t>(s.geometry.index()));
    if (auto* c = std::get_if<Circle>(&s.geometry)) {
        out.vec2(c->center);
        out.f32(c->radius);
    } else if (auto* p = std::get_if<Polygon>(&s.geometry)) {
        out.u32(static_cast<uint32_t>(p->count));
        for (int i = 0; i < p->count; ++i) out.vec2(p->vertices[i]);
        out.f32(p->radius);
    } else if (auto* seg = std::get_if<Segment>(&s.geometry)) {
        out.vec2(seg->v1);
        out.vec2(seg->v2);
    } else if (auto* cap = std::get_if<Capsule>(&s.geometry)) {
        out.vec2(cap->center1);
        out.vec2(cap->center2);
        out.f32(cap->radius);
    } else {
        const Chain& chain = std::get<Chain>(s.geometry);
        out.u32(static_cast<uint32_t>(chain.vertices.size()));
        for (Vec2 v : chain.vertices) out.vec2(v);
        // The loop byte's bits: loop, solid on the right, prevVertex and nextVertex follow (a chain
        // of the code before ChainSide has the bits 0 and so its one side, Left).
        out.u8(static_cast<uint8_t>((chain.loop ? 1 : 0) | (chain.solid == ChainSide::Right ? 2 : 0) |
                                    (chain.prevVertex ? 4 : 0) | (chain.nextVertex ? 8 : 0)));
        if (chain.prevVertex) out.vec2(*chain.prevVertex);
        if (chain.nextVertex) out.vec2(*chain.nextVertex);
    }
}

// Reads geometry and runs the checks createShape runs; a polygon must also be the exact
// normalised form makePolygon produces, which is what the world stores. A polygon equal to the
// one the restoring world holds in that slot (`held`: a rollback restores the same shapes) passed
// those checks when it was made, and is not checked again.
void readGeometry(ByteReader& in, ShapeData& s, const ShapeData* held) {
    try {
        switch (in.u8()) {
            case 0: {
                Circle c;
                c.center = in.finiteVec2();
                c.radius = in.finite();
                validateGeometry(c);
                s.geometry = c;
                break;
            }
            case 1: {
                Polygon p;
                p.count = static_cast<int>(in.u32());
                if (p.count < 3 || p.count > maxPolygonVertices) in.fail("polygon vertex count out of range");
                for (int i = 0; i < p.count; ++i) p.vertices[i] = in.finiteVec2();
                p.radius = in.finite();
                const Polygon* known = held ? std::get_if<Polygon>(&held->geometry) : nullptr;
                if (!known || !(*known == p)) {
                    validateGeometry(p);
                    if (!(makePolygon(std::span(p.vertices.data(), static_cast<size_t>(p.count)), p.radius) == p))
                        in.fail("polygon is not in normalised form");
                }
                s.geometry = p;
                break;
            }
            case 2: {
                Segment seg;
                seg.v1 = in.finiteVec2();
                seg.v2 = in.finiteVec2();
                validateGeometry(seg);
                s.geometry = seg;
                break;
            }
            case 3: {
                Chain chain;
                chain.vertices.resize(in.count(8, "chain vertex"));
                for (Vec2& v : chain.vertices) v = in.finiteVec2();
                const uint8_t bits = in.u8();
                if (bits > 15) in.fail("chain flags " + std::to_string(bits) + " are not valid");
                chain.loop = (bits & 1) != 0;
                chain.solid = (bits & 2) != 0 ? ChainSide::Right : ChainSide::Left;
                if ((bits & 4) != 0) chain.prevVertex = in.finiteVec2();
                if ((bits & 8) != 0) chain.nextVertex = in.finiteVec2();
                validateGeometry(chain);
                s.geometry = std::move(chain);
                break;
            }
            case 4: {
                Capsule cap;
                cap.center1 = in.finiteVec2();
                cap.center2 = in.finiteVec2();
                cap.radius = in.finite();
                validateGeometry(cap);
                s.geometry = cap;
                break;
            }
            default:
                in.fail("shape type is unknown");
        }
    } catch (const Error& e) {
        const std::string what = e.what();
        if (what.starts_with("snapshot:")) throw;
        in.fail("invalid shape geometry: " + what);
    }
    s.type = static_cast<ShapeType>(s.geometry.index());
}

void writeShape(ByteWriter& out, const World::Impl& w, const ShapeData& s) {
    out.i32(s.body);
    writeGeometry(out, s);
    writeFields(out, s);
    out.u32(static_cast<uint32_t>(s.proxies.size()));
    for (int proxy : s.proxies) {
        const AABB fat = w.broadphase.collision.fatAABB(proxy);
        out.vec2(fat.lower);
        out.vec2(fat.upper);
    }
}

// Reads a live shape, appending its proxies' fat AABBs to `proxies`.
void readShape(ByteReader& in, ShapeData& s, std::vector<AABB>& proxies, int bodyCount, const ShapeData* held) {
    s.body = in.integer(0, bodyCount - 1, "shape body");
    readGeometry(in, s, held);
    readFields(in, s);
    if (s.density < 0 || s.friction < 0 || s.restitution < 0) in.fail("negative shape material");
    const int proxyCount = in.count(16, "proxy");
    for (int k = 0; k < proxyCount; ++k) {
        AABB fat;
        fat.lower = in.finiteVec2();
        fat.upper = in.finiteVec2();
        if (fat.lower.x > fat.upper.x || fat.lower.y > fat.upper.y) in.fail("inverted proxy AABB");
        proxies.push_back(fat);
    }
}

// --- contacts ---

// futureOnly: the values the next step's narrowphase recomputes for a contact with an awake body
// are written as zeros (it keeps only touching, pointCount, the materials, each point's id and
// impulses, and a kept manifold's normal, anchors and pose: manifold_reuse.hpp).
void writeContact(ByteWriter& out, const Contact& contact, bool futureOnly) {
    Contact c = contact;
    if (futureOnly && !c.sensor) {
        if (!c.reuseValid) c.normal = {};
        for (ContactPointState& p : c.points) {
            p.point = {};
            if (!c.reuseValid) p.anchorA = p.anchorB = {};
            p.separation = p.maxNormalImpulse = 0;
        }
    }
    writeFields(out, c);
    for (int i = 0; i < c.pointCount; ++i) writeFields(out, c.points[i]);
}

void readContact(ByteReader& in, Contact& c, int shapeCount) {
    readFields(in, c);
    for (const collide::ChildKey& key : {c.a, c.b})
        if (key.shape < 0 || key.shape >= shapeCount || key.child < 0) in.fail("contact names a missing shape child");
    if (c.pointCount < 0 || c.pointCount > 2) in.fail("contact point count out of range");
    for (int i = 0; i < c.pointCount; ++i) readFields(in, c.points[i]);
    if (c.reuseValid && c.pointCount > 0) rememberReuseRotations(c);
}

// --- pools ---

void writeFreeList(ByteWriter& out, const std::vector<int>& free) {
    out.u32(static_cast<uint32_t>(free.size()));
    for (int i : free) out.i32(i);
}

// A free list must name every dead slot exactly once (the order decides which slot is reused next).
std::vector<int> readFreeList(ByteReader& in, const std::vector<bool>& alive, const char* what) {
    std::vector<int> free(in.count(4, what));
    std::vector<bool> seen(alive.size(), false);
    for (int& i : free) {
        i = in.integer(0, static_cast<int>(alive.size()) - 1, what);
        if (alive[i] || seen[i]) in.fail(std::string(what) + " names a live or repeated slot");
        seen[i] = true;
    }
    if (static_cast<size_t>(std::count(alive.begin(), alive.end(), false)) != free.size())
        in.fail(std::string(what) + " misses dead slots");
    return free;
}

// Relinks body `index`'s contact list in the saved order, checking that every edge belongs to it.
void linkEdges(ByteReader& in, World::Impl& w, int index, std::span<const int> edges, std::vector<bool>& seen) {
    ContactCache& cache = w.contactCache;
    for (int e : edges) {
        const Contact& c = cache.contacts[e >> 1];
        if (!c.alive || seen[e] || ((e & 1) ? c.bodyB : c.bodyA) != index) in.fail("contact list is inconsistent");
        seen[e] = true;
    }
    cache.bodyLists.restore(cache.contacts, index, edges);
}

// What a snapshot holds per slot, read in slot order into one array: slot i's are items[start[i],
// start[i + 1]) (a body's contact edges, a shape's fat AABBs).
template <class T>
struct PerSlot {
    std::vector<T> items;
    std::vector<int> start{0};
    void endSlot() { start.push_back(static_cast<int>(items.size())); }
    std::span<const T> operator[](int slot) const {
        return std::span<const T>(items).subspan(static_cast<size_t>(start[slot]), static_cast<size_t>(start[slot + 1] - start[slot]));
    }
};

// Whether the restoring world's broadphase already is the one a snapshot describes — a rollback
// restores the same shapes, and most steps move no proxy out of its fat AABB: the same shapes
// alive with the same geometry, each child's proxy with the saved fat AABB and tree, and the same
// proxies waiting for pairs in the same order. Reads only. Proxy ids and the tree's shape then
// differ from a rebuilt broadphase's, which changes nothing: pairs are made in child-key order.
bool broadphaseMatches(const World::Impl& old, const World::Impl& w, const PerSlot<AABB>& saved,
                       const std::vector<collide::ChildKey>& moved) {
    if (old.shapes.capacity() != w.shapes.capacity() || old.broadphase.movedProxies.size() != moved.size()) return false;
    for (int i = 0; i < w.shapes.capacity(); ++i) {
        const ShapeData& was = old.shapes[i];
        const ShapeData& is = w.shapes[i];
        if (was.alive != is.alive) return false;
        if (!is.alive) continue;
        if (!(was.geometry == is.geometry) || was.proxies.size() != saved[i].size()) return false;
        const bool isStatic = w.bodies[is.body].type == BodyType::Static;
        for (int child = 0; child < static_cast<int>(was.proxies.size()); ++child)
            if (!old.broadphase.collision.proxyIs(was.proxies[child], saved[i][static_cast<size_t>(child)], {i, child}, isStatic)) return false;
    }
    for (size_t k = 0; k < moved.size(); ++k)
        if (old.broadphase.movedProxies[k] != old.shapes[moved[k].shape].proxies[moved[k].child]) return false;
    return true;
}

// Island rings (bodies that fell asleep together) must be proper cycles, or wake() would not end:
// the links of linked bodies must form a permutation of them.
void checkIslandRings(ByteReader& in, const World::Impl& w) {
    std::vector<bool> targeted(w.bodies.capacity(), false);
    for (const Body& b : w.bodies.slots()) {
        if (b.islandNext < 0) continue;
        const Body& next = w.bodies[b.islandNext];
        if (!b.alive || !next.alive || next.islandNext < 0 || targeted[b.islandNext]) in.fail("island ring is broken");
        targeted[b.islandNext] = true;
    }
}

// End events raised since the last step (a shape or body destroyed between steps): the next step
// reports them. Their ids may be stale, so any values load.
template <class Event>
void writePending(ByteWriter& out, const std::vector<Event>& events, size_t reported) {
    out.u32(static_cast<uint32_t>(events.size() - reported));
    for (size_t i = reported; i < events.size(); ++i) writeFields(out, events[i]);
}

template <class Event>
std::vector<Event> readPending(ByteReader& in) {
    std::vector<Event> events(in.count(16, "pending end event"));
    for (Event& e : events) readFields(in, e);
    return events;
}

}  // namespace

std::vector<uint8_t> World::snapshot() const {
    checkUnlocked(impl_->locked, "snapshot");
    return writeSnapshot(*impl_, false);
}

std::vector<uint8_t> writeSnapshot(const World::Impl& w, bool futureOnly) {
    ByteWriter out;
    for (uint8_t m : magic) out.u8(m);
    out.u32(formatVersion);
    writeFields(out, w.def);
    out.u32(static_cast<uint32_t>(w.frozenBodies));
    out.boolean(w.shapes.anyHitEvents);

    out.u32(static_cast<uint32_t>(w.bodies.capacity()));
    for (int i = 0; i < w.bodies.capacity(); ++i) {
        out.u32(w.bodies[i].generation);
        out.boolean(w.bodies[i].alive);
        if (w.bodies[i].alive) writeBody(out, w, i, futureOnly);
    }
    writeFreeList(out, w.bodies.freeList());

    out.u32(static_cast<uint32_t>(w.shapes.capacity()));
    for (const ShapeData& s : w.shapes.slots()) {
        out.u32(s.generation);
        out.boolean(s.alive);
        if (s.alive) writeShape(out, w, s);
    }
    writeFreeList(out, w.shapes.freeList());

    out.u32(static_cast<uint32_t>(w.contactCache.contacts.capacity()));
    for (const Contact& c : w.contactCache.contacts.slots()) {
        out.boolean(c.alive);
        if (c.alive) writeContact(out, c, futureOnly && (w.bodies[c.bodyA].awake || w.bodies[c.bodyB].awake));
    }
    writeFreeList(out, w.contactCache.contacts.freeList());
    writeJoints(out, *w.joints, w.bodies);

    out.u32(static_cast<uint32_t>(w.broadphase.movedProxies.size()));
    for (int proxy : w.broadphase.movedProxies) {
        const collide::ChildKey key = w.broadphase.collision.proxyKey(proxy);
        out.i32(key.shape);
        out.i32(key.child);
    }
    writePending(out, w.events.contactEnd, w.events.contactEndReported);
    writePending(out, w.events.sensorEnd, w.events.sensorEndReported);
    out.u32(w.identity.issued);  // since format 5: the handles this World issued are valid where it is restored
    return std::move(out.bytes);
}

void World::restore(std::span<const uint8_t> bytes) {
    checkUnlocked(impl_->locked, "restore");
    ByteReader in(bytes);
    for (uint8_t m : magic)
        if (in.u8() != m) in.fail("not a perpdot snapshot (bad magic)");
    in.version = in.u32();
    if (in.version < 1 || in.version > formatVersion)
        in.fail("format version " + std::to_string(in.version) + " is not supported (this build reads versions 1 to " +
                std::to_string(formatVersion) + ")");
    auto fresh = std::make_unique<Impl>(readDef(in));  // one worker: the snapshot holds no threads
    Impl& w = *fresh;
    // A rollback restores again and again: the pools read into the slots of the state the last
    // restore replaced, whose shape and proxy lists then allocate nothing.
    if (const std::unique_ptr<Impl> spare = std::move(impl_->spare)) {
        w.bodies.adoptStorage(std::move(spare->bodies));
        w.shapes.adoptStorage(std::move(spare->shapes));
        w.contactCache.contacts.adoptStorage(std::move(spare->contactCache.contacts));
    }
    w.frozenBodies = in.integer(0, 0x7FFFFFFF, "frozen body count");
    w.shapes.anyHitEvents = in.boolean();

    // Bodies, with their contact lists kept aside until the contacts are read.
    const int bodyCount = in.count(5, "body");
    w.bodies.restoreSlots(bodyCount);
    PerSlot<int> edgesOf;
    std::vector<bool> bodyAlive(bodyCount);
    // Shape and contact counts are not known yet: indices are bounded by the input size, then checked.
    const int indexLimit = static_cast<int>(std::min<size_t>(bytes.size(), 0x3FFFFFFF));
    for (int i = 0; i < bodyCount; ++i) {
        Body& b = w.bodies[i];
        b.generation = in.u32();
        b.alive = bodyAlive[i] = in.boolean();
        if (b.alive) readBody(in, b, edgesOf.items, bodyCount, indexLimit, 2 * indexLimit);
        edgesOf.endSlot();
    }
    w.bodies.restoreFreeList(readFreeList(in, bodyAlive, "free body"));

    const int shapeCount = in.count(5, "shape");
    w.shapes.restoreSlots(shapeCount);
    std::vector<bool> shapeAlive(shapeCount), shapeListed(shapeCount, false);
    PerSlot<AABB> savedProxies;
    for (int i = 0; i < shapeCount; ++i) {
        ShapeData& s = w.shapes[i];
        s.generation = in.u32();
        s.alive = shapeAlive[i] = in.boolean();
        if (!s.alive) {
            savedProxies.endSlot();
            continue;
        }
        const bool holds = i < impl_->shapes.capacity() && impl_->shapes[i].alive;
        readShape(in, s, savedProxies.items, bodyCount, holds ? &impl_->shapes[i] : nullptr);
        savedProxies.endSlot();
        w.shapes.noteFilter(s.filter);
        w.shapes.noteRestitution(s.restitution);
        if (!bodyAlive[s.body]) in.fail("shape " + std::to_string(i) + " belongs to a dead body");
    }
    w.shapes.restoreFreeList(readFreeList(in, shapeAlive, "free shape"));
    for (int i = 0; i < bodyCount; ++i)
        for (int s : w.bodies[i].shapes)
            if (s >= shapeCount || !shapeAlive[s] || w.shapes[s].body != i || shapeListed[s]) in.fail("body shape list is inconsistent");
            else shapeListed[s] = true;
    for (int i = 0; i < shapeCount; ++i)
        if (shapeAlive[i] && !shapeListed[i]) in.fail("shape " + std::to_string(i) + " is missing from its body");

    const int contactCount = in.count(1, "contact");
    w.contactCache.contacts.restoreSlots(contactCount);
    std::vector<bool> contactAlive(contactCount);
    for (int i = 0; i < contactCount; ++i) {
        Contact& c = w.contactCache.contacts[i];
        c.alive = contactAlive[i] = in.boolean();
        if (!c.alive) continue;
        readContact(in, c, shapeCount);
        const auto valid = [&](collide::ChildKey k) {
            return shapeAlive[k.shape] && k.child < static_cast<int>(savedProxies[k.shape].size());
        };
        if (!valid(c.a) || !valid(c.b)) in.fail("contact " + std::to_string(i) + " names a missing shape child");
        const ShapeData& sa = w.shapes[c.a.shape];
        const ShapeData& sb = w.shapes[c.b.shape];
        // The narrowphase needs the pair in Box2D's order and a routine for it.
        if (sa.body == sb.body || !collide::CollisionSystem::canCollide(sa.type, sb.type) ||
            collide::CollisionSystem::mustSwap(sa.type, sb.type))
            in.fail("contact " + std::to_string(i) + " pairs shapes that cannot collide");
        bindShapes(w.contactCache, i, sa, sb, contactSkin(w.def, w.bodies[sa.body].type, w.bodies[sb.body].type));
    }
    w.contactCache.contacts.restoreFreeList(readFreeList(in, contactAlive, "free contact"));
    std::vector<bool> edgeSeen(2 * static_cast<size_t>(contactCount), false);
    for (int i = 0; i < bodyCount; ++i) {
        for (int e : edgesOf[i])
            if (e >= 2 * contactCount) in.fail("contact edge out of range");
        linkEdges(in, w, i, edgesOf[i], edgeSeen);
    }
    for (int i = 0; i < contactCount; ++i)
        if (contactAlive[i] && !(edgeSeen[2 * i] && edgeSeen[2 * i + 1])) in.fail("contact missing from a body's list");
    checkIslandRings(in, w);
    readJoints(in, *w.joints, w.bodies);

    std::vector<collide::ChildKey> moved(in.count(8, "moved proxy"));
    for (collide::ChildKey& key : moved) {
        key.shape = in.integer(0, shapeCount - 1, "moved proxy shape");
        key.child = in.integer(0, 0x7FFFFFFF, "moved proxy child");
        if (!shapeAlive[key.shape] || key.child >= static_cast<int>(savedProxies[key.shape].size()))
            in.fail("moved proxy names a missing shape child");
    }
    if (in.version >= 3) {
        w.events.contactEnd = readPending<ContactEndTouchEvent>(in);
        w.events.sensorEnd = readPending<SensorEndTouchEvent>(in);
    }
    std::optional<uint32_t> snapshotIdentity;
    if (in.version >= 5) {
        snapshotIdentity = in.u32();
        if (*snapshotIdentity == 0) in.fail("world identity 0 is no World's");
    }
    in.expectEnd();

    // Everything is checked: build the geometry and the broadphase — or, when this world's
    // broadphase already is the snapshot's (a rollback), keep it, and this world is not touched
    // before the last check has passed. Built proxies come out of the tree with the saved fat
    // AABBs and, like every new proxy, marked as moved.
    const bool keepBroadphase = broadphaseMatches(*impl_, w, savedProxies, moved);
    for (int i = 0; i < shapeCount; ++i) {
        if (!shapeAlive[i]) continue;
        ShapeData& s = w.shapes[i];
        // A shape out of the broadphase (World::setEnabled) has no proxies, one in it one per child.
        const collide::CollisionSystem& geometry = keepBroadphase ? impl_->broadphase.collision : w.broadphase.collision;
        if (!keepBroadphase) std::visit([&](const auto& g) { w.broadphase.collision.setGeometry(i, g); }, s.geometry);
        const bool inBroadphase = s.enabled && w.bodies[s.body].enabled;
        if ((inBroadphase ? geometry.childCount(i) : 0) != static_cast<int>(savedProxies[i].size()))
            in.fail("proxy count does not match the shape");
        if (keepBroadphase) {
            s.proxies = impl_->shapes[i].proxies;
            continue;
        }
        for (int child = 0; child < static_cast<int>(savedProxies[i].size()); ++child)
            s.proxies.push_back(w.broadphase.collision.restoreProxy(savedProxies[i][static_cast<size_t>(child)], {i, child},
                                                         w.bodies[s.body].type == BodyType::Static));
    }
    for (const collide::ChildKey& key : moved) w.broadphase.movedProxies.push_back(w.shapes[key.shape].proxies[key.child]);
    if (!keepBroadphase) {
        std::unordered_set<int> movedSet(w.broadphase.movedProxies.begin(), w.broadphase.movedProxies.end());
        for (const ShapeData& s : w.shapes.slots())
            for (int proxy : s.proxies)
                if (!movedSet.contains(proxy)) w.broadphase.collision.clearMoved(proxy);
    }
    w.contactCache.pairs.reserve(static_cast<size_t>(contactCount));
    for (int i = 0; i < contactCount; ++i) {
        Contact& c = w.contactCache.contacts[i];
        if (!c.alive) continue;
        c.proxyA = w.shapes[c.a.shape].proxies[c.a.child];
        c.proxyB = w.shapes[c.b.shape].proxies[c.b.child];
        c.pairKey = proxyPairKey(c.proxyA, c.proxyB);
        if (!w.contactCache.pairs.insert(c.pairKey)) in.fail("two contacts for one pair");
    }

    if (keepBroadphase) {
        fresh->broadphase.collision = std::move(impl_->broadphase.collision);
        // Its moved proxies are looked for as new ones (restoreProxy's): the boxes they moved from
        // are this world's, not the snapshot's.
        for (int proxy : fresh->broadphase.movedProxies) fresh->broadphase.collision.requery(proxy);
    }
    fresh->preSolve = std::move(impl_->preSolve);  // settings of this World, not of the state
    fresh->jointDestroyed = std::move(impl_->jointDestroyed);
    fresh->shouldCollide = std::move(impl_->shouldCollide);
    // The snapshotted World's identity (ids.hpp): the handles valid when it was taken are valid
    // here, and so are this World's own. A snapshot of format < 5 has none: this World's stays.
    fresh->identity = {.issued = snapshotIdentity.value_or(impl_->identity.issued), .own = impl_->identity.own};
    for (ContactEndTouchEvent& e : fresh->events.contactEnd) e.shapeA.world = e.shapeB.world = fresh->identity.issued;
    for (SensorEndTouchEvent& e : fresh->events.sensorEnd) e.sensorShape.world = e.visitorShape.world = fresh->identity.issued;
    // The threads are the restoring machine's, not the snapshot's: the world keeps its own workers.
    fresh->def.workerCount = impl_->def.workerCount;
    fresh->def.enqueueTask = impl_->def.enqueueTask;
    fresh->def.finishTask = impl_->def.finishTask;
    fresh->def.userTaskContext = impl_->def.userTaskContext;
    fresh->workers = std::move(impl_->workers);
    // The step's working arrays hold nothing between steps but their capacity: keeping this
    // world's, a rollback's next step reallocates nothing.
    fresh->scratch = std::move(impl_->scratch);
    fresh->broadphase.boxRooms = std::move(impl_->broadphase.boxRooms);  // its memory; no body's boxes are measured yet
    fresh->broadphase.boxRooms.assign(fresh->broadphase.boxRooms.size(), BoxRoom{});
    impl_->events.assignKeepingCapacity(fresh->events);
    fresh->events = std::move(impl_->events);
    fresh->contactCache.newPairs = std::move(impl_->contactCache.newPairs);
    fresh->contactCache.newPairsOf = std::move(impl_->contactCache.newPairsOf);
    fresh->contactCache.queried = std::move(impl_->contactCache.queried);
    fresh->contactCache.groupStarts = std::move(impl_->contactCache.groupStarts);
    fresh->contactCache.mortonOrder = std::move(impl_->contactCache.mortonOrder);
    fresh->contactCache.mortonScratch = std::move(impl_->contactCache.mortonScratch);
    fresh->contactCache.narrowphase = std::move(impl_->contactCache.narrowphase);
    fresh->contactCache.unquiet = std::move(impl_->contactCache.unquiet);
    fresh->contactCache.apart = std::move(impl_->contactCache.apart);  // (updateContacts clears it)
    // Moved proxies are state, but the frames re-simulated after a rollback move as many as this
    // world's did: room for them.
    fresh->broadphase.movedProxies.reserve(impl_->broadphase.movedProxies.capacity());
    fresh->spare = std::move(impl_);
    impl_ = std::move(fresh);
}

}  // namespace perpdot
