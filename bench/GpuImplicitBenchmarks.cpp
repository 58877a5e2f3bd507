// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// The implicit step on the GPU (conjugate gradient in float, block Jacobi with and without the coarse
// correction) beside the CPU's (factored rest system and block Jacobi, double) on the steel cantilever at
// 1/60 s, stepped in turn, against a converged answer.
#include "GpuImplicitBenchmarks.h"

#if defined(CRUMPLE_BENCH_GPU)
#include "CantileverScene.h"

#include <crumple/fem/TetStepResult.h>
#include <crumple/gpu/GpuTetSolver.h>

#include <chrono>
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
constexpr int cSteps = 10;                ///< Steps from the sudden load (fem_realtime's measure)

common::CantileverSettings BeamSettings(int inLengthCells, int inSectionCells,
                                        fem::EImplicitPreconditioner inPreconditioner)
{
    common::CantileverSettings settings; // steel, 1 kN at the tip from rest, undamped, corotated, implicit
    settings.mLengthCells = inLengthCells;
    settings.mSectionCells = inSectionCells;
    settings.mSolver.mPreconditioner = inPreconditioner;
    return settings;
}

// inSettings with CG to 1e-12 and Newton to 1e-14: the converged implicit answer the rows are measured
// against.
common::CantileverSettings SolvedToRoundOff(common::CantileverSettings inSettings)
{
    inSettings.mSolver.mCgRelativeTolerance = 1.0e-12;
    inSettings.mSolver.mCgMaxIterations = 100000;
    inSettings.mSolver.mImplicitTolerance = 1.0e-14;
    inSettings.mSolver.mImplicitMaxIterations = 30;
    return inSettings;
}

// One step of a side, timed in wall and thread CPU time; its statistics kept.
struct Side
{
    std::vector<double> mWallMs, mCpuMs;
    int mCg = 0, mNewton = 0, mNotConverged = 0;
    bool mFailed = false;

    template <class Solver> void Step(Solver& ioSolver)
    {
        const double cpu_start = ThreadCpuMs();
        const auto wall_start = std::chrono::steady_clock::now();
        const Result<fem::TetStepResult> result = ioSolver.Step(cFrameTime);
        mWallMs.push_back(ElapsedMs(wall_start));
        mCpuMs.push_back(ThreadCpuMs() - cpu_start);
        mFailed = mFailed || !result || HasEvent(result.Get().mEvents, fem::ETetStepEvent::Diverged);
        if (result)
        {
            mCg += result.Get().mSolverIterations;
            mNewton += result.Get().mNewtonIterations;
            mNotConverged += HasEvent(result.Get().mEvents, fem::ETetStepEvent::SolverNotConverged) ? 1 : 0;
        }
    }
};

