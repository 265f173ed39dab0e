// The persistent contact cache (contact_cache.cpp): a contact for each broadphase pair of shape
// children that may touch, with its manifold and the accumulated impulses that warm-start the next
// step, found by updatePairs and kept up to date by updateContacts.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "collide/collision.hpp"
#include "collide/pair_set.hpp"
#include "core/bodies/edge_list.hpp"
#include "core/base/pool.hpp"
#include "perpdot/world.hpp"

namespace perpdot {

// A hit: a body at least hitRatio times heavier than the body it strikes. A fast one stops at the
// struck body's surface at the end of its step (continuous.cpp, solveStrikes), and a contact point
// closing on a jointed struck body solves its joints' rows with its contacts (contact_groups.cpp).
inline constexpr float hitRatio = 10;

// A manifold point, the fields the solver reads and writes first (prefetchSolverFields).
struct ContactPointState {
    Vec2 anchorA, anchorB;  // from each body's centre of mass to the point
    float separation = 0;
    float normalImpulse = 0, tangentImpulse = 0, maxNormalImpulse = 0;
    Vec2 point;  // world, at the last narrowphase
    uint32_t id = 0;
    float baseSeparation = 0;  // at the last narrowphase, for a kept manifold (manifold_reuse.hpp)
};

struct Contact {
    bool alive = false;
    bool touching = false;     // has manifold points and takes part in the solve (never for sensors)
    bool sensor = false;       // a sensor and a visitor: overlap test only, no constraint
    bool overlapping = false;  // sensor contacts: the shapes overlap
    // Whether the contact point is a point of A's (B's) body, turning with it: a surface without
    // rounding (the rows' turnsA, turnsB). Set from the shapes by bindShapes.
    bool turnsA = false, turnsB = false;
    ShapeType typeA = ShapeType::Circle, typeB = ShapeType::Circle;  // the shapes' (their skins), from bindShapes
    uint64_t pairKey = 0;
    int proxyA = -1, proxyB = -1;
    collide::ChildKey a, b;
    int bodyA = -1, bodyB = -1;
    float friction = 0, restitution = 0;
    float rollingResistance = 0, tangentSpeed = 0;
    float rollingImpulse = 0;  // warm start of the rolling-resistance row
    Vec2 normal;
    int pointCount = 0;
    // A support row's rest sink, low-passed: how much deeper its points are solved (support_sinks.hpp);
    // 0 once the pair parts. Between the runs the solver gathers, in the lines it loads for them.
    float restSink = 0;
    ContactPointState points[2];
    // The pose at the last narrowphase (manifold_reuse.hpp): B's centre in A's frame, both angles,
    // and their rotations R(θ) (derived from the angles, not saved: snapshot.cpp derives them again).
    bool reuseValid = false;
    // Where its separations are measured (contactSkin), from bindShapes; beside the pose the
    // narrowphase reads, in the padding before reuseOffset.
    collide::Skin skin = collide::Skin::Kept;
    Vec2 reuseOffset;
    float reuseAngleA = 0, reuseAngleB = 0;
    Rot reuseRotA, reuseRotB;
    Edge edges[2];  // in bodyA's list (side 0) and bodyB's (side 1): ContactCache::bodyLists
};

// Starts loading the lines of a contact that the solver reads and writes, from its friction to
// its last point's impulses (112 bytes), for reading (0) or writing (1): a block's lanes ask for
// theirs together, so that the misses overlap. The first byte and the 64th lie in two lines in a
// row, the last byte in the third if there is one.
template <int forWrite>
inline void prefetchSolverFields(const Contact& c) {
    constexpr std::size_t first = offsetof(Contact, friction);
    constexpr std::size_t end = offsetof(Contact, points) + sizeof(ContactPointState) + offsetof(ContactPointState, point);
    static_assert(end - first > 64 && end - first <= 128, "the solver's fields span two or three lines");
    const auto* bytes = reinterpret_cast<const char*>(&c);
    __builtin_prefetch(bytes + first, forWrite);
    __builtin_prefetch(bytes + first + 64, forWrite);
    __builtin_prefetch(bytes + end - 1, forWrite);
}

struct ShapeData;
struct ShapeStore;  // shape_store.hpp

// Identity of a broadphase pair in ContactCache::pairs (never 0: the two proxies differ).
inline uint64_t proxyPairKey(int proxyA, int proxyB) {
    const auto lo = static_cast<uint32_t>(std::min(proxyA, proxyB));
    const auto hi = static_cast<uint32_t>(std::max(proxyA, proxyB));
    return (static_cast<uint64_t>(lo) << 32) | hi;
}

// A pair found by the broadphase this step, child keys in order (a < b).
struct NewPair {
    collide::ChildKey a, b;
    int proxyA = -1, proxyB = -1;
};

// What the narrowphase of a contact found: not run (both bodies asleep), the fat AABBs apart, a
// sensor's overlap, or a contact's manifold updated and whether it touched before.
// Quiet: collided by the workers, and nothing is left for updateContacts' one-by-one pass.
enum class Narrowphase : uint8_t { Skipped, Apart, Overlapping, Separate, WasTouching, WasNotTouching, Quiet };

struct ContactCache {
    Pool<Contact> contacts;
    EdgeList bodyLists;      // each body's contacts
    collide::PairSet pairs;  // broadphase pairs that have a contact
    std::vector<NewPair> newPairs;                 // updatePairs scratch: the pairs found,
    std::vector<std::vector<NewPair>> newPairsOf;  // by each worker
    // updatePairs scratch: the moved proxies that look for pairs, in groups that share a tree
    // query (group g is queried[groupStarts[g], groupStarts[g + 1])).
    std::vector<int> queried, groupStarts;
    std::vector<std::pair<uint32_t, int>> mortonOrder, mortonScratch;  // (code, proxy), sorted by code
    std::vector<Narrowphase> narrowphase;          // updateContacts scratch, by contact,
    std::vector<int> unquiet;                      // and the contacts it has more to do for, in pool order;
    std::vector<int> apart;                        // of those, the ones whose boxes parted (releaseApartContacts)
    int beganTouching = 0;                         // of those, how many began touching (seedSupportLoads looks only then)
    // By contact slot, what updateContacts passes over contacts whose bodies both sleep with, and
    // markTouching and selectContacts select constraints by, without reading the contacts' cache
    // lines (a pool of 58,000 contacts is 13 MB): its two bodies (they never change) and the
    // manifold points of a touching contact (0: free or not touching). bindShapes sets both as a
    // contact is created or restored; updateContacts keeps the points in step with the contact
    // (a sleeping contact's do not change) and zeroes a free slot's.
    std::vector<std::array<int, 2>> bodiesOf;
    std::vector<uint8_t> touchingPoints;
};

// The stages that find, collide and destroy contacts take the contact stages' view of the world
// (contact_world.hpp).
// The contacts updateContacts found apart (their fat AABBs no longer overlap), which it reported
// ended and left out of the solve, leave the pool, the pair set and their bodies' lists, in pool
// order: serial work that no stage reads before the next updatePairs, done on the worker that
// re-fits the tree (refit_ahead.cpp) beside the solve.
void releaseApartContacts(ContactCache& cache);
// Where a contact's separations are measured (collide::Skin): Box2D's skins on WorldDef::box2dSkin;
// else a pair with a static or kinematic body keeps keptSkin of each skin as a rest gap, so a body
// slides over the seams between separate pieces of ground or platform; two dynamic bodies rest on
// their true surfaces, so a stack of n boxes stands n rest gaps no taller than built.
collide::Skin contactSkin(const WorldDef& def, BodyType a, BodyType b);
// What a contact takes from its two shapes for its whole life: their bodies, types, whether its
// points turn with them (a shape's geometry never changes) and `skin`, contactSkin of its bodies
// (a body that changes type ends its contacts).
void bindShapes(ContactCache& cache, int contact, const ShapeData& a, const ShapeData& b, collide::Skin skin);

// Box2D's mixing rules, so cross-checks compare like with like.
inline float mixFriction(float a, float b) { return std::sqrt(a * b); }
inline float mixRestitution(float a, float b) { return std::max(a, b); }

// A contact's friction, restitution, rolling resistance and tangent speed, mixed from its shapes'
// as it is created, and again for the contacts of a shape whose material changes
// (remixMaterials): the narrowphase reads no shape of a contact with points.
void mixMaterials(Contact& c, const ShapeData& a, const ShapeData& b);
void remixMaterials(ContactCache& cache, const ShapeStore& shapes, int shape);

}  // namespace perpdot
