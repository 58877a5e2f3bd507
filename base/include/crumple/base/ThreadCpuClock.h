// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

namespace crumple
{

/// CPU time the calling thread has used (s), for what a call costs the game's thread: time it spends
/// waiting (for a task, a lock, the scheduler) is not in it. POSIX's CLOCK_THREAD_CPUTIME_ID; where a
/// platform lacks it, the steady clock (wall time, waits included).
CRUMPLE_API double ThreadCpuSeconds();

} // namespace crumple
