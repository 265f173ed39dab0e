// step() allocates nothing in steady state: the solver arrays, contact cache and broadphase
// reuse their storage once the contacts exist, also while contacts keep being created and
// destroyed. Counted by replacing global operator new.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>

#include "perpdot/perpdot.hpp"

// AddressSanitizer owns operator new itself; there the count is skipped.
#if defined(__SANITIZE_ADDRESS__)
#define PERPDOT_COUNT_ALLOCATIONS 0
#else
#define PERPDOT_COUNT_ALLOCATIONS 1
#endif

namespace {
std::atomic<long> allocationCount{0};
}  // namespace

#if PERPDOT_COUNT_ALLOCATIONS
void* operator new(std::size_t size) {
    ++allocationCount;
    if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
    throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
#endif

namespace perpdot {
namespace {

TEST(Allocation, SteppingARestingPyramidAllocatesNothing) {
    if (!PERPDOT_COUNT_ALLOCATIONS) GTEST_SKIP() << "AddressSanitizer replaces operator new";
    World world(WorldDef{.enableSleep = false});
    const BodyId ground = world.createBody({.position = {0.0f, -0.5f}});
    world.createShape(ground, {}, makeBox(20.0f, 0.5f));
    constexpr int rows = 10;
    for (int row = 0; row < rows; ++row) {
        for (int i = 0; i < rows - row; ++i) {
            const float x = static_cast<float>(i) - 0.5f * static_cast<float>(rows - row - 1);
            const BodyId box = world.createBody({.type = BodyType::Dynamic, .position = {x, 0.5f + static_cast<float>(row)}});
            world.createShape(box, {}, makeBox(0.5f, 0.5f));
        }
    }
    // Let every contact form and the pyramid settle, so no new pair appears later.
    for (int i = 0; i < 120; ++i) world.step(1.0f / 60.0f);
    ASSERT_GT(world.contactCount(), rows * rows / 2);

    const long before = allocationCount.load();
    for (int i = 0; i < 120; ++i) world.step(1.0f / 60.0f);
    EXPECT_EQ(allocationCount.load() - before, 0);
}

// The turning walls' fat boxes sweep across the boxes: pairs are found and dropped every step.
TEST(Allocation, ChurningContactsOfATumblerAllocateNothing) {
    if (!PERPDOT_COUNT_ALLOCATIONS) GTEST_SKIP() << "AddressSanitizer replaces operator new";
    SceneWorld tumbler = buildWorld(findScene("tumbler"));
    // Storage grows (geometrically) only when the contact count reaches a new peak; here the last
    // time is near step 1,900, in the third turn (0.5 rad/s).
    for (int i = 0; i < 2400; ++i) tumbler.step();

    const long before = allocationCount.load();
    for (int i = 0; i < 600; ++i) tumbler.step();
    EXPECT_EQ(allocationCount.load() - before, 0);
}

// Bullets ricocheting (e = 1, no gravity) at 300 m/s in a closed 4 m box hit the walls and each
// other every few steps: the continuous-collision scratch (movers, pairs) is reused too.
TEST(Allocation, RicochetingBulletsAllocateNothing) {
    if (!PERPDOT_COUNT_ALLOCATIONS) GTEST_SKIP() << "AddressSanitizer replaces operator new";
    World world(WorldDef{.gravity = {0.0f, 0.0f}, .enableSleep = false});
    const BodyId walls = world.createBody({});
    world.createShape(walls, {}, Chain{{{-2.0f, -2.0f}, {-2.0f, 2.0f}, {2.0f, 2.0f}, {2.0f, -2.0f}}, true});
    for (int k = 0; k < 12; ++k) {
        const float a = 0.7f + 0.5f * static_cast<float>(k);
        const BodyId bullet = world.createBody({.type = BodyType::Dynamic,
                                                .position = {0.3f * static_cast<float>(k % 4) - 0.5f, 0.3f * static_cast<float>(k / 4) - 0.3f},
                                                .linearVelocity = {300.0f * std::cos(a), 300.0f * std::sin(a)},
                                                .bullet = true});
        world.createShape(bullet, {.restitution = 1.0f}, Circle{.radius = 0.05f});
    }
    for (int i = 0; i < 600; ++i) world.step(1.0f / 60.0f);

    const long before = allocationCount.load();
    for (int i = 0; i < 300; ++i) world.step(1.0f / 60.0f);
    EXPECT_EQ(allocationCount.load() - before, 0);
}

}  // namespace
}  // namespace perpdot
