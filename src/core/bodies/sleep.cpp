// Sleeping: bodies joined by touching contacts or joints form islands (union-find); an island
// whose every body has been slower than the tolerances for timeToSleep falls asleep as a whole.
#include <algorithm>
#include <limits>
#include <numeric>

#include "core/base/union_find.hpp"
#include "core/world/stages.hpp"

namespace perpdot {

namespace {

// Box2D 2.4's tolerances.
constexpr float linearSleepTolerance = 0.01f;             // m/s
constexpr float angularSleepTolerance = 2.0f / 180.0f * pi;  // rad/s
constexpr float timeToSleep = 0.5f;                       // s

}  // namespace

void updateSleep(Pool<Body>& bodies, const ContactCache& cache, const JointStore& joints,
                 std::span<const int> awakeBodies, IslandScratch& islands, float h) {
    const size_t n = bodies.capacity();
    bool anySleepy = false;
    for (int i : awakeBodies) {
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
    islands.parent.resize(n);
    std::iota(islands.parent.begin(), islands.parent.end(), 0);

    // Touching contacts and joints join awake dynamic bodies.
    auto join = [&](int a, int b) {
        auto joinable = [&](int body) { return bodies[body].type == BodyType::Dynamic && bodies[body].awake; };
        if (joinable(a) && joinable(b)) unite(islands.parent, a, b);
    };
    cache.contacts.forEachLive([&](int, const Contact& c) {
        if (c.touching) join(c.bodyA, c.bodyB);
    });
    forEachJointPair(
        joints, [](void* context, int a, int b) { (*static_cast<decltype(join)*>(context))(a, b); }, &join);

    // The island sleeps when its least sleepy body has been still long enough. islands.minSleep and
    // islands.head reuse the parent array's index space.
    islands.minSleep.assign(n, std::numeric_limits<float>::max());
    islands.head.assign(n, -1);
    for (int i : awakeBodies) {
        const int root = findRoot(islands.parent, i);
        islands.minSleep[root] = std::min(islands.minSleep[root], bodies[i].sleepTime);
    }
    for (int i : awakeBodies) {
        const int root = findRoot(islands.parent, i);
        if (islands.minSleep[root] < timeToSleep) continue;
        Body& b = bodies[i];
        b.awake = false;
        b.v = {};
        b.w = 0.0f;
        // Thread the island into a ring so that waking any member wakes all.
        if (islands.head[root] < 0) {
            islands.head[root] = i;
            b.islandNext = i;
        } else {
            Body& head = bodies[islands.head[root]];
            b.islandNext = head.islandNext;
            head.islandNext = i;
        }
    }
}

}  // namespace perpdot
