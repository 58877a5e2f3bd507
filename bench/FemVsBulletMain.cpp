// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// crumple-bench-fem-vs-bullet: Crumple's implicit tetrahedral FEM step against Bullet 3.24's implicit
// deformable solver on the same cantilever (mesh, lumped masses, anchors, tip load, damping, time step),
// stepped interleaved in one process. Prints a table; writes CSV with --csv FILE. A separate executable from
// crumple-bench because it links the double-precision Bullet, whose symbols clash with the float Bullet
// there.
#include "BulletDeformableBeam.h"
#include "CantileverScene.h"
#include "ThreadCpuTime.h"

#include <crumple/base/Version.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

namespace crumple::bench
{

namespace
{

using namespace crumple::fem;
using common::CantileverScene;
using common::CantileverSettings;

constexpr double cFrameTime = 1.0 / 60.0; ///< One game step (s), both sides
constexpr int cSteps = 10;                ///< Steps from the sudden load to the measurement: T = 1/6 s
/// Bullet's steps on one mesh stop once the next would end past this (s of wall time), so that a mesh
/// whose Bullet step takes tens of seconds cannot hold the run for many minutes; the cut is reported in the
/// extra column. On the 2-core reference machine Bullet's 98k-tet step takes 6 to 8 s, so all 10 steps fit
/// and the whole run takes about 1.5 minutes; steps above 12 s would be cut.
constexpr double cBulletBudgetSeconds = 120.0;
/// Bullet's tip "does not move" when it deflects less than this fraction of the static answer.
constexpr double cMinMovedFraction = 1.0e-6;

constexpr const char* cBenchmark = "fem_vs_bullet";
constexpr const char* cErrorUnit = "rel_tip_error_vs_converged";

/// Command line.
struct Options
{
    bool mQuick = false;             ///< Only the 1k-tet mesh
    std::string mCsv;                ///< CSV output path, empty for none
    int mBulletNewtonIterations = 1; ///< Bullet's Newton iterations per step (its default 1)
    int mBulletCgIterations = 300;   ///< Bullet's CG iterations per solve (its default 300)
};

/// A beam mesh: cells along the length and along each side of the section.
struct BeamMesh
{
    int mLengthCells;
    int mSectionCells;
};

/// One result row (CSV: benchmark,case,median_ms,cpu_ms,error,error_unit,extra).
struct Row
{
    std::string mCase;         ///< e.g. "1125_tets/bullet"
    double mMedianMs = 0.0;    ///< Median wall time of one step (ms)
    double mCpuMs = 0.0;       ///< Median thread CPU time of one step (ms)
    double mError = 0.0;       ///< Signed relative tip error against the converged implicit answer
    double mStaticError = 0.0; ///< Signed relative tip error against static equilibrium (printed only)
    double mRatio = 0.0;       ///< Median wall time over Crumple's (printed only)
    std::string mExtra;        ///< key=value pairs separated by ';' (vs_static and the ratios included)
};

/// Wall and thread CPU time of each step (ms).
struct StepTimes
{
    std::vector<double> mWallMs;
    std::vector<double> mCpuMs;
};

double Median(std::vector<double> inValues)
{
    if (inValues.empty())
        return std::numeric_limits<double>::quiet_NaN();
    std::nth_element(inValues.begin(), inValues.begin() + static_cast<std::ptrdiff_t>(inValues.size() / 2),
                     inValues.end());
    return inValues[inValues.size() / 2];
}

// A number for the extra column: 4 significant digits, never a comma.
std::string Format(double inValue)
{
    char text[32];
    std::snprintf(text, sizeof(text), "%.4g", inValue);
    return text;
}

// Runs inStep once and appends its wall and thread CPU time to ioTimes.
template <class Function> void TimeStep(StepTimes& ioTimes, Function&& inStep)
{
    const double cpu_start = common::ThreadCpuMs();
    const auto start = std::chrono::steady_clock::now();
    inStep();
    const auto stop = std::chrono::steady_clock::now();
    ioTimes.mCpuMs.push_back(common::ThreadCpuMs() - cpu_start);
    ioTimes.mWallMs.push_back(std::chrono::duration<double, std::milli>(stop - start).count());
}

// The steel beam on inMesh: corotated, implicit Euler, default preconditioner, mass damping inAlpha.
CantileverSettings BeamSettings(const BeamMesh& inMesh, double inAlpha)
{
    CantileverSettings settings;
    settings.mLengthCells = inMesh.mLengthCells;
    settings.mSectionCells = inMesh.mSectionCells;
    settings.mMaterial.mModel = EElasticModel::CorotatedLinear;
    settings.mMaterial.mMassDamping = inAlpha;
    settings.mSolver.mIntegrator = EIntegrator::ImplicitEuler;
    return settings;
}

// The same beam with the implicit step solved to round-off: the converged implicit Euler answer.
CantileverSettings ConvergedSettings(const BeamMesh& inMesh, double inAlpha)
{
    CantileverSettings settings = BeamSettings(inMesh, inAlpha);
    settings.mSolver.mCgRelativeTolerance = 1.0e-12;
    settings.mSolver.mCgMaxIterations = 100000;
    settings.mSolver.mImplicitTolerance = 1.0e-14;
    settings.mSolver.mImplicitMaxIterations = 30;
    return settings;
}

CantileverScene CreateBeam(const CantileverSettings& inSettings)
{
    Result<CantileverScene> beam = CantileverScene::Create(inSettings);
    if (!beam)
    {
        std::fprintf(stderr, "crumple-bench-fem-vs-bullet: beam refused: %s\n",
                     beam.GetError().mMessage.c_str());
        std::exit(1);
    }
    return std::move(beam).Get();
}

// CantileverScene::TipDeflection()'s area weights: its tip load is spread by the same weights, so each tip
// node's share of the load is its weight. Lets the Bullet side use exactly the same measure.
std::vector<double> TipWeights(const CantileverScene& inBeam)
{
    std::vector<double> weights;
    for (int node : inBeam.GetTipNodes())
        weights.push_back(-inBeam.GetSolver().GetExternalForces()[node].z() / inBeam.GetSettings().mLoad);
    return weights;
}

// Area-weighted mean vertical displacement of the tip nodes of the Bullet beam (m, positive down).
double BulletTipDeflection(const BulletDeformableBeam& inBeam, const std::vector<int>& inTip,
                           const std::vector<double>& inWeights)
{
    double deflection = 0.0;
    for (std::size_t i = 0; i < inTip.size(); ++i)
        deflection -=
            inWeights[i] * (inBeam.GetPosition(inTip[i]).z() - inBeam.GetRestPosition(inTip[i]).z());
    return deflection;
}

bool AllFinite(const std::vector<Vec3>& inPositions)
{
    return std::all_of(inPositions.begin(), inPositions.end(),
                       [](const Vec3& inX) { return inX.allFinite(); });
}

/// Solver statistics of a run of Crumple steps.
struct CrumpleStats
{
    int mNewton = 0;           ///< Linear solves, all steps
    int mCg = 0;               ///< CG iterations, all steps
    int mNotConverged = 0;     ///< Steps that reported SolverNotConverged
    bool mFailed = false;      ///< A step was refused or diverged
    double mMaxResidual = 0.0; ///< Largest final relative CG residual
};

// One Crumple step; records its statistics.
void StepCrumple(CantileverScene& ioBeam, CrumpleStats& ioStats)
{
    Result<TetStepResult> step = ioBeam.GetSolver().Step(cFrameTime);
    if (!step)
    {
        ioStats.mFailed = true;
        return;
    }
    ioStats.mNewton += step.Get().mNewtonIterations;
    ioStats.mCg += step.Get().mSolverIterations;
    ioStats.mNotConverged += HasEvent(step.Get().mEvents, ETetStepEvent::SolverNotConverged) ? 1 : 0;
    ioStats.mFailed = ioStats.mFailed || HasEvent(step.Get().mEvents, ETetStepEvent::Diverged);
    ioStats.mMaxResidual = std::max(ioStats.mMaxResidual, step.Get().mSolverResidual);
}

std::string StatsExtra(const CrumpleStats& inStats)
{
    return ";newton=" + std::to_string(inStats.mNewton) + ";cg_iterations=" + std::to_string(inStats.mCg) +
           ";steps_not_converged=" + std::to_string(inStats.mNotConverged) +
           ";max_cg_residual=" + Format(inStats.mMaxResidual);
}

/// The two references of one mesh: static equilibrium and the converged implicit run.
struct References
{
    bool mOk = true;                   ///< Both solved, nothing refused, diverged or NaN
    double mStaticTip = 0.0;           ///< Static tip deflection (m), NaN when the solve was refused
    TetStaticResult mStatic;           ///< Static solve statistics
    std::vector<double> mConvergedTip; ///< Converged run's tip after 0, 1, ..., cSteps steps (m)
    StepTimes mConvergedTimes;         ///< Its step times
    CrumpleStats mConvergedStats;      ///< Its solver statistics
};

// Static equilibrium on a fourth beam, then the converged implicit run on a third, its tip recorded after
// every step so that each side can be compared at the step count it reached.
References RunReferences(const BeamMesh& inMesh, double inAlpha, const std::string& inName)
{
    References references;
    std::printf("  %s: static solve, then converged reference (%d steps)...\n", inName.c_str(), cSteps);
    std::fflush(stdout);
    CantileverScene statics = CreateBeam(BeamSettings(inMesh, inAlpha));
    const Result<TetStaticResult> solved = statics.GetSolver().SolveStatic();
    references.mStaticTip = solved ? statics.TipDeflection() : std::numeric_limits<double>::quiet_NaN();
    if (solved)
        references.mStatic = solved.Get();
    else
        std::fprintf(stderr, "  %s: static solve refused: %s\n", inName.c_str(),
                     solved.GetError().mMessage.c_str());

    CantileverScene converged = CreateBeam(ConvergedSettings(inMesh, inAlpha));
    references.mConvergedTip.push_back(0.0);
    for (int step = 0; step < cSteps; ++step)
    {
        TimeStep(references.mConvergedTimes, [&] { StepCrumple(converged, references.mConvergedStats); });
        references.mConvergedTip.push_back(converged.TipDeflection());
    }
    references.mOk = solved.IsValid() && !references.mConvergedStats.mFailed &&
                     AllFinite(converged.GetSolver().GetPositions());
    return references;
}

/// One side of the interleaved run.
struct SideRun
{
    StepTimes mTimes;         ///< Each step's wall and CPU time
    double mTip = 0.0;        ///< Tip deflection after the last step (m)
    double mWorstError = 0.0; ///< Largest |relative tip error| against the converged run over the steps
    bool mCut = false;        ///< Stopped early by cBulletBudgetSeconds (Bullet only)

