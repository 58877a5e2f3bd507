// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <cstdint>
#include <functional>

namespace crumple
{

/// The host's job system, injected (STYLE rule 5; Box2D's enqueueTask, Jolt's JobSystem): Crumple owns no
/// thread. Work that splits into independent pieces (the vertices and normals a dent recomputes, the
/// vertices its bounds are checked on, the body pairs' impulse solves of a step with many closing contacts,
/// a prop's FEM element passes) is handed to mParallelFor; each piece writes only its own elements and
/// reductions are exact (max, min), so results are bitwise identical whatever the number of workers and
/// however the host schedules the pieces.
struct CRUMPLE_API JobSystem
{
    /// Runs inTask(inTaskContext, i) for every i in [0, inCount), on any threads in any order, and returns
    /// when all have finished. Called only from the thread that called Crumple, also while a task started
    /// by mStartTask runs (a deferred dent, a prop's step); it is never re-entered from inside a task.
    using ParallelForFunction = void (*)(void* inHost, int inCount, void (*inTask)(void* inTaskContext, int inIndex),
                                         void* inTaskContext);
    ParallelForFunction mParallelFor = nullptr; ///< The host's parallel for; null runs everything inline
    void* mHost = nullptr;                      ///< Passed back to mParallelFor as inHost
    int mWorkerCount = 1;                       ///< How many pieces can run at once (>= 1): a hint for splitting

    /// Starts inTask(inTaskContext) on a worker and returns at once with a ticket for mWaitTask (or runs it
    /// before returning, a valid host too). Crumple has at most one task in flight per DamageWorld (deferred
    /// dents) and one per props::PropWorld (props stepped off the thread), and waits for each before it starts
    /// the next of its kind; tasks never call back into the job system, and results do not depend on the order
    /// in which the host runs them.
    using StartTaskFunction = std::uint64_t (*)(void* inHost, void (*inTask)(void* inTaskContext), void* inTaskContext);
    /// Returns when the task of inTicket has finished (at once when it has).
    using WaitTaskFunction = void (*)(void* inHost, std::uint64_t inTicket);
    StartTaskFunction mStartTask = nullptr; ///< Optional: lets DamageWorldSettings::mDeferDents run dents, and
                                            ///< props::PropWorldSettings::mStepOffThread props, off the game's thread
    WaitTaskFunction mWaitTask = nullptr;   ///< Required with mStartTask
};

/// Runs inTask(i) for i in [0, inCount) through inJobs (inline when inJobs is null, has no mParallelFor or
/// inCount is 1).
CRUMPLE_API void ParallelFor(const JobSystem* inJobs, int inCount, const std::function<void(int)>& inTask);

/// How many pieces to split inItems into for inJobs: one per worker, none smaller than inMinPerPiece items.
CRUMPLE_API int PieceCount(const JobSystem* inJobs, std::size_t inItems, std::size_t inMinPerPiece);

} // namespace crumple
