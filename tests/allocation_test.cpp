// step() allocates nothing in steady state: the solver arrays, contact cache, joint rows and
// broadphase reuse their storage once the contacts exist, also while contacts keep being created
// and destroyed. Counted at the C allocator, so Box2D's b2Alloc (malloc, b2DynamicTree's nodes)
// is counted with operator new (libstdc++'s calls malloc):
// - release builds interpose malloc, calloc and realloc in this executable (they count, then call
//   glibc's __libc_* versions); the dynamic linker binds libbox2d's and libstdc++'s calls to them;
// - AddressSanitizer (and ThreadSanitizer) builds cannot interpose (the sanitizer's own malloc must
//   serve every block it later checks and frees), so they count through its allocation hook,
//   __sanitizer_install_malloc_and_free_hooks, which sees malloc, calloc, realloc and new alike.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdlib>

#include "perpdot/perpdot.hpp"
#include "perpdot/scene.hpp"

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define PERPDOT_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define PERPDOT_ASAN 1
#endif
#endif

namespace {
std::atomic<long> allocationCount{0};
}  // namespace

#if defined(PERPDOT_ASAN)
// From <sanitizer/allocator_interface.h>, which gcc does not install (its libasan exports it).
extern "C" int __sanitizer_install_malloc_and_free_hooks(void (*malloc_hook)(const volatile void*, std::size_t),
                                                         void (*free_hook)(const volatile void*));

namespace {
void countAllocation(const volatile void*, std::size_t) { ++allocationCount; }
void ignoreFree(const volatile void*) {}
const bool counting = __sanitizer_install_malloc_and_free_hooks(countAllocation, ignoreFree) != 0;
}  // namespace
#else
extern "C" {
void* __libc_malloc(std::size_t size);
void* __libc_calloc(std::size_t count, std::size_t size);
void* __libc_realloc(void* p, std::size_t size);

void* malloc(std::size_t size) noexcept {
    ++allocationCount;
    return __libc_malloc(size);
}
void* calloc(std::size_t count, std::size_t size) noexcept {
    ++allocationCount;
    return __libc_calloc(count, size);
}
void* realloc(void* p, std::size_t size) noexcept {
    ++allocationCount;
    return __libc_realloc(p, size);
}
}
namespace {
const bool counting = true;
}  // namespace
#endif

