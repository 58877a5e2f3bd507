// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/base/JobSystem.h>

#include <algorithm>

namespace crumple
{

void ParallelFor(const JobSystem* inJobs, int inCount, const std::function<void(int)>& inTask)
{
    if (inJobs == nullptr || inJobs->mParallelFor == nullptr || inCount <= 1)
    {
        for (int index = 0; index < inCount; ++index)
            inTask(index);
        return;
    }
    auto trampoline = [](void* inContext, int inIndex) { (*static_cast<const std::function<void(int)>*>(inContext))(inIndex); };
    inJobs->mParallelFor(inJobs->mHost, inCount, trampoline, const_cast<std::function<void(int)>*>(&inTask));
}

int PieceCount(const JobSystem* inJobs, std::size_t inItems, std::size_t inMinPerPiece)
{
    if (inJobs == nullptr || inJobs->mParallelFor == nullptr || inJobs->mWorkerCount <= 1)
        return 1;
    const std::size_t by_size = std::max<std::size_t>(1, inItems / std::max<std::size_t>(1, inMinPerPiece));
    return static_cast<int>(std::min<std::size_t>(by_size, static_cast<std::size_t>(inJobs->mWorkerCount)));
}

} // namespace crumple
