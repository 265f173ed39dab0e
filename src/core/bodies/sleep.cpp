// Sleeping: bodies joined by touching contacts or joints form islands (union-find); an island
// whose every body has been slower than the tolerances for timeToSleep falls asleep as a whole.
#include <algorithm>
#include <limits>
#include <numeric>

#include "core/world/stages.hpp"
#include "core/base/union_find.hpp"

namespace perpdot {

namespace {

// Box2D 2.4's tolerances.
constexpr float linearSleepTolerance = 0.01f;             // m/s
constexpr float angularSleepTolerance = 2.0f / 180.0f * pi;  // rad/s
constexpr float timeToSleep = 0.5f;                       // s

}  // namespace

void updateSleep(World::Impl& w, float h) {
    if (!w.def.enableSleep) return;
    const size_t n = w.bodies.capacity();
    bool anySleepy = false;
    for (int i : w.scratch.bodies.awakeBodies) {
        Body& b = w.bodies[i];
        if (!b.allowSleep || b.w * b.w > angularSleepTolerance * angularSleepTolerance ||
            dot(b.v, b.v) > linearSleepTolerance * linearSleepTolerance) {
            b.sleepTime = 0.0f;
        } else {
            b.sleepTime += h;
            anySleepy = anySleepy || b.sleepTime >= timeToSleep;
        }
    }
    if (!anySleepy) return;

    // Every body starts as its own island, those woken after the step's integration (by a broken
    // joint) too: they are awake but not among awakeBodies, and no value of an earlier step is read.
    w.scratch.islands.parent.resize(n);
    std::iota(w.scratch.islands.parent.begin(), w.scratch.islands.parent.end(), 0);

    auto joinable = [&](int body) { return w.bodies[body].type == BodyType::Dynamic && w.bodies[body].awake; };
    w.contactCache.contacts.forEachLive([&](int, const Contact& c) {
        if (c.touching && joinable(c.bodyA) && joinable(c.bodyB)) unite(w.scratch.islands.parent, c.bodyA, c.bodyB);
    });
    forEachJointPair(
        *w.joints,
        [](void* context, int a, int b) {
            World::Impl& world = *static_cast<World::Impl*>(context);
            auto ok = [&](int i) { return world.bodies[i].type == BodyType::Dynamic && world.bodies[i].awake; };
            if (ok(a) && ok(b)) unite(world.scratch.islands.parent, a, b);
        },
        &w);

    // The island sleeps when its least sleepy body has been still long enough. islands.minSleep and
    // islands.head reuse the parent array's index space.
    w.scratch.islands.minSleep.assign(n, std::numeric_limits<float>::max());
    w.scratch.islands.head.assign(n, -1);
    for (int i : w.scratch.bodies.awakeBodies) {
        const int root = findRoot(w.scratch.islands.parent, i);
        w.scratch.islands.minSleep[root] = std::min(w.scratch.islands.minSleep[root], w.bodies[i].sleepTime);
    }
    for (int i : w.scratch.bodies.awakeBodies) {
        const int root = findRoot(w.scratch.islands.parent, i);
        if (w.scratch.islands.minSleep[root] < timeToSleep) continue;
        Body& b = w.bodies[i];
        b.awake = false;
        b.v = {};
        b.w = 0.0f;
        // Thread the island into a ring so that waking any member wakes all.
        if (w.scratch.islands.head[root] < 0) {
            w.scratch.islands.head[root] = i;
            b.islandNext = i;
        } else {
            Body& head = w.bodies[w.scratch.islands.head[root]];
            b.islandNext = head.islandNext;
            head.islandNext = i;
        }
    }
}

}  // namespace perpdot