// The 1,125-tet beam in a soft material (E = 10 MPa, mass damping 5 /s), 1 kN at the tip: it bends until its
// tip has dropped 0.84 m of 1 m, turning its far aggregates by tens of degrees. The GPU with its coarse space
// turned before each step (the default) and kept as built, stepped in turn; the CPU's steps solved to
// round-off are the answer. Medians over the late steps (the beam bent), where the two part.
void RunBentBeamCase(BenchTable& ioTable, const BenchOptions& inOptions,
                     const std::shared_ptr<gpu::ComputeDevice>& inDevice, const std::string& inDeviceName)
{
    const int steps = inOptions.mQuick ? 12 : 40;
    const auto settings = [](int inRefresh)
    {
        common::CantileverSettings beam =
            BeamSettings(25, 3, fem::EImplicitPreconditioner::RestFactorization);
        beam.mMaterial.mYoungsModulus = 1.0e7;
        beam.mMaterial.mMassDamping = 5.0;
        beam.mSolver.mFactorRefreshIterations = inRefresh;
        return beam;
    };
    common::CantileverScene turned_scene = common::CantileverScene::Create(settings(0)).Get();
    common::CantileverScene kept_scene =
        common::CantileverScene::Create(settings(std::numeric_limits<int>::max())).Get();
    common::CantileverScene converged = common::CantileverScene::Create(SolvedToRoundOff(settings(0))).Get();
    Result<gpu::GpuTetSolver> turned = gpu::GpuTetSolver::CreateFrom(inDevice, turned_scene.GetSolver());
    Result<gpu::GpuTetSolver> kept = gpu::GpuTetSolver::CreateFrom(inDevice, kept_scene.GetSolver());
    if (turned.HasError() || kept.HasError())
    {
        std::printf("gpu_implicit: %s\n", (turned.HasError() ? turned : kept).GetError().mMessage.c_str());
        return;
    }
    Side sides[2];
    const int late = steps / 2;
    for (int step = 0; step < steps; ++step)
    {
        if (step == late)
            for (Side& side : sides)
                side = Side{}; // intent: the late steps alone, the beam bent
        sides[0].Step(turned.Get());
        sides[1].Step(kept.Get());
        (void)converged.GetSolver().Step(cFrameTime);
    }
    const double reference = converged.TipDeflection();
    const gpu::GpuTetSolver* solvers[2] = {&turned.Get(), &kept.Get()};
    const char* names[2] = {"bent_1125_tets/gpu_float/coarse_turned",
                            "bent_1125_tets/gpu_float/coarse_as_built"};
    for (int side = 0; side < 2; ++side)
    {
        std::vector<Vec3> positions;
        solvers[side]->ReadPositions(positions);
        const double tip = turned_scene.TipDeflection(positions);
        const Side& timed = sides[side];
        ioTable.Add({"gpu_implicit", names[side], Median(timed.mWallMs),
                     timed.mFailed ? std::numeric_limits<double>::quiet_NaN() : (tip - reference) / reference,
                     "rel_tip_error_vs_converged_implicit",
                     "tets=1125;steps=" + std::to_string(steps) +
                         ";timed_steps=" + std::to_string(steps - late) + ";thread_cpu_ms=" +
                         FormatExtra(Median(timed.mCpuMs)) + ";cg_iterations=" + std::to_string(timed.mCg) +
                         ";steps_not_converged=" + std::to_string(timed.mNotConverged) + ";turns=" +
                         std::to_string(solvers[side]->GetCoarseSpaceTurns()) + ";tip_m=" + FormatExtra(tip) +
                         ";converged_tip_m=" + FormatExtra(reference) + ";device=" + inDeviceName});
    }
}

} // namespace

