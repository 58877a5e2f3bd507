// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "ThreadCpuTime.h"

#include <crumple/base/ThreadCpuClock.h>

namespace crumple::common
{

double ThreadCpuMs()
{
    return 1.0e3 * ThreadCpuSeconds();
}

} // namespace crumple::common
