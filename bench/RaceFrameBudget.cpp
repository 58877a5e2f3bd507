// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// The racing samples' scene at game frames (frame_budget group): the course with Crumple attached, and the
// same course bare (the engine alone), stepped in lockstep, frame by frame.
#include "Benchmarks.h"

#if defined(CRUMPLE_BENCH_RACING_BULLET)
#include "BulletRaceScene.h"
#endif
#if defined(CRUMPLE_BENCH_RACING_ODE)
#include "OdeRaceScene.h"
#endif
#if defined(CRUMPLE_BENCH_RACING_BULLET) || defined(CRUMPLE_BENCH_RACING_ODE)
#include "RaceProps.h"
#endif

#include <algorithm>
#include <cstdio>
#include <string>

namespace crumple::bench
{

namespace
{

#if defined(CRUMPLE_BENCH_RACING_BULLET) || defined(CRUMPLE_BENCH_RACING_ODE)

// inFrames 60 Hz frames of the bare scene and the attached one, alternating (bare frame, attached frame, ...),
// each frame timed in wall and thread CPU time: the worst and the 99th percentile of each side, and where the
// attached side's worst frame fell (the fence hit and the parked car are the candidates).
template <class Scene>
void RaceCase(BenchTable& ioTable, const std::string& inEngine, const std::string& inCase,
              const samples::RaceSceneSettings& inAttached, int inFrames)
{
    samples::RaceSceneSettings bare_settings = inAttached;
    bare_settings.mAttach = false;
    Result<std::unique_ptr<Scene>> bare = Scene::Create(bare_settings);
    Result<std::unique_ptr<Scene>> attached = Scene::Create(inAttached);
    if (!bare || !attached)
    {
        std::printf("  frame_budget %s/%s: not run: %s\n", inEngine.c_str(), inCase.c_str(),
                    (!bare ? bare.GetError() : attached.GetError()).mMessage.c_str());
        return;
    }
    Status stepped = Status::Ok();
    // The attached frames' share of Crumple (adapter and props, game-thread CPU)
    std::vector<double> crumple_ms;
    crumple_ms.reserve(static_cast<std::size_t>(inFrames));
    const LockstepFrames timed = TimeLockstep(inFrames, [&](int inSide) {
        stepped = (inSide == 0 ? *bare.Get() : *attached.Get()).StepFrame(nullptr);
        if (inSide == 1)
            crumple_ms.push_back(attached.Get()->GetLastFrameCrumpleMs());
        return stepped.IsValid();
    });
    const std::vector<double>(&wall)[2] = timed.mWallMs;
    const std::vector<double>(&cpu)[2] = timed.mCpuMs;
    if (!stepped)
    {
        std::printf("  frame_budget %s/%s: stopped: %s\n", inEngine.c_str(), inCase.c_str(), stepped.GetError().mMessage.c_str());
        return;
    }
    attached.Get()->GetDamage()->Flush();
    const auto worst_at = [](const std::vector<double>& inValues)
    { return static_cast<int>(std::max_element(inValues.begin(), inValues.end()) - inValues.begin()); };
    const int worst = worst_at(cpu[1]);
    const samples::RaceProps& race_props = *attached.Get()->GetProps();
    // Fragments and shapes the props' task worked out for the hand-over, and those its calls did
    const props::PropHandOverStats& handover = race_props.GetHandOverStats();
    ioTable.Add(
        {"frame_budget", inEngine + "/" + inCase, Quantile(wall[1], 0.5), 0.0, "none",
         "worst_cpu_ms=" + FormatExtra(cpu[1][static_cast<std::size_t>(worst)]) +
             ";worst_at_s=" + FormatExtra(worst / 60.0) +
             ";worst_wall_ms=" + FormatExtra(*std::max_element(wall[1].begin(), wall[1].end())) +
             ";p99_cpu_ms=" + FormatExtra(Quantile(cpu[1], 0.99)) + ";p99_wall_ms=" +
             FormatExtra(Quantile(wall[1], 0.99)) + ";median_cpu_ms=" + FormatExtra(Quantile(cpu[1], 0.5)) +
             ";bare_worst_cpu_ms=" + FormatExtra(*std::max_element(cpu[0].begin(), cpu[0].end())) +
             ";bare_p99_cpu_ms=" + FormatExtra(Quantile(cpu[0], 0.99)) +
             ";bare_median_cpu_ms=" + FormatExtra(Quantile(cpu[0], 0.5)) +
             ";props_worst_step_ms=" + FormatExtra(race_props.GetWorstStepMs()) +
             ";props_steps_split=" + std::to_string(race_props.GetSplitSteps()) +
             ";props_steps_given_up=" + std::to_string(race_props.GetGivenUpSteps()) +
             ";props_steps_unconverged=" + std::to_string(race_props.GetUnconvergedSteps()) +
             ";crumple_worst_cpu_ms=" + FormatExtra(*std::max_element(crumple_ms.begin(), crumple_ms.end())) +
             ";crumple_worst_at_s=" + FormatExtra(worst_at(crumple_ms) / 60.0) +
             ";crumple_p99_cpu_ms=" + FormatExtra(Quantile(crumple_ms, 0.99)) +
             ";handover_on_task=" + std::to_string(handover.mFragmentsForecast + handover.mShapesForecast) +
             ";handover_in_calls=" + std::to_string(handover.mFragmentsComputed + handover.mShapesComputed) +
             ";frames=" + std::to_string(inFrames)});
}

template <class Scene>
void RaceCases(BenchTable& ioTable, const std::string& inEngine, bool inQuick)
{
    // The samples' 7 s session (in Bullet the brick wall at 1.55 s, the fence at 3.4 s, the parked car at 4.1
    // s);
    // --quick stops before them.
    const int frames = inQuick ? 30 : 420;
    RaceCase<Scene>(ioTable, inEngine, "racing/inline", {}, frames);
    if (inQuick)
        return;
    RaceCase<Scene>(ioTable, inEngine, "racing/deferred_2_threads", {.mThreads = 2, .mDeferDents = true}, frames);
    // The props' FEM as a task too (landing one engine step later): what is left on the game's thread.
    RaceCase<Scene>(ioTable, inEngine, "racing/deferred_props_off_thread_2_threads",
                    {.mThreads = 2, .mDeferDents = true, .mPropsOffThread = true}, frames);
    // The contacts' impulses on the dents' task as well (the props hear of a hit one more engine step later:
    // another run, whose car may take another path).
    RaceCase<Scene>(ioTable, inEngine, "racing/impulses_props_off_thread_2_threads",
                    {.mThreads = 2, .mDeferDents = true, .mDeferImpulses = true, .mPropsOffThread = true},
                    frames);
}

#endif

} // namespace

void RunRaceFrameBudgetBenchmarks(BenchTable& ioTable, const BenchOptions& inOptions)
{
#if defined(CRUMPLE_BENCH_RACING_BULLET)
    RaceCases<samples::BulletRaceScene>(ioTable, "bullet", inOptions.mQuick);
#endif
#if defined(CRUMPLE_BENCH_RACING_ODE)
    RaceCases<samples::OdeRaceScene>(ioTable, "ode", inOptions.mQuick);
#endif
    (void)ioTable;
    (void)inOptions;
}

} // namespace crumple::bench
