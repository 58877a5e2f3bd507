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
    mJobs.mStartTask = &ThreadJobSystem::StartTask;
    mJobs.mWaitTask = &ThreadJobSystem::WaitTask;
    mJobs.mHost = this;
    mJobs.mWorkerCount = threads;
    mThreads = threads;
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
    {
        std::lock_guard<std::mutex> lock(mTaskMutex);
        mTaskStop = true;
    }
    mTaskWake.notify_all();
    if (mTaskThread.joinable())
        mTaskThread.join();
}

std::uint64_t ThreadJobSystem::StartTask(void* inHost, void (*inTask)(void*), void* inTaskContext)
{
    auto* self = static_cast<ThreadJobSystem*>(inHost);
    std::unique_lock<std::mutex> lock(self->mTaskMutex);
    const std::uint64_t ticket = ++self->mTasksStarted;
    if (self->mThreads <= 1)
    {
        lock.unlock();
        inTask(inTaskContext);
        lock.lock();
        self->mTasksFinished = ticket;
        return ticket;
    }
    if (!self->mTaskThread.joinable())
        self->mTaskThread = std::thread([self] { self->TaskLoop(); });
    self->mTaskQueue.emplace_back(inTask, inTaskContext);
    self->mTaskWake.notify_all();
    return ticket;
}

void ThreadJobSystem::WaitTask(void* inHost, std::uint64_t inTicket)
{
    auto* self = static_cast<ThreadJobSystem*>(inHost);
    std::unique_lock<std::mutex> lock(self->mTaskMutex);
    self->mTaskDone.wait(lock, [&] { return self->mTasksFinished >= inTicket; });
}

void ThreadJobSystem::TaskLoop()
{
    std::unique_lock<std::mutex> lock(mTaskMutex);
    for (;;)
    {
        mTaskWake.wait(lock, [&] { return mTaskStop || !mTaskQueue.empty(); });
        if (mTaskQueue.empty())
            return; // stopping, nothing left
        const auto [task, context] = mTaskQueue.front();
        mTaskQueue.erase(mTaskQueue.begin());
        lock.unlock();
        task(context);
        lock.lock();
        ++mTasksFinished;
        mTaskDone.notify_all();
    }
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
