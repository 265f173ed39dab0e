// The threads that run the step's parallel stages: a oneTBB arena of WorldDef::workerCount
// threads by default, or the game's own job system through WorldDef::enqueueTask/finishTask.
// With one worker every loop runs inline on the caller's thread.
//
// Every parallel loop of the step writes only to its own items' outputs, so its result does not
// depend on how the items are split or which thread runs them: the world is bit-identical for
// any worker count.
#pragma once

#include <algorithm>
#include <memory>
#include <vector>

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

    // The items of [0, itemCount) that keep(i) keeps, in order, on the workers: each block of
    // selectBlock items counts what it keeps, the counts' prefix sums give every block its place,
    // then reserve(total) sizes the output once and write(k, i) fills slot k with item i, blocks
    // side by side. keep runs twice per item and must give the same answer both times. Returns
    // the total. The slots do not depend on the split: the output is the same for any worker count.
    template <class Keep, class Reserve, class Write>
    int parallelSelect(int itemCount, const Keep& keep, const Reserve& reserve, const Write& write) {
        const int blocks = (itemCount + selectBlock - 1) / selectBlock;
        blockOffsets_.resize(static_cast<size_t>(blocks) + 1);  // grows to the largest pool, then stays
        blockOffsets_[0] = 0;
        parallelFor(blocks, 1, [&](int begin, int end, int) {
            for (int b = begin; b < end; ++b) {
                int kept = 0;
                for (int i = b * selectBlock, last = std::min(i + selectBlock, itemCount); i < last; ++i)
                    kept += keep(i) ? 1 : 0;
                blockOffsets_[static_cast<size_t>(b) + 1] = kept;
            }
        });
        for (size_t b = 1; b < blockOffsets_.size(); ++b) blockOffsets_[b] += blockOffsets_[b - 1];
        const int total = blockOffsets_.back();
        reserve(total);
        parallelFor(blocks, 1, [&](int begin, int end, int) {
            // The kept items of a block are listed without a branch on keep(i), which a mixed
            // block would mispredict at every other item, then written.
            int kept[selectBlock];
            for (int b = begin; b < end; ++b) {
                int n = 0;
                for (int i = b * selectBlock, last = std::min(i + selectBlock, itemCount); i < last; ++i) {
                    kept[n] = i;
                    n += keep(i) ? 1 : 0;
                }
                const int first = blockOffsets_[static_cast<size_t>(b)];
                for (int k = 0; k < n; ++k) write(first + k, kept[k]);
            }
        });
        return total;
    }

    // task(0, 1, 0, context) once, on another worker while the caller goes on (with one worker:
    // at once, here); awaitAside() returns when it has run. One task aside at a time.
    void runAside(TaskFn* task, void* context);
    void awaitAside();

private:
    static constexpr int selectBlock = 1024;

    template <class Fn>
    static void call(int begin, int end, int worker, void* fn) {
        (*static_cast<const Fn*>(fn))(begin, end, worker);
    }
    void run(TaskFn* task, int itemCount, int minRange, void* context);

    int count_ = 1;
    EnqueueTaskFn* enqueue_ = nullptr;
    FinishTaskFn* finish_ = nullptr;
    void* userContext_ = nullptr;
    bool aside_ = false;           // a task aside runs, not yet awaited
    void* asideHandle_ = nullptr;  // the game's handle of it
    struct Arena;  // oneTBB, when the game brings no job system
    std::unique_ptr<Arena> arena_;
    std::vector<int> blockOffsets_;  // parallelSelect's prefix sums
};

}  // namespace perpdot
