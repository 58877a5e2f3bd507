// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "ThreadCpuTime.h"

#include <ctime>

namespace crumple::common
{

double ThreadCpuMs()
{
    timespec now{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
    return 1.0e3 * static_cast<double>(now.tv_sec) + 1.0e-6 * static_cast<double>(now.tv_nsec);
}

} // namespace crumple::common
