// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "Benchmarks.h"

#if defined(CRUMPLE_BENCH_PROPS)
#include "FenceDriveThrough.h"
#include "ThreadJobSystem.h"

#include <crumple/base/FileBytes.h>
#include <crumple/plugin/ReplayFormat.h>
#include <crumple/props/PropRecording.h>
#if defined(CRUMPLE_BENCH_BULLET)
#include "BulletWallCrash.h"
#endif
#if defined(CRUMPLE_BENCH_ODE)
#include "OdeWallCrash.h"
#endif
#if defined(CRUMPLE_BENCH_GPU)
#include <crumple/gpu/ComputeDevice.h>
#endif
#endif

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <unistd.h>

namespace crumple::bench
{

#if defined(CRUMPLE_BENCH_PROPS)
namespace
{

// One repetition of an interleaved pair: drive A, then drive B, in one engine; both runs, or nothing after
// printing why (the row's group and engine named).
template <class Scene>
std::optional<std::array<common::FenceRun, 2>> DrivePair(const char* inGroup, const char* inEngine,
                                                         const common::FenceDriveSettings& inA,
                                                         const common::FenceDriveSettings& inB)
{
    const Result<common::FenceRun> a = common::DriveThroughFence<Scene>(inA);
    const Result<common::FenceRun> b = common::DriveThroughFence<Scene>(inB);
    if (!a || !b)
    {
        std::printf("%s/%s: %s\n", inGroup, inEngine, (a ? b : a).GetError().mMessage.c_str());
        return std::nullopt;
    }
    return std::array<common::FenceRun, 2>{a.Get(), b.Get()};
}

// The drive alone and the drive through the fence, interleaved (A, B, A, B, ...), in one engine.
template <class Scene>
void RunFenceBreak(const char* inEngine, BenchTable& ioTable, const BenchOptions& inOptions)
{
    const int repetitions = inOptions.mQuick ? 1 : 3;
    common::FenceDriveSettings drive;
    drive.mDuration = inOptions.mQuick ? 0.3 : 0.6;
    common::FenceDriveSettings fence = drive;
    drive.mFence = false;
    std::vector<double> drive_ms, drive_wall_ms, fence_ms, worst_ms, props_ms, hand_over_ms, hand_over_total_ms, wall_ms, prepare_ms;
    common::FenceRun last;
    for (int rep = 0; rep < repetitions; ++rep)
    {
        const std::optional<std::array<common::FenceRun, 2>> runs =
            DrivePair<Scene>("fence_break", inEngine, drive, fence);
        if (!runs)
            return;
        const common::FenceRun& alone = (*runs)[0];
        const common::FenceRun& run = (*runs)[1];
        drive_ms.push_back(alone.mStepCpuMs / alone.mSteps);
        drive_wall_ms.push_back(alone.mWallMs / alone.mSteps);
        fence_ms.push_back(run.mStepCpuMs / run.mSteps);
        worst_ms.push_back(run.mWorstStepCpuMs);
        props_ms.push_back(run.mPropsCpuMs / run.mSteps);
        hand_over_ms.push_back(run.mHandOverCpuMs / run.mSteps);
        hand_over_total_ms.push_back(run.mHandOverCpuMs);
        prepare_ms.push_back(run.mPrepareCpuMs);
        wall_ms.push_back(run.mWallMs / run.mSteps);
        last = run;
    }
    const std::string speed = std::to_string(static_cast<int>(std::lround(fence.mSpeed * 3.6))) + "kmh";
    ioTable.Add({"fence_break", std::string(inEngine) + "/drive_only/" + speed, Median(drive_ms), 0.0, "baseline",
                 "cpu_ms_per_step=" + FormatExtra(Median(drive_ms)) + ";wall_ms_per_step=" + FormatExtra(Median(drive_wall_ms))});
    // Error: how far the engine's change of the car's momentum is from Crumple's impulses on it.
    const double engine_change = 1200.0 * (last.mSpeedAfter - last.mSpeedBefore);
    ioTable.Add({"fence_break", std::string(inEngine) + "/wood_fence/" + speed, Median(fence_ms),
                 last.mCarImpulse != 0.0 ? engine_change / last.mCarImpulse - 1.0 : 0.0, "rel_engine_vs_crumple_car_impulse",
                 "cpu_ms_per_step=" + FormatExtra(Median(fence_ms)) + ";wall_ms_per_step=" + FormatExtra(Median(wall_ms)) +
                     ";ratio_to_drive=" + FormatExtra(Median(fence_ms) / std::max(Median(drive_ms), 1e-9)) +
                     ";worst_step_ms=" + FormatExtra(Median(worst_ms)) + ";prepare_ms=" + FormatExtra(Median(prepare_ms)) +
                     ";fem_ms_per_step_per_prop=" + FormatExtra(Median(props_ms)) +
                     ";hand_over_ms_per_step=" + FormatExtra(Median(hand_over_ms)) + ";hand_over_ms_total=" + FormatExtra(Median(hand_over_total_ms)) +
                     ";tets=" + std::to_string(last.mFenceTets) + ";links_broken=" + std::to_string(last.mBrokenLinks) +
                     ";pieces_loose=" + std::to_string(last.mLoose) + ";piece_bodies=" + std::to_string(last.mBodiesMade) +
                     ";speed_after_m_s=" + FormatExtra(last.mSpeedAfter)});
}

// A restarted level: the same drive with the fence removed one step in (PropWorld::RemoveProp, the adapter's
// RemoveBody) and added again, interleaved with the plain drive (A, B, A, B, ...). Time: the restart on the
// game's thread (removal, the fresh fence's body, FEM and Prepare); error: the links that broke differently
// than in the plain drive, over those that broke.
template <class Scene>
void RunFenceRestart(const char* inEngine, BenchTable& ioTable, const BenchOptions& inOptions)
{
    const int repetitions = inOptions.mQuick ? 1 : 3;
    common::FenceDriveSettings plain;
    plain.mDuration = inOptions.mQuick ? 0.3 : 0.6;
    common::FenceDriveSettings restarted = plain;
    restarted.mRestartFenceAtStep = 1;
    std::vector<double> restart_cpu_ms, restart_wall_ms, prepare_ms;
    int differing = 0, broken = 0;
    for (int rep = 0; rep < repetitions; ++rep)
    {
        const std::optional<std::array<common::FenceRun, 2>> runs =
            DrivePair<Scene>("fence_restart", inEngine, plain, restarted);
        if (!runs)
            return;
        const common::FenceRun& first = (*runs)[0];
        const common::FenceRun& again = (*runs)[1];
        restart_cpu_ms.push_back(again.mRestartCpuMs);
        restart_wall_ms.push_back(again.mRestartWallMs);
        prepare_ms.push_back(again.mPrepareCpuMs);
        // intent: the worst repetition's (each pair is its own comparison)
        broken = first.mBrokenLinks;
        differing = std::max(differing, CountDiffering(first.mBroken, again.mBroken));
    }
    const std::string speed = std::to_string(static_cast<int>(std::lround(plain.mSpeed * 3.6))) + "kmh";
    ioTable.Add({"fence_restart", std::string(inEngine) + "/wood_fence/" + speed, Median(restart_cpu_ms),
                 broken > 0 ? static_cast<double>(differing) / broken : 0.0, "links_differing_over_broken",
                 "restart_cpu_ms=" + FormatExtra(Median(restart_cpu_ms)) +
                     ";restart_wall_ms=" + FormatExtra(Median(restart_wall_ms)) + ";of_it_prepare_cpu_ms=" +
                     FormatExtra(Median(prepare_ms)) + ";links_broken=" + std::to_string(broken) +
                     ";links_differing=" + std::to_string(differing)});
}

// The drive-through recorded once, then its props replayed with no engine (props::ReplayProps) on the calling
// thread alone and with a 2-thread job system, alternated three times (A, B, A, B, ...): wall time of each
// replay (its FEM's element passes are what the workers share), the calling thread's CPU beside it; error:
// the fence nodes whose replayed positions differ between the two (bitwise the same is the contract).
template <class Scene>
void RunFenceReplayThreads(const char* inEngine, BenchTable& ioTable, const BenchOptions& inOptions)
{
    common::FenceDriveSettings drive;
    drive.mDuration = inOptions.mQuick ? 0.1 : 0.6;
    // intent: a name of this process's own (two benches at once must not share it)
    const std::filesystem::path path = std::filesystem::temp_directory_path() /
                                       ("crumple_bench_fence_replay_" + std::string(inEngine) + "_" +
                                        std::to_string(static_cast<long>(::getpid())) + ".crumple");
    drive.mRecordTo = path;
    const Result<common::FenceRun> live = common::DriveThroughFence<Scene>(drive);
    Result<std::vector<std::byte>> bytes =
        live ? ReadFileBytes(path) : Result<std::vector<std::byte>>(live.GetError());
    // intent: the recording and, where the drive stopped before closing it, its partial file: nothing left
    std::error_code ignored;
    std::filesystem::remove(path, ignored);
    std::filesystem::remove(PartialFilePath(path), ignored);
    Result<plugin::Replay> replay =
        bytes ? plugin::DecodeReplay(bytes.Get()) : Result<plugin::Replay>(bytes.GetError());
    if (!replay)
    {
        std::printf("fence_replay/%s: %s\n", inEngine, replay.GetError().mMessage.c_str());
        return;
    }
    const common::ThreadJobSystem two(2);
    std::vector<double> wall_ms[2], cpu_ms[2];
    std::vector<Vec3> positions[2];
    int differing = 0; // the worst repetition's nodes whose positions differ between the two sides
    const int repetitions = inOptions.mQuick ? 1 : 3;
    for (int rep = 0; rep < repetitions; ++rep)
    {
        for (int side = 0; side < 2; ++side)
        {
            const double cpu_start = ThreadCpuMs();
            const auto wall_start = std::chrono::steady_clock::now();
            Result<std::vector<props::ReplayedProp>> replayed =
                props::ReplayProps(replay.Get(), nullptr, side == 0 ? nullptr : &two.Get());
            wall_ms[side].push_back(
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - wall_start)
                    .count());
            cpu_ms[side].push_back(ThreadCpuMs() - cpu_start);
            if (!replayed || replayed.Get().empty() || replayed.Get()[0].mProp.GetCpuSolver() == nullptr)
            {
                std::printf("fence_replay/%s: %s\n", inEngine,
                            replayed ? "no CPU prop replayed" : replayed.GetError().mMessage.c_str());
                return;
            }
            positions[side] = replayed.Get()[0].mProp.GetCpuSolver()->GetPositions();
        }
        differing = std::max(differing, CountDiffering(positions[0], positions[1]));
    }
    const std::string name = std::string(inEngine) + "/" + std::to_string(live.Get().mFenceTets) + "_tets/";
    ioTable.Add({"fence_replay", name + "1_thread", Median(wall_ms[0]), 0.0, "baseline",
                 "wall_ms=" + FormatExtra(Median(wall_ms[0])) + ";cpu_ms=" + FormatExtra(Median(cpu_ms[0])) +
                     ";links_broken=" + std::to_string(live.Get().mBrokenLinks)});
    ioTable.Add({"fence_replay", name + "2_threads", Median(wall_ms[1]), static_cast<double>(differing),
                 "nodes_differing_from_1_thread",
                 "wall_ms=" + FormatExtra(Median(wall_ms[1])) +
                     ";calling_thread_cpu_ms=" + FormatExtra(Median(cpu_ms[1])) + ";speedup_wall=" +
                     FormatExtra(Median(wall_ms[0]) / std::max(Median(wall_ms[1]), 1e-9))});
}

// How much the fence's outcome depends on solver settings that should not matter: the same 64 km/h hit with
// the conjugate-gradient tolerance at 1e-6 (the default), 1e-7 and 1e-8, and with the factor refreshed after 3
// iterations. A converged answer would not move; today the links broken move by a factor of 4 (README, known
// limits: the contact coupling puts km/s velocities on a few light nodes); the same with the impulses spread
// over 0.1 m footprints (FemProp::SetContactSpread). Error: the spread of the car's
// loss of speed, (max - min) / median, over the settings. inContactSpread: the fence FEM's contact spread
// radius (FemProp::SetContactSpread, m; 0: each contact's impulse on its element's four nodes).
template <class Scene>
void RunFenceSpread(const char* inEngine, double inContactSpread, BenchTable& ioTable)
{
    struct Variant
    {
        const char* mName;
        double mCgTolerance;
        int mRefresh;
    };
    const Variant variants[] = {{"cg_1e-6", 1.0e-6, 0}, {"cg_1e-7", 1.0e-7, 0}, {"cg_1e-8", 1.0e-8, 0}, {"refresh_3", 1.0e-6, 3}};
    std::vector<double> losses, wall_ms;
    std::string extra;
    for (const Variant& variant : variants)
    {
        common::FenceDriveSettings settings;
        settings.mSolver.mCgRelativeTolerance = variant.mCgTolerance;
        settings.mSolver.mFactorRefreshIterations = variant.mRefresh;
        settings.mContactSpread = inContactSpread;
        const Result<common::FenceRun> run = common::DriveThroughFence<Scene>(settings);
        if (!run)
        {
            std::printf("fence_spread/%s: %s\n", inEngine, run.GetError().mMessage.c_str());
            return;
        }
        losses.push_back(run.Get().mSpeedBefore - run.Get().mSpeedAfter);
        wall_ms.push_back(run.Get().mWallMs);
        extra += std::string(extra.empty() ? "" : ";") + variant.mName + "_links=" + std::to_string(run.Get().mBrokenLinks) + ";" +
                 variant.mName + "_bodies=" + std::to_string(run.Get().mBodiesMade) + ";" + variant.mName +
                 "_loss_m_s=" + FormatExtra(losses.back());
    }
    const auto [low, high] = std::minmax_element(losses.begin(), losses.end());
    const std::string spread = inContactSpread > 0.0 ? "/contact_spread_" + FormatExtra(inContactSpread) + "m" : "";
    ioTable.Add({"fence_spread", std::string(inEngine) + "/wood_fence/64kmh" + spread, Median(wall_ms),
                 (*high - *low) / std::max(Median(losses), 1e-9), "rel_spread_of_car_loss", extra});
}

// The 64 km/h drive-through with the held body at the whole fence's mass (as the samples run it) and at the
// struck planks' contact mass (HeldPropEngine::mSetHeldMass), alternated: what the opt-in does to the car in
// this engine (the README compares the engines). Error: the engine's change of the car's momentum against
// Crumple's impulses on it, with the contact mass.
template <class Scene>
void RunFenceContactMass(const char* inEngine, BenchTable& ioTable)
{
    common::FenceDriveSettings whole;
    common::FenceDriveSettings matched = whole;
    matched.mMatchMass = true;
    std::vector<double> whole_ms, matched_ms;
    common::FenceRun whole_run, matched_run;
    for (int rep = 0; rep < 2; ++rep)
        for (const bool match : {false, true})
        {
            const Result<common::FenceRun> run = common::DriveThroughFence<Scene>(match ? matched : whole);
            if (!run)
            {
                std::printf("fence_contact_mass/%s: %s\n", inEngine, run.GetError().mMessage.c_str());
                return;
            }
            (match ? matched_ms : whole_ms).push_back(run.Get().mStepCpuMs / run.Get().mSteps);
            (match ? matched_run : whole_run) = run.Get();
        }
    const double engine_change = 1200.0 * (matched_run.mSpeedAfter - matched_run.mSpeedBefore);
    ioTable.Add(
        {"fence_contact_mass", std::string(inEngine) + "/wood_fence/64kmh", Median(matched_ms),
         matched_run.mCarImpulse != 0.0 ? engine_change / matched_run.mCarImpulse - 1.0 : 0.0,
         "rel_engine_vs_crumple_car_impulse",
         "cpu_ms_per_step=" + FormatExtra(Median(matched_ms)) +
             ";whole_mass_cpu_ms_per_step=" + FormatExtra(Median(whole_ms)) +
             ";car_loss_m_s=" + FormatExtra(matched_run.mSpeedBefore - matched_run.mSpeedAfter) +
             ";whole_mass_car_loss_m_s=" + FormatExtra(whole_run.mSpeedBefore - whole_run.mSpeedAfter) +
             ";links_broken=" + std::to_string(matched_run.mBrokenLinks) +
             ";whole_mass_links_broken=" + std::to_string(whole_run.mBrokenLinks) +
             ";fence_impulse_n_s=" + FormatExtra(matched_run.mFenceImpulse) +
             ";whole_mass_fence_impulse_n_s=" + FormatExtra(whole_run.mFenceImpulse)});
}

#if defined(CRUMPLE_BENCH_GPU)
// The 64 km/h drive-through with the fence's FEM on the CPU (double, factored rest system) and on the GPU
// (float, block-Jacobi conjugate gradient; llvmpipe where there is no GPU), one 0.3 s run each (llvmpipe
// takes seconds per step of this 17,600-tet fence), CPU first: the game thread's CPU per step and the FEM's
// share of it, wall time per step, the outcome of each. Error: the GPU's car loss of speed against the CPU's,
// relative.
template <class Scene>
void RunFenceBackends(const char* inEngine, gpu::ComputeDeviceProvider& ioProvider, BenchTable& ioTable)
{
    common::FenceDriveSettings cpu;
    cpu.mDuration = 0.3;
    common::FenceDriveSettings on_gpu = cpu;
    on_gpu.mBackend = props::EFemBackend::Gpu;
    on_gpu.mProvider = &ioProvider;
    common::FenceRun runs[2];
    for (int side = 0; side < 2; ++side)
    {
        const Result<common::FenceRun> run = common::DriveThroughFence<Scene>(side == 0 ? cpu : on_gpu);
        if (!run)
        {
            std::printf("fence_backend/%s: %s\n", inEngine, run.GetError().mMessage.c_str());
            return;
        }
        runs[side] = run.Get();
    }
    if (runs[1].mBackend != props::EFemBackend::Gpu)
    {
        std::printf("fence_backend/%s: the fence ran on the CPU (no device)\n", inEngine);
        return;
    }
    const double cpu_loss = runs[0].mSpeedBefore - runs[0].mSpeedAfter;
    for (int side = 0; side < 2; ++side)
    {
        const common::FenceRun& run = runs[side];
        const double loss = run.mSpeedBefore - run.mSpeedAfter;
        ioTable.Add(
            {"fence_backend", std::string(inEngine) + "/wood_fence/64kmh/" + (side == 0 ? "cpu" : "gpu"),
             run.mWallMs / run.mSteps, side == 0 ? 0.0 : (loss - cpu_loss) / cpu_loss, "rel_car_loss_vs_cpu",
             "game_thread_cpu_ms_per_step=" + FormatExtra(run.mStepCpuMs / run.mSteps) +
                 ";fem_game_thread_cpu_ms_per_step=" + FormatExtra(run.mPropsCpuMs / run.mSteps) +
                 ";worst_step_cpu_ms=" + FormatExtra(run.mWorstStepCpuMs) + ";tets=" +
                 std::to_string(run.mFenceTets) + ";links_broken=" + std::to_string(run.mBrokenLinks) +
                 ";pieces_loose=" + std::to_string(run.mLoose) +
                 ";steps_not_converged=" + std::to_string(run.mNotConverged) + "_of_" +
                 std::to_string(run.mSteps) + ";car_loss_m_s=" + FormatExtra(loss) +
                 (side == 1 ? ";device=" + ioProvider.Acquire().Get()->GetDescription() : std::string())});
    }
}
#endif

} // namespace
#endif