    int GetStepCount() const { return static_cast<int>(mTimes.mWallMs.size()); }
};

double Relative(double inValue, double inReference)
{
    return (inValue - inReference) / inReference;
}

// Crumple and Bullet stepped alternately (Crumple, Bullet, Crumple, ...) so that noise from other jobs on the
// machine falls on both alike. The worst error over the steps is kept because the settled tip at T hides how
// far a side strays on the way (the first steps carry the dynamics).
void RunInterleaved(CantileverScene& ioCrumple, CrumpleStats& ioCrumpleStats, BulletDeformableBeam& ioBullet,
                    const std::vector<double>& inConvergedTip, SideRun& outCrumple, SideRun& outBullet)
{
    const std::vector<double> weights = TipWeights(ioCrumple);
    double bullet_seconds = 0.0;
    for (int step = 0; step < cSteps; ++step)
    {
        TimeStep(outCrumple.mTimes, [&] { StepCrumple(ioCrumple, ioCrumpleStats); });
        outCrumple.mTip = ioCrumple.TipDeflection();
        outCrumple.mWorstError =
            std::max(outCrumple.mWorstError, std::abs(Relative(outCrumple.mTip, inConvergedTip[step + 1])));
        if (outBullet.mCut)
            continue;

        TimeStep(outBullet.mTimes, [&] { ioBullet.Step(); });
        outBullet.mTip = BulletTipDeflection(ioBullet, ioCrumple.GetTipNodes(), weights);
        outBullet.mWorstError =
            std::max(outBullet.mWorstError, std::abs(Relative(outBullet.mTip, inConvergedTip[step + 1])));
        // Stop Bullet when one more step of the last one's length would end past the budget.
        const double last_seconds = outBullet.mTimes.mWallMs.back() / 1000.0;
        bullet_seconds += last_seconds;
        outBullet.mCut = step + 1 < cSteps && bullet_seconds + last_seconds > cBulletBudgetSeconds;
    }
}

std::string MeshExtra(const BeamMesh& inMesh, int inTets, double inAlpha, double inStaticTip)
{
    return "tets=" + std::to_string(inTets) + ";cells=" + std::to_string(inMesh.mLengthCells) + "x" +
           std::to_string(inMesh.mSectionCells) + "x" + std::to_string(inMesh.mSectionCells) +
           ";dt_s=" + Format(cFrameTime) + ";alpha_per_s=" + Format(inAlpha) +
           ";static_m=" + Format(inStaticTip);
}

Row CrumpleRow(const std::string& inMeshName, const std::string& inMeshExtra, const TetSolver& inSolver,
               const CrumpleStats& inStats, const SideRun& inRun, const References& inReferences)
{
    const double converged = inReferences.mConvergedTip[cSteps];
    Row row;
    row.mCase = inMeshName + "/crumple";
    row.mMedianMs = Median(inRun.mTimes.mWallMs);
    row.mCpuMs = Median(inRun.mTimes.mCpuMs);
    row.mError = Relative(inRun.mTip, converged);
    row.mStaticError = Relative(inRun.mTip, inReferences.mStaticTip);
    row.mRatio = 1.0;
    row.mExtra = inMeshExtra + ";model=corotated_linear;integrator=implicit_euler;preconditioner=" +
                 ToString(inSolver.GetSettings().mPreconditioner) + ";steps=" + std::to_string(cSteps) +
                 ";time=median_of_" + std::to_string(cSteps) +
                 "_steps;first_step_ms=" + Format(inRun.mTimes.mWallMs.front()) +
                 ";first_step_cpu_ms=" + Format(inRun.mTimes.mCpuMs.front()) +
                 ";factorizations=" + std::to_string(inSolver.GetFactorizationCount()) + StatsExtra(inStats) +
                 ";deflection_m=" + Format(inRun.mTip) + ";converged_m=" + Format(converged) +
                 ";vs_static=" + Format(row.mStaticError) + ";max_step_error=" + Format(inRun.mWorstError);
    return row;
}

Row BulletRow(const std::string& inMeshName, const std::string& inMeshExtra, const Options& inOptions,
              const SideRun& inRun, const Row& inCrumpleRow, const References& inReferences)
{
    const int steps = inRun.GetStepCount();
    const double converged = inReferences.mConvergedTip[static_cast<std::size_t>(steps)];
    Row row;
    row.mCase = inMeshName + "/bullet";
    row.mMedianMs = Median(inRun.mTimes.mWallMs);
    row.mCpuMs = Median(inRun.mTimes.mCpuMs);
    row.mError = Relative(inRun.mTip, converged);
    row.mStaticError = Relative(inRun.mTip, inReferences.mStaticTip);
    row.mRatio = row.mMedianMs / inCrumpleRow.mMedianMs;
    const std::string cut = inRun.mCut ? ";steps_cut_by_budget_s=" + Format(cBulletBudgetSeconds) +
                                             ";error_at_step=" + std::to_string(steps)
                                       : "";
    row.mExtra = inMeshExtra + ";force=btDeformableLinearElasticityForce(corotated_linear)" +
                 ";solver=btDeformableBodySolver_implicit_cg_projection;newton=" +
                 std::to_string(inOptions.mBulletNewtonIterations) +
                 ";cg_max=" + std::to_string(inOptions.mBulletCgIterations) +
                 ";steps=" + std::to_string(steps) + ";time=median_of_" + std::to_string(steps) + "_steps" +
                 cut + ";first_step_ms=" + Format(inRun.mTimes.mWallMs.front()) +
                 ";deflection_m=" + Format(inRun.mTip) + ";converged_m=" + Format(converged) +
                 ";vs_static=" + Format(row.mStaticError) + ";max_step_error=" + Format(inRun.mWorstError) +
                 ";bullet_over_crumple_wall=" + Format(row.mRatio) +
                 ";bullet_over_crumple_cpu=" + Format(row.mCpuMs / inCrumpleRow.mCpuMs);
    return row;
}

// The converged reference's own cost, for scale (its error against itself is 0 by definition).
Row ConvergedRow(const std::string& inMeshName, const std::string& inMeshExtra,
                 const References& inReferences, const Row& inCrumpleRow)
{
    const double converged = inReferences.mConvergedTip[cSteps];
    Row row;
    row.mCase = inMeshName + "/crumple_converged";
    row.mMedianMs = Median(inReferences.mConvergedTimes.mWallMs);
    row.mCpuMs = Median(inReferences.mConvergedTimes.mCpuMs);
    row.mError = 0.0;
    row.mStaticError = Relative(converged, inReferences.mStaticTip);
    row.mRatio = row.mMedianMs / inCrumpleRow.mMedianMs;
    row.mExtra = inMeshExtra + ";cg_tolerance=1e-12;implicit_tolerance=1e-14;max_newton=30;steps=" +
                 std::to_string(cSteps) + StatsExtra(inReferences.mConvergedStats) +
                 ";deflection_m=" + Format(converged) + ";vs_static=" + Format(row.mStaticError) +
                 ";static_newton=" + std::to_string(inReferences.mStatic.mIterations) +
                 ";static_residual=" + Format(inReferences.mStatic.mRelativeResidual);
    return row;
}

/// Runs one mesh: the references, then Crumple and Bullet interleaved. Appends the rows crumple, bullet and
/// crumple_converged; returns false when a side produced a NaN, a step or reference failed, or Bullet's tip
/// did not move.
bool RunMesh(const BeamMesh& inMesh, const Options& inOptions, double inAlpha, std::vector<Row>& ioRows)
{
    // The timed pair: Crumple at its defaults and Bullet built from the same solver at rest.
    CantileverScene crumple = CreateBeam(BeamSettings(inMesh, inAlpha));
    BulletDeformableBeamSettings bullet_settings;
    bullet_settings.mTimeStep = cFrameTime;
    bullet_settings.mMassDamping = inAlpha;
    bullet_settings.mMaxNewtonIterations = inOptions.mBulletNewtonIterations;
    bullet_settings.mCgMaxIterations = inOptions.mBulletCgIterations;
    Result<BulletDeformableBeam> created = BulletDeformableBeam::Create(crumple.GetSolver(), bullet_settings);
    if (!created)
    {
        std::fprintf(stderr, "crumple-bench-fem-vs-bullet: Bullet beam refused: %s\n",
                     created.GetError().mMessage.c_str());
        return false;
    }
    BulletDeformableBeam bullet = std::move(created).Get();

    const int tets = crumple.GetSolver().GetMesh().GetTetCount();
    const std::string mesh_name = std::to_string(tets) + "_tets";
    const References references = RunReferences(inMesh, inAlpha, mesh_name);
    std::printf("  %s: Crumple and Bullet interleaved, %d steps...\n", mesh_name.c_str(), cSteps);
    std::fflush(stdout);
    SideRun crumple_run, bullet_run;
    CrumpleStats crumple_stats;
    RunInterleaved(crumple, crumple_stats, bullet, references.mConvergedTip, crumple_run, bullet_run);

    // Sanity: no NaN, no failed step, and Bullet's load must have moved its tip.
    const bool crumple_ok = !crumple_stats.mFailed && AllFinite(crumple.GetSolver().GetPositions());
    const bool bullet_finite = !bullet.HasNonFinitePosition() && std::isfinite(bullet_run.mTip);
    const bool bullet_moved =
        bullet_finite && std::abs(bullet_run.mTip) > cMinMovedFraction * std::abs(references.mStaticTip);
    if (!references.mOk)
        std::fprintf(stderr, "  %s: a reference failed (static solve or converged run)\n", mesh_name.c_str());
    if (!crumple_ok)
        std::fprintf(stderr, "  %s: Crumple produced a NaN or a failed step\n", mesh_name.c_str());
    if (!bullet_finite)
        std::fprintf(stderr, "  %s: Bullet produced a NaN\n", mesh_name.c_str());
    else if (!bullet_moved)
        std::fprintf(stderr, "  %s: Bullet's tip did not move (%.3e m)\n", mesh_name.c_str(),
                     bullet_run.mTip);

    const std::string mesh_extra = MeshExtra(inMesh, tets, inAlpha, references.mStaticTip);
    const Row crumple_row =
        CrumpleRow(mesh_name, mesh_extra, crumple.GetSolver(), crumple_stats, crumple_run, references);
    ioRows.push_back(crumple_row);
    ioRows.push_back(BulletRow(mesh_name, mesh_extra, inOptions, bullet_run, crumple_row, references));
    ioRows.push_back(ConvergedRow(mesh_name, mesh_extra, references, crumple_row));
    return references.mOk && crumple_ok && bullet_finite && bullet_moved;
}

void PrintTable(const std::vector<Row>& inRows)
{
    std::printf("\n%-14s %-28s %12s %12s %12s %12s %9s\n", "benchmark", "case", "wall_ms", "cpu_ms",
                "err_vs_conv", "err_vs_static", "vs_crumple");
    for (const Row& row : inRows)
        std::printf("%-14s %-28s %12.3f %12.3f %12.3e %12.3e %9.3g\n", cBenchmark, row.mCase.c_str(),
                    row.mMedianMs, row.mCpuMs, row.mError, row.mStaticError, row.mRatio);
    std::printf("\nextra:\n");
    for (const Row& row : inRows)
        std::printf("  %-28s %s\n", row.mCase.c_str(), row.mExtra.c_str());
}

bool WriteCsv(const std::string& inPath, const std::vector<Row>& inRows)
{
    std::ofstream out(inPath);
    if (!out)
        return false;
    out << "benchmark,case,median_ms,cpu_ms,error,error_unit,extra\n";
    char numbers[96];
    for (const Row& row : inRows)
    {
        std::snprintf(numbers, sizeof(numbers), "%.6f,%.6f,%.6e", row.mMedianMs, row.mCpuMs, row.mError);
        out << cBenchmark << ',' << row.mCase << ',' << numbers << ',' << cErrorUnit << ',' << row.mExtra
            << '\n';
    }
    return static_cast<bool>(out.flush());
}

// Parses a positive integer argument; false when it is not one.
bool ParseCount(const char* inText, int& outValue)
{
    char* end = nullptr;
    const long value = std::strtol(inText, &end, 10);
    if (end == inText || *end != '\0' || value < 1 || value > 1000000)
        return false;
    outValue = static_cast<int>(value);
    return true;
}

// Returns 0 to run, 1 for --help/--version (already answered), 2 for a bad argument.
int ParseOptions(int inArgc, char** inArgv, Options& outOptions)
{
    for (int i = 1; i < inArgc; ++i)
    {
        const std::string arg = inArgv[i];
        if (arg == "--help" || arg == "-h")
        {
            std::printf(
                "usage: crumple-bench-fem-vs-bullet [--quick] [--csv FILE] [--bullet-newton N] [--bullet-cg "
                "N]\n"
                "  Steps Crumple's implicit FEM and Bullet's implicit deformable solver on the same steel\n"
                "  cantilever (1k, 9k and 98k tets), interleaved, 10 steps of 1/60 s each, and reports the\n"
                "  median step time and the tip error against the converged implicit and static answers.\n"
                "  --quick            only the 1k-tet mesh (a smoke run)\n"
                "  --csv FILE         also write rows "
                "benchmark,case,median_ms,cpu_ms,error,error_unit,extra\n"
                "  --bullet-newton N  Bullet's Newton iterations per step (default 1, Bullet's own)\n"
                "  --bullet-cg N      Bullet's CG iterations per solve (default 300, Bullet's own)\n");
            return 1;
        }
        if (arg == "--version")
        {
            std::printf("crumple-bench-fem-vs-bullet %s\n", crumple::VersionString());
            return 1;
        }
        if (arg == "--quick")
            outOptions.mQuick = true;
        else if (arg == "--csv" && i + 1 < inArgc)
            outOptions.mCsv = inArgv[++i];
        else if (arg == "--bullet-newton" && i + 1 < inArgc &&
                 ParseCount(inArgv[i + 1], outOptions.mBulletNewtonIterations))
            ++i;
        else if (arg == "--bullet-cg" && i + 1 < inArgc &&
                 ParseCount(inArgv[i + 1], outOptions.mBulletCgIterations))
            ++i;
        else
        {
            std::fprintf(stderr, "crumple-bench-fem-vs-bullet: bad argument '%s' (see --help)\n",
                         arg.c_str());
            return 2;
        }
    }
    return 0;
}

} // namespace

} // namespace crumple::bench

