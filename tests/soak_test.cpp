// Soak: a bucket that is fed new bodies and emptied of old ones every step, for 5,000 steps in CI
// (PERPDOT_SOAK_STEPS=100000 for the full run of docs/reliability.md). Asserts no NaN ever, no
// frozen body, and pools whose size levels off: slots are reused, so memory is bounded.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <deque>

#include <gtest/gtest.h>

#include "perpdot/world.hpp"

namespace perpdot {
namespace {

// A small deterministic generator (the soak must be reproducible).
struct Lcg {
    uint32_t state = 12345u;
    float uniform() {  // [0, 1)
        state = state * 1664525u + 1013904223u;
        return static_cast<float>(state >> 8) / 16777216.0f;
    }
};

int soakSteps() {
    const char* text = std::getenv("PERPDOT_SOAK_STEPS");
    return text ? std::atoi(text) : 5000;
}

TEST(Soak, CreatingAndDestroyingBodiesForThousandsOfStepsKeepsPoolsBoundedAndStateFinite) {
    World world;
    const BodyId bucket = world.createBody({.type = BodyType::Static});
    world.createShape(bucket, {}, makeBox(6.0f, 0.5f, {0, -0.5f}));
    world.createShape(bucket, {}, makeBox(0.5f, 5.0f, {-6.5f, 4.0f}));
    world.createShape(bucket, {}, makeBox(0.5f, 5.0f, {6.5f, 4.0f}));
    const Vec2 triangle[] = {{-0.3f, -0.25f}, {0.3f, -0.25f}, {0.0f, 0.35f}};

    constexpr size_t maxLive = 120;  // the bucket holds about this many before the oldest go
    Lcg random;
    std::deque<BodyId> live;
    WorldStats peak;
    const int steps = soakSteps();
    for (int step = 0; step < steps; ++step) {
        // Two new bodies a step, dropped at random places with a random spin.
        for (int k = 0; k < 2; ++k) {
            const Vec2 at{-5.0f + 10.0f * random.uniform(), 9.0f + 2.0f * random.uniform()};
            const BodyId b = world.createBody({.type = BodyType::Dynamic, .position = at, .angularVelocity = 4.0f * random.uniform() - 2.0f});
            const float pick = random.uniform();
            if (pick < 0.33f) world.createShape(b, {.restitution = 0.3f}, Circle{{0, 0}, 0.2f + 0.2f * random.uniform()});
            else if (pick < 0.66f) world.createShape(b, {}, makeBox(0.2f + 0.2f * random.uniform(), 0.2f + 0.2f * random.uniform()));
            else world.createShape(b, {.friction = 0.3f}, makePolygon(triangle));
            live.push_back(b);
        }
        // The oldest go when the bucket is full; now and then one from the middle of the pile.
        while (live.size() > maxLive) {
            world.destroyBody(live.front());
            live.pop_front();
        }
        if (random.uniform() < 0.1f) {
            const size_t victim = static_cast<size_t>(random.uniform() * static_cast<float>(live.size()));
            world.destroyBody(live[victim]);
            live.erase(live.begin() + static_cast<std::ptrdiff_t>(victim));
        }
        world.step(1.0f / 60.0f);

        const WorldStats s = world.stats();
        peak.bodySlots = std::max(peak.bodySlots, s.bodySlots);
        peak.shapeSlots = std::max(peak.shapeSlots, s.shapeSlots);
        peak.contactSlots = std::max(peak.contactSlots, s.contactSlots);
        if (step % 50 == 0 || step == steps - 1) {
            for (BodyId b : live) {
                const Vec2 p = world.position(b), v = world.linearVelocity(b);
                ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(v.x) && std::isfinite(v.y) &&
                            std::isfinite(world.angularVelocity(b)))
                    << "step " << step;
                ASSERT_GT(p.y, -2.0f) << "a body fell through the bucket at step " << step;
            }
            ASSERT_EQ(s.frozenBodies, 0) << "step " << step;
            ASSERT_EQ(s.bodies, static_cast<int>(live.size()) + 1);
        }
    }
    // Pools hold the live objects plus freed slots waiting for reuse: bounded by the pile's size,
    // not by the number of bodies ever created (2 × steps).
    EXPECT_LE(peak.bodySlots, static_cast<int>(maxLive) + 3);
    EXPECT_LE(peak.shapeSlots, static_cast<int>(maxLive) + 5);
    EXPECT_LE(peak.contactSlots, 12 * static_cast<int>(maxLive));
    RecordProperty("peak_contact_slots", peak.contactSlots);
}

}  // namespace
}  // namespace perpdot
