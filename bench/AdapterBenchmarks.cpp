// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "Benchmarks.h"

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

double Median(std::vector<double> inValues)
{
    std::nth_element(inValues.begin(), inValues.begin() + static_cast<std::ptrdiff_t>(inValues.size() / 2), inValues.end());
    return inValues[inValues.size() / 2];
}

// Steps a bare scene and the same scene with Crumple attached alternately (same run, same machine state)
// and reports the attached step's median time and its ratio to the bare one.
template <class Scene>
void OverheadCase(BenchTable& ioTable, const std::string& inEngine, const std::string& inCase,
                  common::EngineCrashSettings inSettings, int inRepetitions)
{
    std::vector<double> bare_ms, attached_ms;
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
                const auto start = std::chrono::steady_clock::now();
                scene->Step();
                const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
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

} // namespace

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
