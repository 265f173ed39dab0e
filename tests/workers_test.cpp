// Threads (WorldDef::workerCount, the task interface): the world after N steps is bit-identical
// for every worker count and for a game's own task system, whichever way it splits the work; a
// restored world keeps its threads; bad settings are refused; a parallel selection keeps store
// order for any worker count.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <thread>
#include <vector>

#include "core/threads/workers.hpp"
#include "perpdot/feature_scenes.hpp"
#include "perpdot/perpdot.hpp"
#include "perpdot/scene.hpp"
#include "perpdot/state_hash.hpp"
#include "scene/build_world.hpp"

namespace perpdot {
namespace {

uint64_t hashAfter(const std::string& sceneName, int steps, int workers) {
    Scene scene = findScene(sceneName);
    scene.steps = steps;
    SceneWorld built = buildWorldWithBehaviour(scene, workers);
    for (int i = 0; i < steps; ++i) built.step();
    return stateHash(built.world);
}

// The scene's world settings (as buildWorld makes them) with the given threads.
WorldDef defOf(const Scene& scene, WorldDef threads) {
    threads.gravity = scene.gravity;
    threads.enableSleep = scene.enableSleep;
    if (scene.solver.substeps) threads.substeps = *scene.solver.substeps;
    threads.box2dSkin = scene.solver.box2dSkin;
    return threads;
}

// Stacks and sleep, joints of every colour and trees, sensors and events, bullets and continuous
// collision, a churning broadphase.
struct HashCase {
    const char* scene;
    int steps;
};
const HashCase hashCases[] = {{"pyramid", 200}, {"ragdoll", 120}, {"car", 150},       {"sensor_zone", 160},
                              {"bullet_wall", 40}, {"tumbler", 150}, {"rain", 200}, {"joint_grid", 30},
                              {"suspension_bridge", 120}, {"dominoes", 200}, {"joint_rack", 60},
                              {"distance_net", 60},
                              {"motor_swarm", 60}};

TEST(Workers, EveryWorkerCountGivesTheSameWorld) {
    for (const HashCase& c : hashCases) {
        const uint64_t one = hashAfter(c.scene, c.steps, 1);
        for (int workers : {2, 3, 4, 8}) EXPECT_EQ(hashAfter(c.scene, c.steps, workers), one) << c.scene << " with " << workers << " workers";
    }
}

// A game's job system: each task starts at once, cut into ranges of exactly minRange items, run by
// `threads` std::threads of its own, the ranges dealt out round-robin in reverse order; a task may
// run while another is enqueued (the step keeps the broadphase's re-fits running beside its loops).
struct GameJobs {
    int threads = 3;
    int tasks = 0;
    struct Running {
        std::vector<std::thread> pool;
    };

    static void* enqueue(TaskFn* fn, int count, int minRange, void* context, void* user) {
        auto* jobs = static_cast<GameJobs*>(user);
        ++jobs->tasks;
        auto* running = new Running;
        const int ranges = (count + minRange - 1) / minRange;
        const int threads = jobs->threads;
        for (int worker = 0; worker < threads; ++worker) {
            running->pool.emplace_back([=] {
                for (int r = ranges - 1 - worker; r >= 0; r -= threads) {
                    const int begin = r * minRange;
                    fn(begin, std::min(begin + minRange, count), worker, context);
                }
            });
        }
        return running;
    }
    static void finish(void* handle, void*) {
        auto* running = static_cast<Running*>(handle);
        for (std::thread& t : running->pool) t.join();
        delete running;
    }
};

// The scene's bodies and joints (no scripted actions) stepped in a world with these threads.
uint64_t plainHash(const HashCase& c, const WorldDef& threads) {
    const Scene scene = findScene(c.scene);
    World world(defOf(scene, threads));
    addToWorld(world, scene);
    for (int i = 0; i < c.steps; ++i) world.step(scene.timestep);
    return stateHash(world);
}

// Every scene on the game's own threads gives the world of one worker. (The CI's ThreadSanitizer
// run is this test: its threads are std::threads, which the sanitizer sees whole, where oneTBB's
// uninstrumented internals would raise false reports.)
TEST(Workers, AGamesTaskSystemGivesTheSameWorld) {
    for (const HashCase& c : hashCases) {
        GameJobs jobs;
        const uint64_t hash = plainHash(c, {.workerCount = jobs.threads, .enqueueTask = &GameJobs::enqueue,
                                            .finishTask = &GameJobs::finish, .userTaskContext = &jobs});
        EXPECT_GE(jobs.tasks, c.steps) << c.scene << ": every step hands it work";
        EXPECT_EQ(hash, plainHash(c, {})) << c.scene;
    }
}

// A task system may run a task at once and return no handle.
TEST(Workers, ATaskRunInsideEnqueueIsFinished) {
    auto inline_ = [](TaskFn* fn, int count, int, void* context, void*) -> void* {
        fn(0, count, 0, context);
        return nullptr;
    };
    auto never = [](void*, void*) { FAIL() << "finishTask called without a handle"; };
    Scene scene = findScene("ragdoll");
    World world(defOf(scene, {.workerCount = 4, .enqueueTask = +inline_, .finishTask = +never}));
    addToWorld(world, scene);
    for (int i = 0; i < 120; ++i) world.step(scene.timestep);
    EXPECT_EQ(stateHash(world), hashAfter("ragdoll", 120, 1));
}

// Workers::parallelSelect: the kept items in store order, each written once, whatever the
// worker count and wherever the 1024-item blocks end.
TEST(Workers, AParallelSelectionKeepsTheItemsInOrder) {
    for (int workerCount : {1, 2, 3}) {
        Workers workers(WorldDef{.workerCount = workerCount});
        for (int n : {0, 1, 1023, 1024, 1025, 5000}) {
            auto keep = [](int i) { return i % 3 == 0 || i % 7 == 1; };
            std::vector<int> selected(7, -2);  // resized by reserve: stale entries must be overwritten
            const int total = workers.parallelSelect(n, keep, [&](int count) { selected.assign(count, -1); },
                                                     [&](int slot, int i) { selected[slot] = i; });
            std::vector<int> expected;
            for (int i = 0; i < n; ++i)
                if (keep(i)) expected.push_back(i);
            EXPECT_EQ(total, static_cast<int>(expected.size())) << n << " items, " << workerCount << " workers";
            EXPECT_EQ(selected, expected) << n << " items, " << workerCount << " workers";
        }
    }
}

TEST(Workers, BadSettingsAreRefused) {
    EXPECT_THROW(World(WorldDef{.workerCount = 0}), Error);
    EXPECT_THROW(World(WorldDef{.workerCount = 257}), Error);
    auto enqueue = [](TaskFn*, int, int, void*, void*) -> void* { return nullptr; };
    EXPECT_THROW(World(WorldDef{.workerCount = 2, .enqueueTask = +enqueue}), Error);
}

// A snapshot holds no threads: the restoring world keeps its own, and its future is the same.
TEST(Workers, ARestoredWorldKeepsItsWorkers) {
    Scene scene = findScene("pyramid");
    SceneWorld threaded = buildWorld(scene, 2);
    for (int i = 0; i < 100; ++i) threaded.step();
    const std::vector<uint8_t> saved = threaded.world.snapshot();
    threaded.world.restore(saved);
    EXPECT_EQ(threaded.world.settings().workerCount, 2);
    for (int i = 0; i < 100; ++i) threaded.step();
    EXPECT_EQ(stateHash(threaded.world), hashAfter("pyramid", 200, 1));
}

}  // namespace
}  // namespace perpdot
