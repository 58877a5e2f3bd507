// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "Benchmarks.h"
#include "ThreadCpuTime.h"
#include "ThreadJobSystem.h"

#if defined(CRUMPLE_BENCH_BULLET)
#include "BulletWallCrash.h"
#endif
#if defined(CRUMPLE_BENCH_ODE)
#include "OdeWallCrash.h"
#endif

#include <algorithm>
#include <chrono>
#include <numeric>
#include <string>

namespace crumple::bench
{

namespace
{

// Steps a bare scene and the same scene with Crumple attached alternately (same run, same machine state)
// and reports the attached step's median time and its ratio to the bare one.
template <class Scene>
void OverheadCase(BenchTable& ioTable, const std::string& inEngine, const std::string& inCase,
                  common::EngineCrashSettings inSettings, int inRepetitions)
{
    std::vector<double> bare_ms, attached_ms, bare_cpu_ms, attached_cpu_ms;
    double bare_total = 0.0, attached_total = 0.0;
    int collisions = 0;
    std::uint64_t vertices = 0;
    for (int repetition = 0; repetition < inRepetitions; ++repetition)
    {
        inSettings.mAttach = false;
        Scene bare(inSettings);
        inSettings.mAttach = true;
        Scene attached(inSettings);
        const int steps = static_cast<int>(inSettings.mDuration / inSettings.mTimeStep);
        for (int step = 0; step < steps; ++step)
        {
            for (Scene* scene : {&bare, &attached})
            {
                // intent: thread CPU time too (the other jobs on a shared host inflate wall time); its clock reads
                // bracket both scenes' steps alike
                const double cpu_start = common::ThreadCpuMs();
                const auto start = std::chrono::steady_clock::now();
                scene->Step();
                const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
                (scene == &bare ? bare_cpu_ms : attached_cpu_ms).push_back(common::ThreadCpuMs() - cpu_start);
                (scene == &bare ? bare_ms : attached_ms).push_back(ms);
                (scene == &bare ? bare_total : attached_total) += ms;
            }
        }
        attached.GetDamage().Flush();
        collisions = attached.GetCounter().mCollisions;
        vertices = attached.GetDamage().GetObject(attached.GetCarObject())->GetDeformer().GetVertexEvaluationCount();
    }
    const double bare = Median(bare_ms), with = Median(attached_ms);
    ioTable.Add({"adapter_overhead", inEngine + "/" + inCase, with, 0.0, "none",
                 "bare_step_ms=" + std::to_string(bare) + ";median_ratio=" + std::to_string(with / bare) +
                     ";bare_step_cpu_ms=" + std::to_string(Median(bare_cpu_ms)) +
                     ";cpu_median_ratio=" + std::to_string(Median(attached_cpu_ms) / Median(bare_cpu_ms)) +
                     ";total_ratio=" + std::to_string(attached_total / bare_total) + ";collisions=" + std::to_string(collisions) +
                     ";vertex_evaluations=" + std::to_string(vertices)});
}

template <class Scene>
void EngineCases(BenchTable& ioTable, const std::string& inEngine, int inRepetitions)
{
    // 100 crates resting beside the road give the engine a realistic load (about 100 contacts per step).
    common::EngineCrashSettings flying;
    flying.mSceneryBoxes = 100;
    flying.mFloating = true;
    flying.mDuration = 2.0;
    OverheadCase<Scene>(ioTable, inEngine, "car_without_contacts", flying, inRepetitions);

    common::EngineCrashSettings resting;
    resting.mSceneryBoxes = 100;
    resting.mDriveOnly = true;
    resting.mSpeed = 0.0;
    resting.mDuration = 2.0;
    OverheadCase<Scene>(ioTable, inEngine, "car_resting_contacts", resting, inRepetitions);

    common::EngineCrashSettings crash;
    crash.mSceneryBoxes = 100;
    crash.mDuration = 0.6;
    OverheadCase<Scene>(ioTable, inEngine, "wall_crash_15m_s", crash, inRepetitions);
}

// A crash at game frames: a bare scene and the same scene with Crumple attached stepped in lockstep (bare
// frame, attached frame, ...), each frame timed in wall and thread CPU time. The attached scene's worst
// frame is the hitch a game sees when the car hits; the bare scene's is the engine's own.
template <class Scene>
void FrameBudgetCase(BenchTable& ioTable, const std::string& inEngine, const std::string& inCase,
                     common::EngineCrashSettings inSettings)
{
    inSettings.mAttach = false;
    Scene bare(inSettings);
    inSettings.mAttach = true;
    Scene attached(inSettings);
    const int frames = static_cast<int>(inSettings.mDuration / inSettings.mTimeStep);
    const LockstepFrames timed = TimeLockstep(frames, [&](int inSide) {
        (inSide == 0 ? bare : attached).Step();
        return true;
    });
    const std::vector<double>(&wall)[2] = timed.mWallMs;
    const std::vector<double>(&cpu)[2] = timed.mCpuMs;
    attached.GetDamage().Flush();
    const auto worst = [](const std::vector<double>& inValues) { return *std::max_element(inValues.begin(), inValues.end()); };
    ioTable.Add({"frame_budget", inEngine + "/" + inCase, Quantile(wall[1], 0.5), 0.0, "none",
                 "worst_cpu_ms=" + FormatExtra(worst(cpu[1])) + ";worst_wall_ms=" + FormatExtra(worst(wall[1])) +
                     ";p99_cpu_ms=" + FormatExtra(Quantile(cpu[1], 0.99)) + ";median_cpu_ms=" + FormatExtra(Quantile(cpu[1], 0.5)) +
                     ";bare_worst_cpu_ms=" + FormatExtra(worst(cpu[0])) + ";bare_p99_cpu_ms=" + FormatExtra(Quantile(cpu[0], 0.99)) +
                     ";frames=" + std::to_string(frames) + ";collisions=" + std::to_string(attached.GetCounter().mCollisions)});
}

template <class Scene>
void FrameBudgetCases(BenchTable& ioTable, const std::string& inEngine, bool inQuick)
{
    // A 1,200 kg box car into a wall at 15 m/s, stepped at 60 Hz, on the default lattice; then the same with
    // its dents deferred to a 2-thread job system's task (DamageWorldSettings::mDeferDents): the game thread
    // only starts them and, a frame later, publishes them.
    const common::ThreadJobSystem jobs(2);
    for (int triangles : inQuick ? std::vector<int>{4000} : std::vector<int>{8000, 50000})
        for (bool deferred : {false, true})
        {
            common::EngineCrashSettings crash;
            crash.mSceneryBoxes = 100;
            crash.mDuration = 0.6;
            crash.mTimeStep = 1.0 / 60.0;
            crash.mTriangles = triangles;
            if (deferred)
            {
                crash.mWorld.mJobs = &jobs.Get();
                crash.mWorld.mDeferDents = true;
            }
            FrameBudgetCase<Scene>(ioTable, inEngine,
                                   "wall_crash_15m_s/" + std::to_string(triangles / 1000) + "k_tris" +
                                       (deferred ? "/deferred_2_threads" : ""),
                                   crash);
        }
}

} // namespace

void RunFrameBudgetBenchmarks(BenchTable& ioTable, const BenchOptions& inOptions)
{
#if defined(CRUMPLE_BENCH_BULLET)
    FrameBudgetCases<common::BulletWallCrash>(ioTable, "bullet", inOptions.mQuick);
#endif
#if defined(CRUMPLE_BENCH_ODE)
    FrameBudgetCases<common::OdeWallCrash>(ioTable, "ode", inOptions.mQuick);
#endif
    RunRaceFrameBudgetBenchmarks(ioTable, inOptions);
    (void)ioTable;
    (void)inOptions;
}

void RunAdapterBenchmarks(BenchTable& ioTable, const BenchOptions& inOptions)
{
    const int repetitions = inOptions.mQuick ? 1 : 5;
#if defined(CRUMPLE_BENCH_BULLET)
    EngineCases<common::BulletWallCrash>(ioTable, "bullet", repetitions);
#endif
#if defined(CRUMPLE_BENCH_ODE)
    EngineCases<common::OdeWallCrash>(ioTable, "ode", repetitions);
#endif
    (void)ioTable;
    (void)repetitions;
}

} // namespace crumple::bench
