// The default workers are a oneTBB task arena (Debian's libtbb-dev); a game's job system replaces it.
#include "core/threads/workers.hpp"

#include <algorithm>

#include <tbb/blocked_range.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <tbb/task_group.h>

#include "perpdot/error.hpp"

namespace perpdot {

// More threads than the machine runs at once would only take turns: the arena asks for no more.
// Workers beyond it still take part (SolverStages), one after another.
struct Workers::Arena {
    tbb::task_arena arena;
    tbb::task_group aside;  // runAside's task: spawned into the arena, taken by an idle worker
    explicit Arena(int workers) : arena(std::min(workers, tbb::info::default_concurrency())) {}
};

Workers::Workers(const WorldDef& def)
    : count_(def.workerCount), enqueue_(def.enqueueTask), finish_(def.finishTask), userContext_(def.userTaskContext) {
    if (def.workerCount < 1 || def.workerCount > 256) throw Error("WorldDef.workerCount must be 1..256");
    if ((enqueue_ == nullptr) != (finish_ == nullptr))
        throw Error("WorldDef.enqueueTask and WorldDef.finishTask must be given together");
    if (count_ > 1 && enqueue_ == nullptr) arena_ = std::make_unique<Arena>(count_);
}

Workers::~Workers() = default;
Workers::Workers(Workers&&) noexcept = default;
Workers& Workers::operator=(Workers&&) noexcept = default;

void Workers::run(TaskFn* task, int itemCount, int minRange, void* context) {
    if (enqueue_ != nullptr) {
        if (void* handle = enqueue_(task, itemCount, minRange, context, userContext_)) finish_(handle, userContext_);
        return;
    }
    arena_->arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<int>(0, itemCount, minRange), [&](const tbb::blocked_range<int>& r) {
            task(r.begin(), r.end(), tbb::this_task_arena::current_thread_index(), context);
        });
    });
}

void Workers::runAside(TaskFn* task, void* context) {
    if (count_ == 1) {
        task(0, 1, 0, context);
        return;
    }
    aside_ = true;
    if (enqueue_ != nullptr)
        asideHandle_ = enqueue_(task, 1, 1, context, userContext_);  // nullptr: it ran inside
    else
        arena_->arena.execute([&] { arena_->aside.run([task, context] { task(0, 1, 0, context); }); });
}

// Waiting in the arena: a task no worker took yet runs here.
void Workers::awaitAside() {
    if (!aside_) return;
    aside_ = false;
    if (enqueue_ == nullptr)
        arena_->arena.execute([&] { arena_->aside.wait(); });
    else if (asideHandle_ != nullptr)
        finish_(asideHandle_, userContext_);
    asideHandle_ = nullptr;
}

}  // namespace perpdot