void RunGpuImplicitCases(BenchTable& ioTable, const BenchOptions& inOptions,
                         const std::shared_ptr<gpu::ComputeDevice>& inDevice, const std::string& inDeviceName)
{
    // The fem_realtime beams (1,125 and 9,000 tets): the CPU's default (factored) and block Jacobi, the GPU's
    // default (block Jacobi and the coarse correction) and block Jacobi alone, one step each in turn (CPU
    // factored, CPU Jacobi, GPU coarse, GPU Jacobi, CPU factored, ...); a fifth beam solved to round-off (CG
    // 1e-12, Newton 1e-14), untimed, is the converged implicit answer. The first step is left out of the
    // medians (the factorisation, the GPU's first allocations and its coarse space).
    struct Mesh
    {
        int mLength, mSection;
    };
    std::vector<Mesh> meshes = {{25, 3}};
    if (!inOptions.mQuick)
        meshes.push_back({50, 6});
    for (const Mesh& mesh : meshes)
    {
        common::CantileverScene factored =
            common::CantileverScene::Create(
                BeamSettings(mesh.mLength, mesh.mSection, fem::EImplicitPreconditioner::RestFactorization))
                .Get();
        common::CantileverScene jacobi =
            common::CantileverScene::Create(
                BeamSettings(mesh.mLength, mesh.mSection, fem::EImplicitPreconditioner::BlockJacobi))
                .Get();
        common::CantileverScene converged =
            common::CantileverScene::Create(
                SolvedToRoundOff(BeamSettings(mesh.mLength, mesh.mSection,
                                              fem::EImplicitPreconditioner::RestFactorization)))
                .Get();
        Result<gpu::GpuTetSolver> gpu = gpu::GpuTetSolver::CreateFrom(inDevice, factored.GetSolver());
        Result<gpu::GpuTetSolver> gpu_jacobi = gpu::GpuTetSolver::CreateFrom(inDevice, jacobi.GetSolver());
        if (gpu.HasError() || gpu_jacobi.HasError())
        {
            std::printf("gpu_implicit: %s\n",
                        (gpu.HasError() ? gpu : gpu_jacobi).GetError().mMessage.c_str());
            return;
        }
        constexpr int cSides = 4;
        Side sides[cSides];
        for (int step = 0; step < cSteps; ++step)
        {
            sides[0].Step(factored.GetSolver());
            sides[1].Step(jacobi.GetSolver());
            sides[2].Step(gpu.Get());
            sides[3].Step(gpu_jacobi.Get());
            (void)converged.GetSolver().Step(cFrameTime);
        }
        const double reference = converged.TipDeflection();
        std::vector<Vec3> gpu_positions, gpu_jacobi_positions;
        gpu.Get().ReadPositions(gpu_positions);
        gpu_jacobi.Get().ReadPositions(gpu_jacobi_positions);
        const double tips[cSides] = {factored.TipDeflection(), jacobi.TipDeflection(),
                                     factored.TipDeflection(gpu_positions),
                                     factored.TipDeflection(gpu_jacobi_positions)};
        const char* names[cSides] = {"cpu_double/factored", "cpu_double/block_jacobi", "gpu_float/coarse",
                                     "gpu_float/block_jacobi"};
        const int coarse_unknowns[cSides] = {0, 0, gpu.Get().GetCoarseUnknowns(),
                                             gpu_jacobi.Get().GetCoarseUnknowns()};
        const int tets = factored.GetSolver().GetMesh().GetTetCount();
        const double factored_ms =
            Median(std::vector<double>(sides[0].mWallMs.begin() + 1, sides[0].mWallMs.end()));
        for (int side = 0; side < cSides; ++side)
        {
            const Side& timed = sides[side];
            const std::vector<double> wall(timed.mWallMs.begin() + 1, timed.mWallMs.end());
            const std::vector<double> cpu(timed.mCpuMs.begin() + 1, timed.mCpuMs.end());
            const double error = timed.mFailed ? std::numeric_limits<double>::quiet_NaN()
                                               : (tips[side] - reference) / reference;
            ioTable.Add({"gpu_implicit", std::to_string(tets) + "_tets/" + names[side], Median(wall), error,
                         "rel_tip_error_vs_converged_implicit",
                         "tets=" + std::to_string(tets) + ";steps=" + std::to_string(cSteps) +
                             ";thread_cpu_ms=" + FormatExtra(Median(cpu)) + ";first_step_ms=" +
                             FormatExtra(timed.mWallMs.front()) + ";newton=" + std::to_string(timed.mNewton) +
                             ";cg_iterations=" + std::to_string(timed.mCg) +
                             ";steps_not_converged=" + std::to_string(timed.mNotConverged) +
                             ";vs_cpu_factored_time=" + FormatExtra(Median(wall) / factored_ms) + ";tip_m=" +
                             FormatExtra(tips[side]) + ";converged_tip_m=" + FormatExtra(reference) +
                             (side >= 2 ? ";coarse_unknowns=" + std::to_string(coarse_unknowns[side]) +
                                              ";device=" + inDeviceName
                                        : std::string()) +
                             (timed.mFailed ? ";error=step_failed" : "")});
        }
    }
    RunBentBeamCase(ioTable, inOptions, inDevice, inDeviceName);
}

#endif

} // namespace crumple::bench