void RunPropBenchmarks(BenchTable& ioTable, const BenchOptions& inOptions)
{
#if defined(CRUMPLE_BENCH_PROPS) && defined(CRUMPLE_BENCH_BULLET)
    RunFenceBreak<common::BulletWallCrash>("bullet", ioTable, inOptions);
    RunFenceRestart<common::BulletWallCrash>("bullet", ioTable, inOptions);
    RunFenceReplayThreads<common::BulletWallCrash>("bullet", ioTable, inOptions);
    if (!inOptions.mQuick)
    {
        for (double spread : {0.0, 0.1})
            RunFenceSpread<common::BulletWallCrash>("bullet", spread, ioTable);
        RunFenceContactMass<common::BulletWallCrash>("bullet", ioTable);
    }
#endif
#if defined(CRUMPLE_BENCH_PROPS) && defined(CRUMPLE_BENCH_ODE)
    RunFenceBreak<common::OdeWallCrash>("ode", ioTable, inOptions);
    RunFenceRestart<common::OdeWallCrash>("ode", ioTable, inOptions);
    if (!inOptions.mQuick)
    {
        for (double spread : {0.0, 0.1})
            RunFenceSpread<common::OdeWallCrash>("ode", spread, ioTable);
        RunFenceContactMass<common::OdeWallCrash>("ode", ioTable);
    }
#endif
    (void)ioTable;
    (void)inOptions;
}

void RunPropGpuBenchmarks(BenchTable& ioTable, const BenchOptions& inOptions)
{
#if defined(CRUMPLE_BENCH_PROPS) && defined(CRUMPLE_BENCH_GPU) && defined(CRUMPLE_BENCH_BULLET)
    if (inOptions.mQuick)
    {
        // intent: the smoke run stays short; llvmpipe takes minutes for this drive
        std::printf("fence_backend: skipped with --quick (minutes on a software device)\n");
        return;
    }
    gpu::ComputeDeviceProvider provider;
    if (Result<std::shared_ptr<gpu::ComputeDevice>> device = provider.Acquire(); device.HasError())
        std::printf("fence_backend: skipped, no compute device: %s\n", device.GetError().mMessage.c_str());
    else
        RunFenceBackends<common::BulletWallCrash>("bullet", provider, ioTable);
#else
    std::printf("fence_backend: skipped: this build has no GPU backend, no props or no Bullet\n");
#endif
    (void)ioTable;
    (void)inOptions;
}

} // namespace crumple::bench
