// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "CountingJobs.h"

namespace crumple::common
{

CountingJobs::CountingJobs(int inThreads) : mThreads(inThreads)
{
    mJobs = mThreads.Get();
    mJobs.mHost = this;
    mJobs.mParallelFor = [](void* inHost, int inCount, void (*inTask)(void*, int), void* inContext)
    {
        auto* self = static_cast<CountingJobs*>(inHost);
        ++self->mCalls;
        self->mOffThreadCalls += std::this_thread::get_id() == self->mGameThread ? 0 : 1;
        const JobSystem& threads = self->mThreads.Get();
        threads.mParallelFor(threads.mHost, inCount, inTask, inContext);
    };
    // intent: the started tasks go to the same threads (mHost is this object, not the ThreadJobSystem)
    mJobs.mStartTask = [](void* inHost, void (*inTask)(void*), void* inContext)
    {
        const JobSystem& threads = static_cast<CountingJobs*>(inHost)->mThreads.Get();
        return threads.mStartTask(threads.mHost, inTask, inContext);
    };
    mJobs.mWaitTask = [](void* inHost, std::uint64_t inTicket)
    {
        const JobSystem& threads = static_cast<CountingJobs*>(inHost)->mThreads.Get();
        threads.mWaitTask(threads.mHost, inTicket);
    };
}

} // namespace crumple::common
