// Sleeping: bodies joined by touching contacts or joints form islands (union-find); an island
// whose every body has been slower than the tolerances for timeToSleep falls asleep as a whole.
#include <algorithm>
#include <limits>
#include <numeric>

#include "core/union_find.hpp"
#include "core/world_impl.hpp"

namespace perpdot {

namespace {

// Box2D 2.4's tolerances.
constexpr float linearSleepTolerance = 0.01f;             // m/s
constexpr float angularSleepTolerance = 2.0f / 180.0f * pi;  // rad/s
constexpr float timeToSleep = 0.5f;                       // s

}  // namespace

void World::Impl::updateSleep(float h) {
    if (!def.enableSleep) return;
    const size_t n = bodies.capacity();
    bool anySleepy = false;
    for (int i : scratch.awakeBodies) {
        Body& b = bodies[i];
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
    scratch.islandParent.resize(n);
    std::iota(scratch.islandParent.begin(), scratch.islandParent.end(), 0);

    auto joinable = [&](int body) { return bodies[body].type == BodyType::Dynamic && bodies[body].awake; };
    contactCache.contacts.forEachLive([&](int, const Contact& c) {
        if (c.touching && joinable(c.bodyA) && joinable(c.bodyB)) unite(scratch.islandParent, c.bodyA, c.bodyB);
    });
    forEachJointPair(
        *this,
        [](void* context, int a, int b) {
            World::Impl& w = *static_cast<World::Impl*>(context);
            auto ok = [&](int i) { return w.bodies[i].type == BodyType::Dynamic && w.bodies[i].awake; };
            if (ok(a) && ok(b)) unite(w.scratch.islandParent, a, b);
        },
        this);

    // The island sleeps when its least sleepy body has been still long enough. islandMinSleep and
    // islandHead reuse the parent array's index space.
    scratch.islandMinSleep.assign(n, std::numeric_limits<float>::max());
    scratch.islandHead.assign(n, -1);
    for (int i : scratch.awakeBodies) {
        const int root = findRoot(scratch.islandParent, i);
        scratch.islandMinSleep[root] = std::min(scratch.islandMinSleep[root], bodies[i].sleepTime);
    }
    for (int i : scratch.awakeBodies) {
        const int root = findRoot(scratch.islandParent, i);
        if (scratch.islandMinSleep[root] < timeToSleep) continue;
        Body& b = bodies[i];
        b.awake = false;
        b.v = {};
        b.w = 0.0f;
        // Thread the island into a ring so that waking any member wakes all.
        if (scratch.islandHead[root] < 0) {
            scratch.islandHead[root] = i;
            b.islandNext = i;
        } else {
            Body& head = bodies[scratch.islandHead[root]];
            b.islandNext = head.islandNext;
            head.islandNext = i;
        }
    }
}

}  // namespace perpdot
