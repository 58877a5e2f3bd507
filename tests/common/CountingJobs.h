// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include "ThreadJobSystem.h"

#include <crumple/base/JobSystem.h>

#include <thread>

namespace crumple::common
{

/// A host job system for tests: counts the parallel fors Crumple hands it and notes those that come from a
/// thread other than the one that made it (the game's: JobSystem allows no other), and runs them and its
/// started tasks on a ThreadJobSystem of inThreads threads.
class CountingJobs
{
  public:
    explicit CountingJobs(int inThreads);
    CountingJobs(const CountingJobs&) = delete;
    CountingJobs& operator=(const CountingJobs&) = delete;

    /// The interface to hand to Crumple; valid while this object lives.
    const JobSystem& Get() const { return mJobs; }
    /// Parallel fors run so far (read on the thread that made this object)
    int GetCalls() const { return mCalls; }
    /// Parallel fors that came from another thread (there must be none)
    int GetOffThreadCalls() const { return mOffThreadCalls; }

  private:
    ThreadJobSystem mThreads;
    JobSystem mJobs;
    std::thread::id mGameThread = std::this_thread::get_id();
    int mCalls = 0;
    int mOffThreadCalls = 0;
};

} // namespace crumple::common
