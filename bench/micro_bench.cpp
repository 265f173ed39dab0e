// Micro-benchmarks: narrowphase per pair, the solver per contact row, broadphase re-fitting,
// snapshot capture and restore for rollback.
//   build/bench/perpdot-microbench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <vector>

#include "collide/collision.hpp"
#include "perpdot/perpdot.hpp"

namespace perpdot {
namespace {

// b2CollidePolygons through the adapter: two 1 m boxes resting on each other, slightly turned.
void BM_NarrowphaseBoxBox(benchmark::State& state) {
    collide::CollisionSystem collision;
    collision.setGeometry(0, makeBox(0.5f, 0.5f));
    collision.setGeometry(1, makeBox(0.5f, 0.5f));
    const Transform a{{0.0f, 0.5f}, Rot::fromAngle(0.01f)};
    const Transform b{{0.1f, 1.49f}, Rot::fromAngle(-0.02f)};
    for (auto _ : state) {
        collide::Manifold m = collision.collide({0, 0}, a, {1, 0}, b, collide::Skin::Kept);
        benchmark::DoNotOptimize(m);
    }
}
BENCHMARK(BM_NarrowphaseBoxBox);

// A pyramid of 1 m boxes on a static ground, sleep off, settled for 120 steps.
World settledPyramid(int rows, int substeps, int workerCount = 1) {
    World world(WorldDef{.substeps = substeps, .enableSleep = false, .workerCount = workerCount});
    const BodyId ground = world.createBody({.position = {0.0f, -0.5f}});
    world.createShape(ground, {}, makeBox(30.0f, 0.5f));
    for (int row = 0; row < rows; ++row)
        for (int i = 0; i < rows - row; ++i) {
            const float x = static_cast<float>(i) - 0.5f * static_cast<float>(rows - row - 1);
            const BodyId box = world.createBody({.type = BodyType::Dynamic, .position = {x, 0.5f + static_cast<float>(row)}});
            world.createShape(box, {}, makeBox(0.5f, 0.5f));
        }
    for (int i = 0; i < 120; ++i) world.step(1.0f / 60.0f);
    return world;
}

// A settled 20-row pyramid stepped with 1, 2, 4 and 8 substeps: the cost that grows with the
// substep count is the contact solver's (solve + relax per substep); items = contact rows solved.
void BM_PyramidStep(benchmark::State& state) {
    const int substeps = static_cast<int>(state.range(0));
    World world = settledPyramid(20, substeps);
    const int contacts = world.contactCount();
    for (auto _ : state) world.step(1.0f / 60.0f);
    state.SetItemsProcessed(state.iterations() * contacts * substeps);
    state.counters["contacts"] = contacts;
}
BENCHMARK(BM_PyramidStep)->Arg(1)->Arg(2)->Arg(4)->Arg(8)->Unit(benchmark::kMicrosecond);

// Broadphase update: 5,000 proxies each nudged a little (most stay inside their fat AABB) and
// every 16th moved a whole metre (re-inserted), then the moved ones queried for overlaps.
void BM_BroadphaseUpdate(benchmark::State& state) {
    collide::CollisionSystem collision;
    constexpr int count = 5000;
    std::vector<int> proxies;
    std::vector<Transform> xf(count);
    for (int i = 0; i < count; ++i) {
        collision.setGeometry(i, makeBox(0.5f, 0.5f));
        xf[i] = {{static_cast<float>(i % 100) * 1.1f, static_cast<float>(i / 100) * 1.1f}, {}};
        proxies.push_back(collision.createProxy(collision.computeAABB(i, 0, xf[i]), {i, 0}, false));
    }
    float sign = 1.0f;
    for (auto _ : state) {
        int overlaps = 0;
        sign = -sign;
        for (int i = 0; i < count; ++i) {
            const Vec2 d{sign * (i % 16 == 0 ? 1.0f : 0.01f), 0.0f};
            xf[i].p += d;
            if (collision.moveProxy(proxies[i], collision.computeAABB(i, 0, xf[i]), d))
                collision.query(collision.fatAABB(proxies[i]), [&](int) { ++overlaps; return true; });
        }
        benchmark::DoNotOptimize(overlaps);
    }
    state.SetItemsProcessed(state.iterations() * count);
}
BENCHMARK(BM_BroadphaseUpdate)->Unit(benchmark::kMicrosecond);

// Rollback on an 820-box pyramid (40 rows, every body awake, about 1,600 touching contacts).
// Args {compact, workers}: full snapshots (0) or compact ones against a baseline taken 8 steps
// before (1), on 1 or 2 workers (the re-simulated frames use them).
// Capture: the snapshot of the current state. Restore: restore it. Rollback: restore, then
// re-simulate 8 frames (the netcode case). bytes_per_body = snapshot bytes / awake bodies.
struct RollbackFixture {
    World world;
    std::vector<uint8_t> baseline, saved;
    bool compact;
    explicit RollbackFixture(const benchmark::State& state)
        : world(settledPyramid(40, 4, static_cast<int>(state.range(1)))), compact(state.range(0) == 1) {
        baseline = world.baselineSnapshot();
        for (int i = 0; i < 8; ++i) world.step(1.0f / 60.0f);
        saved = capture();
    }
    std::vector<uint8_t> capture() const { return compact ? world.compactSnapshot(baseline) : world.snapshot(); }
    void restore() {
        if (compact) world.restoreCompact(baseline, saved);
        else world.restore(saved);
    }
    void count(benchmark::State& state) const {
        state.counters["bytes_per_body"] = static_cast<double>(saved.size()) / (world.bodyCount() - 1);
        state.counters["bytes"] = static_cast<double>(saved.size());
    }
};

void BM_SnapshotCapture(benchmark::State& state) {
    RollbackFixture f(state);
    for (auto _ : state) benchmark::DoNotOptimize(f.capture());
    f.count(state);
}
BENCHMARK(BM_SnapshotCapture)->Args({0, 1})->Args({1, 1})->Unit(benchmark::kMicrosecond);

void BM_SnapshotRestore(benchmark::State& state) {
    RollbackFixture f(state);
    for (auto _ : state) f.restore();
    f.count(state);
}
BENCHMARK(BM_SnapshotRestore)->Args({0, 1})->Args({1, 1})->Unit(benchmark::kMicrosecond);

void BM_RollbackRestoreAnd8Frames(benchmark::State& state) {
    RollbackFixture f(state);
    for (auto _ : state) {
        f.restore();
        for (int i = 0; i < 8; ++i) f.world.step(1.0f / 60.0f);
    }
    f.count(state);
}
BENCHMARK(BM_RollbackRestoreAnd8Frames)->ArgsProduct({{0, 1}, {1, 2}})->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace perpdot
