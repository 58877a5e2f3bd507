// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// CPU against GPU FEM on the steel cantilever of the FEM issue, 1k to 1M tetrahedra, in one run.
#include "Benchmarks.h"

#if defined(CRUMPLE_BENCH_GPU)
#include "CantileverScene.h"
#include "GpuImplicitBenchmarks.h"

#include <crumple/gpu/GpuTetSolver.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>
#endif

namespace crumple::bench
{

#if defined(CRUMPLE_BENCH_GPU)

namespace
{

constexpr double cFrameTime = 1.0 / 60.0; ///< One game step (s)

struct BeamMesh
{
    int mLengthCells;
    int mSectionCells;
};

} // namespace

void RunGpuBenchmarks(BenchTable& ioTable, const BenchOptions& inOptions)
{
    gpu::ComputeDeviceProvider provider;
    Result<std::shared_ptr<gpu::ComputeDevice>> device = provider.Acquire();
    if (device.HasError())
    {
        std::printf("gpu_fem: skipped, no compute device: %s\n", device.GetError().mMessage.c_str());
        return;
    }
    const std::string device_name = device.Get()->IsSoftware() ? "llvmpipe_on_the_CPU" : "gpu";
    std::printf("gpu_fem: device %s%s\n", device.Get()->GetDescription().c_str(),
                device.Get()->IsSoftware() ? " (a software rasteriser: the GPU path runs on the CPU here)" : "");

    // Both solvers run explicit (symplectic) Euler with the same stable sub-step; time per sub-step is
    // measured on a sample and scaled to a 1/60 s step (steel needs thousands). Both start from the CPU's
    // static equilibrium under the 1 kN tip load (SolveStatic, double) and run the sample under that load: the
    // error is the tip deflection after it against Timoshenko, i.e. the mesh's error plus whatever the solver
    // adds while holding equilibrium (float round-off on the GPU). 1M tets: no static solve (minutes of CG):
    // the run starts at rest, time only.
    std::vector<BeamMesh> meshes = {{25, 3}};
    if (!inOptions.mQuick)
    {
        meshes.push_back({50, 6});
        meshes.push_back({100, 14});
        meshes.push_back({200, 29});
    }
    const int sample = inOptions.mQuick ? 8 : 32; // sub-steps per timed Step()
    const int repetitions = inOptions.mQuick ? 1 : 3;
    for (const BeamMesh& mesh : meshes)
    {
        common::CantileverSettings settings;
        settings.mLengthCells = mesh.mLengthCells;
        settings.mSectionCells = mesh.mSectionCells;
        settings.mSolver.mIntegrator = fem::EIntegrator::SymplecticEuler;
        Result<common::CantileverScene> created = common::CantileverScene::Create(settings);
        if (created.HasError())
        {
            std::printf("gpu_fem: %s\n", created.GetError().mMessage.c_str());
            return;
        }
        common::CantileverScene& beam = created.Get();
        fem::TetSolver& cpu = beam.GetSolver();
        const int tets = cpu.GetMesh().GetTetCount();
        const bool with_error = tets <= 200000;
        if (with_error && cpu.SolveStatic().HasError())
            std::printf("gpu_fem: %d tets: no static equilibrium, error not measured\n", tets);
        const double timoshenko = common::TimoshenkoDeflection(settings);
        const double sub_step = cpu.GetStableTimeStep();
        const double per_frame = std::ceil(cFrameTime / sub_step);

        // GPU from the same state.
        Result<gpu::GpuTetSolver> gpu = gpu::GpuTetSolver::CreateFrom(device.Get(), cpu);
        if (gpu.HasError())
        {
            std::printf("gpu_fem: %d tets: %s\n", tets, gpu.GetError().mMessage.c_str());
            continue;
        }

        // Time the same sample on both, the two interleaved (CPU, GPU, CPU, ...) so that other jobs' noise falls
        // on both alike; the median per sub-step scales to a frame. Thread CPU time is the calling thread's:
        // for the GPU its dispatches and waits, not the device's (or llvmpipe's threads') work.
        const std::vector<Timing> timing =
            InterleavedMedians(repetitions, {{[] {}, [&] { (void)cpu.Step(sample * sub_step); }},
                                             {[] {}, [&] { (void)gpu.Get().Step(sample * sub_step); }}});
        const double cpu_ms = timing[0].mWallMs / sample, gpu_ms = timing[1].mWallMs / sample;
        const double cpu_thread_ms = timing[0].mCpuMs / sample, gpu_thread_ms = timing[1].mCpuMs / sample;
        std::vector<Vec3> gpu_positions;
        gpu.Get().ReadPositions(gpu_positions);
        const double nan = std::numeric_limits<double>::quiet_NaN();
        const double cpu_error = with_error ? beam.TipDeflection() / timoshenko - 1.0 : nan;
        const double gpu_error = with_error ? beam.TipDeflection(gpu_positions) / timoshenko - 1.0 : nan;

        const std::string common_extra = "tets=" + std::to_string(tets) + ";sub_steps_per_step=" + FormatExtra(per_frame) +
                                         ";sub_step_ms=";
        const std::string start = with_error ? ";start=static_equilibrium" : ";start=rest;error=not_measured";
        ioTable.Add({"gpu_fem", std::to_string(tets) + "_tets/cpu_double", cpu_ms * per_frame, cpu_error,
                     "rel_tip_error", common_extra + FormatExtra(cpu_ms) + ";sub_step_cpu_ms=" + FormatExtra(cpu_thread_ms) +
                         ";steps_per_s=" + FormatExtra(1000.0 / (cpu_ms * per_frame)) + start});
        ioTable.Add({"gpu_fem", std::to_string(tets) + "_tets/gpu_float", gpu_ms * per_frame, gpu_error,
                     "rel_tip_error",
                     common_extra + FormatExtra(gpu_ms) + ";sub_step_calling_thread_cpu_ms=" + FormatExtra(gpu_thread_ms) +
                         ";steps_per_s=" + FormatExtra(1000.0 / (gpu_ms * per_frame)) +
                         ";gpu_vs_cpu_time=" + FormatExtra(gpu_ms / cpu_ms) + ";device=" + device_name + start});
    }
    RunGpuImplicitCases(ioTable, inOptions, device.Get(), device_name);
}

#else

void RunGpuBenchmarks(BenchTable& ioTable, const BenchOptions& inOptions)
{
    (void)ioTable;
    (void)inOptions;
}

#endif

} // namespace crumple::bench
