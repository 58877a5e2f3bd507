// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "ThreadJobSystem.h"

#include <algorithm>

namespace crumple::common
{

ThreadJobSystem::ThreadJobSystem(int inThreads)
{
    const int threads = std::max(inThreads, 1);
    mJobs.mParallelFor = &ThreadJobSystem::ParallelFor;
    mJobs.mHost = this;
    mJobs.mWorkerCount = threads;
    for (int worker = 1; worker < threads; ++worker)
        mWorkers.emplace_back([this] { WorkerLoop(); });
}

ThreadJobSystem::~ThreadJobSystem()
{
    {
        std::lock_guard<std::mutex> lock(mMutex);
        mStop = true;
    }
    mWake.notify_all();
    for (std::thread& worker : mWorkers)
        worker.join();
}

void ThreadJobSystem::Drain(std::unique_lock<std::mutex>& ioLock)
{
    while (mNext < mCount)
    {
        const int index = mNext++;
        ioLock.unlock();
        mTask(mTaskContext, index);
        ioLock.lock();
        if (++mDone == mCount)
            mFinished.notify_all();
    }
}

void ThreadJobSystem::WorkerLoop()
{
    std::unique_lock<std::mutex> lock(mMutex);
    std::uint64_t seen = 0;
    for (;;)
    {
        mWake.wait(lock, [&] { return mStop || mBatch != seen; });
        if (mStop)
            return;
        seen = mBatch;
        Drain(lock);
    }
}

void ThreadJobSystem::ParallelFor(void* inHost, int inCount, void (*inTask)(void*, int), void* inTaskContext)
{
    auto* self = static_cast<ThreadJobSystem*>(inHost);
    std::unique_lock<std::mutex> lock(self->mMutex);
    self->mTask = inTask;
    self->mTaskContext = inTaskContext;
    self->mCount = inCount;
    self->mNext = 0;
    self->mDone = 0;
    ++self->mBatch;
    self->mWake.notify_all();
    self->Drain(lock);
    self->mFinished.wait(lock, [&] { return self->mDone == self->mCount; });
}

} // namespace crumple::common
