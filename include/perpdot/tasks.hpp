/// @file
/// Running the step on several threads: a worker count, and the interface through which a game
/// with its own job system runs perpdot's work instead of perpdot's default (oneTBB).
#pragma once

namespace perpdot {

/// A piece of a parallel loop: items [begin, end) of a task, run by worker `worker`. Two calls of
/// one task that run at the same time have different `worker` indices, each below
/// WorldDef::workerCount.
using TaskFn = void(int begin, int end, int worker, void* taskContext);

/// Starts running `task` over items [0, itemCount) in ranges of at least `minRange` items (the
/// whole range may go to one call), on any threads, and returns a handle for FinishTaskFn. It may
/// also run the task to completion before returning, and then return nullptr. `userContext` is
/// WorldDef::userTaskContext. A step enqueues a task while an earlier one still runs: one task of
/// a single item (the broadphase tree's re-fits) runs beside its parallel loops until the step
/// finishes it, as Box2D v3 runs its tree rebuild beside the narrowphase.
using EnqueueTaskFn = void*(TaskFn* task, int itemCount, int minRange, void* taskContext, void* userContext);

/// Waits until every item of the task behind `handle` (from EnqueueTaskFn, never nullptr) has run.
using FinishTaskFn = void(void* handle, void* userContext);

}  // namespace perpdot
