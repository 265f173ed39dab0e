// The threads that run the step's parallel stages: a oneTBB arena of WorldDef::workerCount
// threads by default, or the game's own job system through WorldDef::enqueueTask/finishTask.
// With one worker every loop runs inline on the caller's thread.
//
// Every parallel loop of the step writes only to its own items' outputs, so its result does not
// depend on how the items are split or which thread runs them: the world is bit-identical for
// any worker count.
#pragma once

#include <memory>

#include "perpdot/world.hpp"

namespace perpdot {

class Workers {
public:
    explicit Workers(const WorldDef& def);
    ~Workers();
    Workers(Workers&&) noexcept;
    Workers& operator=(Workers&&) noexcept;

    int count() const { return count_; }

    // fn(begin, end, worker) over [0, itemCount) in ranges of about `minRange` items or more;
    // returns when every item has run.
    template <class Fn>
    void parallelFor(int itemCount, int minRange, const Fn& fn) {
        if (itemCount <= 0) return;
        if (count_ == 1 || itemCount <= minRange) {
            fn(0, itemCount, 0);
            return;
        }
        run(&call<Fn>, itemCount, minRange, const_cast<Fn*>(&fn));
    }

private:
    template <class Fn>
    static void call(int begin, int end, int worker, void* fn) {
        (*static_cast<const Fn*>(fn))(begin, end, worker);
    }
    void run(TaskFn* task, int itemCount, int minRange, void* context);

    int count_ = 1;
    EnqueueTaskFn* enqueue_ = nullptr;
    FinishTaskFn* finish_ = nullptr;
    void* userContext_ = nullptr;
    struct Arena;  // oneTBB, when the game brings no job system
    std::unique_ptr<Arena> arena_;
};

}  // namespace perpdot