int main(int argc, char** argv)
{
    using namespace crumple::bench;
    Options options;
    if (const int parsed = ParseOptions(argc, argv, options); parsed != 0)
        return parsed == 1 ? 0 : 2;

    // Rayleigh mass damping alpha = 2 omega_1, omega_1 = 2 pi f_EB the analytic first bending mode (81.5 Hz):
    // near-critical for that mode, as in crumple-bench's fem group, so that after T = 1/6 s both sides should
    // be close to static equilibrium. Bullet's m_damping_alpha is the same -alpha M v force.
    const double alpha =
        4.0 * std::numbers::pi * crumple::common::EulerBernoulliFrequency(CantileverSettings());

    // Meshes of about 1k, 9k and 98k tetrahedra (five per cell, cells close to cubic); --quick only the 1k.
    std::vector<BeamMesh> meshes = {{25, 3}};
    if (!options.mQuick)
    {
        meshes.push_back({50, 6});
        meshes.push_back({100, 14});
    }

    std::printf("crumple-bench-fem-vs-bullet %s%s: running\n", crumple::VersionString(),
                options.mQuick ? " (quick)" : "");
    std::vector<Row> rows;
    bool ok = true;
    for (const BeamMesh& mesh : meshes)
        ok = RunMesh(mesh, options, alpha, rows) && ok;
    PrintTable(rows);
    if (!options.mCsv.empty() && !WriteCsv(options.mCsv, rows))
    {
        std::fprintf(stderr, "crumple-bench-fem-vs-bullet: cannot write %s\n", options.mCsv.c_str());
        return 1;
    }
    return ok ? 0 : 1;
}
