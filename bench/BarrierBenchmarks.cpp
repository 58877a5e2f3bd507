// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "Benchmarks.h"
#include "ThreadCpuTime.h"

#if defined(CRUMPLE_BENCH_CRASH)
#include "FloatingBarrierCrash.h"
#endif

#include <chrono>
#include <cmath>
#include <string>

namespace crumple::bench
{

void RunBarrierBenchmarks(BenchTable& ioTable, const BenchOptions& inOptions)
{
#if defined(CRUMPLE_BENCH_CRASH)
    // A car at 30 km/h into a steel barrier that holds: time per engine step of the two-way coupling (contact
    // solve and FEM) against the error of the crush where the car stops, relative to Campbell's line. The
    // error is the coupling's one-step lag, so it should shrink with the step.
    for (double steps_per_second : {60.0, 120.0, 240.0})
    {
        if (inOptions.mQuick && steps_per_second != 120.0)
            continue;
        crash::FloatingBarrierCrashSettings settings;
        settings.mTimeStep = 1.0 / steps_per_second;
        settings.mDuration = inOptions.mQuick ? 0.05 : 0.2;
        const auto start = std::chrono::steady_clock::now();
        const double cpu_start = common::ThreadCpuMs();
        const Result<crash::FloatingBarrierCrashResult> result = crash::RunFloatingBarrierCrash(settings);
        const double elapsed = ElapsedMs(start);
        const double cpu_elapsed = common::ThreadCpuMs() - cpu_start;
        if (result.HasError())
            continue;
        const crash::FloatingBarrierCrashResult& crash = result.Get();
        const int steps = static_cast<int>(std::lround(settings.mDuration / settings.mTimeStep));
        ioTable.Add({"barrier_crush", "steel/30kmh/dt_1/" + std::to_string(static_cast<int>(steps_per_second)),
                     elapsed / steps, crash.mDeepestCrush / crash.mCampbellCrush - 1.0, "rel_crush_vs_campbell",
                     "crush_m=" + FormatExtra(crash.mDeepestCrush) + ";campbell_m=" + FormatExtra(crash.mCampbellCrush) +
                         ";end_speed_m_s=" + FormatExtra(crash.mEndSpeed) +
                         ";momentum_error_N_s=" + FormatExtra(crash.mMomentumError) +
                         ";cpu_ms_per_step=" + FormatExtra(cpu_elapsed / steps)});
    }
#else
    (void)ioTable;
    (void)inOptions;
#endif
}

} // namespace crumple::bench
