// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/JobSystem.h>

#include <condition_variable>
#include <cstdint>
#include <utility>
#include <mutex>
#include <thread>
#include <vector>

namespace crumple::common
{

/// A host job system for tests, benchmarks and samples (a game brings its own): inThreads - 1 worker
/// threads that live as long as this object, and the calling thread, take the pieces of each parallel
/// for in whatever order they come for them, so a test sees the scheduling a real job system could produce.
/// Started tasks (JobSystem::mStartTask) run in order on one background thread, made on the first one;
/// with one thread they run before mStartTask returns.
class ThreadJobSystem
{
public:
    /// @param[in] inThreads threads per parallel for, the caller's included, >= 1
    explicit ThreadJobSystem(int inThreads);
    ~ThreadJobSystem();
    ThreadJobSystem(const ThreadJobSystem&) = delete;
    ThreadJobSystem& operator=(const ThreadJobSystem&) = delete;

    /// The interface to hand to Crumple; valid while this object lives.
    const JobSystem& Get() const { return mJobs; }

private:
    static void ParallelFor(void* inHost, int inCount, void (*inTask)(void*, int), void* inTaskContext);
    static std::uint64_t StartTask(void* inHost, void (*inTask)(void*), void* inTaskContext);
    static void WaitTask(void* inHost, std::uint64_t inTicket);
    void TaskLoop();
    void WorkerLoop();
    // Takes and runs pieces of the current batch until none is left.
    void Drain(std::unique_lock<std::mutex>& ioLock);

    JobSystem mJobs;
    std::vector<std::thread> mWorkers;
    std::mutex mMutex;
    std::condition_variable mWake;     ///< Workers wait here for a batch (or the end)
    std::condition_variable mFinished; ///< The caller waits here for the batch's last piece
    void (*mTask)(void*, int) = nullptr;
    void* mTaskContext = nullptr;
    int mCount = 0;        ///< Pieces in the current batch
    int mNext = 0;         ///< Next piece to hand out
    int mDone = 0;         ///< Pieces finished
    std::uint64_t mBatch = 0; ///< Batch number, so a worker joins each batch once
    bool mStop = false;

    // Started tasks, served in order by mTaskThread.
    int mThreads = 1;
    std::thread mTaskThread;
    std::mutex mTaskMutex;
    std::condition_variable mTaskWake;
    std::condition_variable mTaskDone;
    std::vector<std::pair<void (*)(void*), void*>> mTaskQueue;
    std::uint64_t mTasksStarted = 0;  ///< Tickets handed out (ticket n is the n-th task)
    std::uint64_t mTasksFinished = 0; ///< Tasks run to the end, in ticket order
    bool mTaskStop = false;
};

} // namespace crumple::common
