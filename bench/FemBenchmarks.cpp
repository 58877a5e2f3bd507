// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "Benchmarks.h"

#if defined(CRUMPLE_BENCH_FEM)
#include "CantileverScene.h"
#include "ThreadJobSystem.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <memory>
#include <string>
#include <thread>
#include <vector>
#endif

namespace crumple::bench
{

#if defined(CRUMPLE_BENCH_FEM)

using namespace crumple::fem;
using common::CantileverScene;
using common::CantileverSettings;

namespace
{

constexpr double cFrameTime = 1.0 / 60.0; ///< One game step (s)
constexpr int cSettleFrames = 3;          ///< Steps from the sudden load to the measurement: T = 0.05 s
constexpr int cSampleSubSteps = 64;       ///< Explicit sub-steps timed to extrapolate a full step

/// A beam mesh: cells along the length and along each side of the section.
struct BeamMesh
{
    int mLengthCells;
    int mSectionCells;
};

const char* IntegratorLabel(EIntegrator inIntegrator)
{
    return inIntegrator == EIntegrator::SymplecticEuler ? "explicit" : "implicit";
}

// "linear" is the paper's Green-strain law (St. Venant-Kirchhoff).
const char* ModelLabel(EElasticModel inModel)
{
    return inModel == EElasticModel::StVenantKirchhoff ? "linear_stvk" : "corotated";
}

// The beam on inMesh with model inModel, integrator inIntegrator and mass damping inAlpha (1/s).
CantileverSettings BeamSettings(const BeamMesh& inMesh, EElasticModel inModel, EIntegrator inIntegrator,
                                double inAlpha)
{
    CantileverSettings settings;
    settings.mLengthCells = inMesh.mLengthCells;
    settings.mSectionCells = inMesh.mSectionCells;
    settings.mMaterial.mModel = inModel;
    settings.mMaterial.mMassDamping = inAlpha;
    settings.mSolver.mIntegrator = inIntegrator;
    return settings;
}

// Signed relative error of the tip deflection against Timoshenko (negative: stiffer than the beam).
double TipError(const CantileverScene& inBeam)
{
    const double reference = common::TimoshenkoDeflection(inBeam.GetSettings());
    return (inBeam.TipDeflection() - reference) / reference;
}

// Mesh part of a case name and of the extra column.
std::string MeshName(const CantileverScene& inBeam)
{
    return std::to_string(inBeam.GetSolver().GetMesh().GetTetCount()) + "_tets";
}

std::string MeshExtra(const CantileverScene& inBeam)
{
    const CantileverSettings& settings = inBeam.GetSettings();
    return "tets=" + std::to_string(inBeam.GetSolver().GetMesh().GetTetCount()) +
           ";cells=" + std::to_string(settings.mLengthCells) + "x" + std::to_string(settings.mSectionCells) +
           "x" + std::to_string(settings.mSectionCells);
}

// Static equilibrium by TetSolver::SolveStatic(): the discretisation-error reference of the mesh. Returns the
// static tip deflection (m).
double StaticCase(BenchTable& ioTable, const BeamMesh& inMesh, EElasticModel inModel, int inRepetitions)
{
    CantileverScene beam =
        CantileverScene::Create(BeamSettings(inMesh, inModel, EIntegrator::ImplicitEuler, 0.0)).Get();
    const std::vector<Vec3> rest = beam.GetSolver().GetMesh().GetRestPositions();
    TetStaticResult solve;
    bool solved = true;
    const Timing timing = MedianTiming(
        inRepetitions, [&] { (void)beam.GetSolver().SetPositions(rest); },
        [&]
        {
            Result<TetStaticResult> result = beam.GetSolver().SolveStatic();
            solved = solved && result.IsValid();
            if (result)
                solve = result.Get();
        });
    const double error = solved ? TipError(beam) : std::numeric_limits<double>::quiet_NaN();
    ioTable.Add({"fem_cantilever", MeshName(beam) + "/static/" + ModelLabel(inModel), timing.mWallMs, error,
                 "rel_tip_error",
                 MeshExtra(beam) + ";cpu_ms=" + FormatExtra(timing.mCpuMs) + ";solved=" + (solved ? "yes" : "no") +
                     ";newton=" + std::to_string(solve.mIterations) +
                     ";cg_iterations=" + std::to_string(solve.mSolverIterations) + ";residual=" +
                     FormatExtra(solve.mRelativeResidual) + ";deflection_m=" + FormatExtra(beam.TipDeflection())});
    return solved ? beam.TipDeflection() : std::numeric_limits<double>::quiet_NaN();
}

// The beam at rest, the tip load applied suddenly, cSettleFrames steps of cFrameTime with near-critical mass
// damping; the time is the median Step(), the error that of the tip deflection at the end. Cases whose run
// is estimated above inBudgetSeconds are not run to the end: their time comes from a measured sample and
// their error is NaN, with the reason in the extra column.
void DynamicCase(BenchTable& ioTable, const BeamMesh& inMesh, EElasticModel inModel, EIntegrator inIntegrator,
                 double inAlpha, double inStaticDeflection, double inBudgetSeconds)
{
    const CantileverSettings settings = BeamSettings(inMesh, inModel, inIntegrator, inAlpha);
    CantileverScene beam = CantileverScene::Create(settings).Get();
    TetSolver& solver = beam.GetSolver();
    const std::string name = MeshName(beam) + "/" + IntegratorLabel(inIntegrator) + "/" + ModelLabel(inModel);
    std::string extra = MeshExtra(beam) + ";alpha_per_s=" + FormatExtra(inAlpha) +
                        ";settle_s=" + FormatExtra(cSettleFrames * cFrameTime);
    const double nan = std::numeric_limits<double>::quiet_NaN();

    // Explicit: time a sample of sub-steps on a separate beam and extrapolate to a full step and a full run.
    const bool symplectic = inIntegrator == EIntegrator::SymplecticEuler;
    if (symplectic)
    {
        const int sub_steps = static_cast<int>(std::ceil(cFrameTime / solver.GetStableTimeStep()));
        CantileverScene sample = CantileverScene::Create(settings).Get();
        std::vector<double> per_sub_step;
        for (int repetition = 0; repetition < 3; ++repetition)
        {
            const auto start = std::chrono::steady_clock::now();
            Result<TetStepResult> step =
                sample.GetSolver().Step(cSampleSubSteps * solver.GetStableTimeStep());
            const double ms = ElapsedMs(start);
            if (step)
                per_sub_step.push_back(ms / step.Get().mSubSteps);
        }
        if (per_sub_step.empty())
        {
            ioTable.Add(
                {"fem_cantilever", name, nan, nan, "rel_tip_error", extra + ";error=sample_step_refused"});
            return;
        }
        const double frame_ms = Median(per_sub_step) * sub_steps;
        const double run_s = frame_ms * cSettleFrames / 1000.0;
        extra +=
            ";sub_steps=" + std::to_string(sub_steps) + ";sub_step_s=" + FormatExtra(solver.GetStableTimeStep());
        if (run_s > inBudgetSeconds)
        {
            ioTable.Add({"fem_cantilever", name, frame_ms, nan, "rel_tip_error",
                         extra + ";time=extrapolated_from_" + std::to_string(cSampleSubSteps) +
                             "_sub_steps;error=not_run_over_budget;estimated_run_s=" + FormatExtra(run_s) +
                             ";budget_s=" + FormatExtra(inBudgetSeconds)});
            return;
        }
    }

    // The run: each Step() timed; an implicit run stops early when its first step shows it cannot fit the
    // budget.
    std::vector<double> step_ms;
    int newton = 0, cg = 0, not_converged = 0, events = 0;
    double previous = 0.0;
    bool failed = false;
    for (int frame = 0; frame < cSettleFrames && !failed; ++frame)
    {
        previous = beam.TipDeflection();
        const auto start = std::chrono::steady_clock::now();
        Result<TetStepResult> step = solver.Step(cFrameTime);
        step_ms.push_back(ElapsedMs(start));
        if (!step)
        {
            failed = true;
            break;
        }
        newton += step.Get().mNewtonIterations;
        cg += step.Get().mSolverIterations;
        not_converged += HasEvent(step.Get().mEvents, ETetStepEvent::SolverNotConverged) ? 1 : 0;
        failed = HasEvent(step.Get().mEvents, ETetStepEvent::Diverged);
        events |= static_cast<int>(step.Get().mEvents);
        if (!symplectic && frame == 0 && step_ms[0] * cSettleFrames / 1000.0 > inBudgetSeconds)
        {
            ioTable.Add(
                {"fem_cantilever", name, step_ms[0], nan, "rel_tip_error",
                 extra + ";time=first_step_only;newton=" + std::to_string(newton) +
                     ";cg_iterations=" + std::to_string(cg) + ";error=not_run_over_budget;estimated_run_s=" +
                     FormatExtra(step_ms[0] * cSettleFrames / 1000.0) + ";budget_s=" + FormatExtra(inBudgetSeconds)});
            return;
        }
    }
    const double deflection = beam.TipDeflection();
    extra += ";time=median_of_" + std::to_string(step_ms.size()) + "_steps";
    if (!symplectic)
        extra += ";newton=" + std::to_string(newton) + ";cg_iterations=" + std::to_string(cg) +
                 ";steps_not_converged=" + std::to_string(not_converged);
    extra += ";events=" + std::to_string(events) + ";deflection_m=" + FormatExtra(deflection) +
             ";vs_static=" + FormatExtra((deflection - inStaticDeflection) / inStaticDeflection) +
             ";last_step_change=" + FormatExtra(std::abs(deflection - previous) / std::abs(deflection));
    ioTable.Add({"fem_cantilever", name, Median(step_ms), failed ? nan : TipError(beam), "rel_tip_error",
                 extra + (failed ? ";error=step_failed" : "")});
}

const char* PreconditionerLabel(EImplicitPreconditioner inPreconditioner)
{
    return inPreconditioner == EImplicitPreconditioner::RestFactorization ? "factored" : "block_jacobi";
}

// The real-time measure: the steel beam at rest, the tip load applied suddenly, cRealTimeSteps
// implicit steps of cFrameTime, undamped, corotated. The default preconditioner (the factored rest system) on
// one thread and on all cores (the element passes on a ThreadJobSystem; the result is bitwise the one-thread
// one), and block Jacobi, step side by side, one step each in turn, each step timed in wall and thread CPU
// time (thread CPU counts the calling thread only); a further beam solved to round-off (CG 1e-12, Newton
// 1e-14) is stepped alongside, untimed, as the fully converged implicit answer the tip error is measured
// against. A side whose steps are estimated above inBudgetSeconds stops after its first step (its time is
// that step's, its error NaN).
constexpr int cRealTimeSteps = 10;

void RealTimeCase(BenchTable& ioTable, const BeamMesh& inMesh, double inBudgetSeconds)
{
    struct Variant
    {
        EImplicitPreconditioner mPreconditioner;
        int mThreads;
    };
    const int cores = std::max(2, static_cast<int>(std::thread::hardware_concurrency()));
    const Variant variants[] = {{EImplicitPreconditioner::RestFactorization, 1},
                                {EImplicitPreconditioner::RestFactorization, cores},
                                {EImplicitPreconditioner::BlockJacobi, 1}};
    std::vector<std::unique_ptr<common::ThreadJobSystem>> jobs;
    std::vector<CantileverScene> beams;
    for (const Variant& variant : variants)
    {
        CantileverSettings settings = BeamSettings(inMesh, EElasticModel::CorotatedLinear, EIntegrator::ImplicitEuler, 0.0);
        settings.mSolver.mPreconditioner = variant.mPreconditioner;
        beams.push_back(CantileverScene::Create(settings).Get());
        jobs.push_back(std::make_unique<common::ThreadJobSystem>(variant.mThreads));
        if (variant.mThreads > 1)
            beams.back().GetSolver().SetJobSystem(&jobs.back()->Get());
    }
    CantileverSettings converged_settings =
        BeamSettings(inMesh, EElasticModel::CorotatedLinear, EIntegrator::ImplicitEuler, 0.0);
    converged_settings.mSolver.mCgRelativeTolerance = 1.0e-12;
    converged_settings.mSolver.mCgMaxIterations = 100000;
    converged_settings.mSolver.mImplicitTolerance = 1.0e-14;
    converged_settings.mSolver.mImplicitMaxIterations = 30;
    CantileverScene converged = CantileverScene::Create(converged_settings).Get();

    struct Side
    {
        std::vector<double> mWallMs, mCpuMs;
        int mCg = 0, mNewton = 0, mNotConverged = 0;
        bool mStopped = false, mFailed = false;
    };
    std::vector<Side> sides(beams.size());
    for (int step = 0; step < cRealTimeSteps; ++step)
    {
        for (std::size_t side = 0; side < beams.size(); ++side)
        {
            Side& timed = sides[side];
            if (timed.mStopped)
                continue;
            const double cpu_start = ThreadCpuMs();
            const auto wall_start = std::chrono::steady_clock::now();
            Result<TetStepResult> result = beams[side].GetSolver().Step(cFrameTime);
            timed.mWallMs.push_back(ElapsedMs(wall_start));
            timed.mCpuMs.push_back(ThreadCpuMs() - cpu_start);
            timed.mFailed = timed.mFailed || !result || HasEvent(result.Get().mEvents, ETetStepEvent::Diverged);
            if (result)
            {
                timed.mCg += result.Get().mSolverIterations;
                timed.mNewton += result.Get().mNewtonIterations;
                timed.mNotConverged += HasEvent(result.Get().mEvents, ETetStepEvent::SolverNotConverged) ? 1 : 0;
            }
            // The first step of a factored side includes the factorisation: judge the budget on the second.
            const bool factored = variants[side].mPreconditioner == EImplicitPreconditioner::RestFactorization;
            const double estimate = timed.mWallMs.back() * cRealTimeSteps / 1000.0;
            timed.mStopped = timed.mFailed || (step == (factored ? 1 : 0) && estimate > inBudgetSeconds);
        }
        if (!converged.GetSolver().Step(cFrameTime))
            break;
    }

    const double reference = converged.TipDeflection();
    for (std::size_t side = 0; side < beams.size(); ++side)
    {
        Side& timed = sides[side];
        const TetSolver& solver = beams[side].GetSolver();
        const int steps = static_cast<int>(timed.mWallMs.size());
        const bool complete = steps == cRealTimeSteps && !timed.mFailed;
        // Steady-state step: the median of the steps after the first (which factors), or the first alone.
        const std::vector<double> wall(timed.mWallMs.begin() + (steps > 1 ? 1 : 0), timed.mWallMs.end());
        const std::vector<double> cpu(timed.mCpuMs.begin() + (steps > 1 ? 1 : 0), timed.mCpuMs.end());
        const double error = complete ? (beams[side].TipDeflection() - reference) / reference
                                      : std::numeric_limits<double>::quiet_NaN();
        ioTable.Add({"fem_realtime",
                     MeshName(beams[side]) + "/implicit/corotated/" +
                         PreconditionerLabel(variants[side].mPreconditioner) + "/" +
                         std::to_string(variants[side].mThreads) + (variants[side].mThreads == 1 ? "_thread" : "_threads"),
                     Median(wall), error, "rel_tip_error_vs_converged_implicit",
                     MeshExtra(beams[side]) + ";cpu_ms=" + FormatExtra(Median(cpu)) +
                         ";first_step_ms=" + FormatExtra(timed.mWallMs.front()) +
                         ";steps=" + std::to_string(steps) + ";cg_iterations=" + std::to_string(timed.mCg) +
                         ";newton=" + std::to_string(timed.mNewton) +
                         ";steps_not_converged=" + std::to_string(timed.mNotConverged) +
                         ";factorizations=" + std::to_string(solver.GetFactorizationCount()) +
                         (variants[side].mThreads == 1 ? std::string()
                          : beams[side].GetSolver().GetPositions() == beams[0].GetSolver().GetPositions()
                              ? std::string(";same_as_one_thread=yes")
                              : std::string(";same_as_one_thread=NO")) +
                         ";dt_s=" + FormatExtra(cFrameTime) + ";tip_m=" + FormatExtra(beams[side].TipDeflection()) +
                         ";converged_tip_m=" + FormatExtra(reference) +
                         (complete ? "" : timed.mFailed ? ";error=step_failed" : ";error=not_run_over_budget")});
    }
}

} // namespace

void RunFemBenchmarks(BenchTable& ioTable, const BenchOptions& inOptions)
{
    // Rayleigh mass damping alpha = 2 omega_1 with omega_1 = 2 pi f_EB the analytic first bending mode (81.5
    // Hz): critical for that mode, and every other mode decays at least as e^(-alpha t / 2). The FE meshes
    // are stiffer than the beam (their first mode is higher), so their first mode is slightly underdamped and
    // decays as e^(-omega_1 t): after T = 0.05 s that is e^(-25.6) ~ 1e-11 of the sudden-load overshoot, far
    // below the discretisation error. Checked once at T = 0.1 s on the 1k and 10k meshes: the explicit tip
    // moved by < 1e-12 relative and stays 1.3e-8 from SolveStatic (its residual tolerance). Implicit Euler
    // itself only relaxes by ~1 / sqrt(1 + alpha h + (omega h)^2) per step, so at T it still lags the static
    // answer by a few 0.1 % (vs_static in the extra column; 1e-7 .. 5e-6 at T = 0.1 s): that is its error.
    const double alpha = 4.0 * std::numbers::pi * common::EulerBernoulliFrequency(CantileverSettings());

    // Meshes of about 1k, 10k and 100k tetrahedra (five per cell, cells close to cubic); --quick only the 1k.
    std::vector<BeamMesh> meshes = {{25, 3}};
    if (!inOptions.mQuick)
    {
        meshes.push_back({50, 6});
        meshes.push_back({100, 14});
    }
    // Per-case budget (s) for a run to T; over it, the time is extrapolated from a sample and the error NaN.
    // 60 s keeps the whole benchmark near 1.5 minutes on 2 cores: explicit Euler runs on 1k tets (2-6 s) and
    // on 10k with the linear model (~30 s), not corotated on 10k (~100 s) nor on 100k (12 to 48 minutes).
    // --quick: 0.5 s, so only the implicit cases run to T.
    const double budget = inOptions.mQuick ? 0.5 : 60.0;
    for (const BeamMesh& mesh : meshes)
    {
        const int repetitions = inOptions.mQuick ? 1 : (mesh.mSectionCells > 10 ? 1 : 3);
        for (EElasticModel model : {EElasticModel::StVenantKirchhoff, EElasticModel::CorotatedLinear})
        {
            const double static_deflection = StaticCase(ioTable, mesh, model, repetitions);
            for (EIntegrator integrator : {EIntegrator::SymplecticEuler, EIntegrator::ImplicitEuler})
                DynamicCase(ioTable, mesh, model, integrator, alpha, static_deflection, budget);
        }
        RealTimeCase(ioTable, mesh, budget);
    }
}

#else

void RunFemBenchmarks(BenchTable& ioTable, const BenchOptions& inOptions)
{
    (void)ioTable;
    (void)inOptions;
}

#endif

} // namespace crumple::bench