namespace perpdot {
namespace {

// Allocations made by `steps` calls of step().
template <class Step>
long allocationsOf(int steps, Step&& step) {
    const long before = allocationCount.load();
    for (int i = 0; i < steps; ++i) step();
    return allocationCount.load() - before;
}

// The counter sees plain malloc (Box2D's b2Alloc), operator new, and a world growing its
// b2DynamicTree past its initial 16 nodes.
TEST(Allocation, CounterSeesMallocAndNew) {
    ASSERT_TRUE(counting) << "the allocation hook was not installed";
    long before = allocationCount.load();
    void* volatile block = std::malloc(16);  // volatile: the compiler may not elide the pair
    EXPECT_EQ(allocationCount.load() - before, 1);
    std::free(block);
    before = allocationCount.load();
    int* volatile number = new int(1);
    delete number;
    EXPECT_EQ(allocationCount.load() - before, 1);

    World world;
    const BodyId ground = world.createBody({});
    before = allocationCount.load();
    for (int i = 0; i < 64; ++i) world.createShape(ground, {}, Circle{{static_cast<float>(3 * i), 0.0f}, 1.0f});
    EXPECT_GT(allocationCount.load() - before, 0);
}

TEST(Allocation, SteppingARestingPyramidAllocatesNothing) {
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
    EXPECT_EQ(allocationsOf(120, [&] { world.step(1.0f / 60.0f); }), 0);
}

// The turning walls' fat boxes sweep across the boxes: pairs are found and dropped every step.
TEST(Allocation, ChurningContactsOfATumblerAllocateNothing) {
    SceneWorld tumbler = buildWorld(findScene("tumbler"));
    // Storage grows (geometrically) only when the contact count reaches a new peak; here the last
    // time is near step 2,750, in the fourth turn (0.5 rad/s); none follows to step 5,400.
    for (int i = 0; i < 3000; ++i) tumbler.step();
    EXPECT_EQ(allocationsOf(600, [&] { tumbler.step(); }), 0);
}

// Joint rows: 40 hinged links swinging (and the ball's contacts), and the 100x100 joint grid.
TEST(Allocation, SwingingChainAllocatesNothing) {
    SceneWorld chain = buildWorld(findScene("chain"));
    ASSERT_GE(chain.world.joints().size(), 40u);
    // The links fold onto each other: the pair and contact storage grows up to its peak (the last
    // time near step 1,950, the most pairs found in one step; none follows to step 3,900).
    for (int i = 0; i < 2000; ++i) chain.step();
    EXPECT_EQ(allocationsOf(600, [&] { chain.step(); }), 0);
}

TEST(Allocation, JointGridAllocatesNothing) {
    SceneWorld grid = buildWorld(findScene("joint_grid"));
    ASSERT_GE(grid.world.joints().size(), 9000u);
    for (int i = 0; i < 10; ++i) grid.step();
    EXPECT_EQ(allocationsOf(20, [&] { grid.step(); }), 0);
}

// Rollback: restore keeps the world's step scratch (the contacts' and the joints' per-step arrays),
// so the first frame re-simulated after a restore allocates nothing either.
TEST(Allocation, AFrameAfterARestoreAllocatesNothing) {
    SceneWorld chain = buildWorld(findScene("chain"));
    for (int i = 0; i < 240; ++i) chain.step();
    const std::vector<uint8_t> saved = chain.world.snapshot();
    for (int i = 0; i < 8; ++i) chain.step();
    chain.world.restore(saved);
    EXPECT_EQ(allocationsOf(1, [&] { chain.step(); }), 0);
}

// With workers (oneTBB): the threads' task storage is reused too.
TEST(Allocation, ThreadedStepsAllocateNothing) {
    for (const char* name : {"pyramid", "joint_grid", "ragdoll_rain"}) {
        SceneWorld scene = buildWorld(findScene(name), 2);
        for (int i = 0; i < 300; ++i) scene.step();
        EXPECT_EQ(allocationsOf(100, [&] { scene.step(); }), 0) << name;
    }
}

// Bullets ricocheting (e = 1, no gravity) at 300 m/s in a closed 4 m box hit the walls and each
// other every few steps: the continuous-collision scratch (movers, pairs) is reused too.
TEST(Allocation, RicochetingBulletsAllocateNothing) {
    World world(WorldDef{.gravity = {0.0f, 0.0f}, .enableSleep = false});
    const BodyId walls = world.createBody({});
    world.createShape(walls, {}, Chain{{{-2.0f, -2.0f}, {-2.0f, 2.0f}, {2.0f, 2.0f}, {2.0f, -2.0f}}, true, ChainSide::Left});
    for (int k = 0; k < 12; ++k) {
        const float a = 0.7f + 0.5f * static_cast<float>(k);
        const BodyId bullet = world.createBody({.type = BodyType::Dynamic,
                                                .position = {0.3f * static_cast<float>(k % 4) - 0.5f, 0.3f * static_cast<float>(k / 4) - 0.3f},
                                                .linearVelocity = {300.0f * std::cos(a), 300.0f * std::sin(a)},
                                                .bullet = true});
        world.createShape(bullet, {.restitution = 1.0f}, Circle{.radius = 0.05f});
    }
    for (int i = 0; i < 600; ++i) world.step(1.0f / 60.0f);
    EXPECT_EQ(allocationsOf(300, [&] { world.step(1.0f / 60.0f); }), 0);
}

}  // namespace
}  // namespace perpdot
