// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "Benchmarks.h"

#if defined(CRUMPLE_BENCH_FEM)
#include <PushedRail.h>

#include <crumple/fem/TetSolver.h>
#endif

#include <chrono>
#include <limits>
#include <numeric>
#include <string>
#include <vector>

namespace crumple::bench
{

#if defined(CRUMPLE_BENCH_FEM)

using namespace crumple::fem;

namespace
{

void CrackBoundCase(BenchTable& ioTable, double inImpulse)
{
    // Side 0 has the crack-safe bound (the default), side 1 the energy test alone, side 2 the bound with the
    // factor refreshed after 6 iterations, side 3 also by cost, as a held prop's solver
    // (props::HeldPropSolverSettings, the racing fence's); all pushed and stepped in turn, step by step. The
    // reference converges to round-off and is not timed.
    TetSolverSettings bounded, energy_only, refreshing, held, converged;
    bounded.mGravity = energy_only.mGravity = refreshing.mGravity = held.mGravity = converged.mGravity =
        Vec3::Zero();
    energy_only.mCrackStressTolerance = std::numeric_limits<double>::infinity();
    refreshing.mFactorRefreshIterations = 6;
    held.mFactorRefreshIterations = 6;
    held.mFactorRefreshByCost = true;
    converged.mImplicitTolerance = 1.0e-12;
    converged.mImplicitMaxIterations = 40;
    converged.mCgRelativeTolerance = 1.0e-10;
    converged.mCrackStressTolerance = std::numeric_limits<double>::infinity();
    std::vector<TetSolver> rails = {
        common::MakePushedRailSolver(bounded).Get(), common::MakePushedRailSolver(energy_only).Get(),
        common::MakePushedRailSolver(refreshing).Get(), common::MakePushedRailSolver(held).Get()};
    constexpr int cSides = 4;
    const char* const names[cSides] = {"crack_bound_0.5", "energy_test_alone",
                                       "crack_bound_0.5/refresh_after_6", "crack_bound_0.5/refresh_by_cost"};
    TetSolver reference = common::MakePushedRailSolver(converged).Get();
    for (TetSolver& rail : rails)
        (void)rail.Prepare(common::cPushedRailStep);
    (void)reference.Prepare(common::cPushedRailStep);
    const std::vector<int> struck = common::PushedRailNodes(reference.GetPositions());
    std::vector<double> wall[cSides], cpu[cSides];
    int newton[cSides] = {}, cg[cSides] = {}, refreshes[cSides] = {};
    bool failed = false;
    for (int step = 0; step < common::cPushedRailSteps; ++step)
    {
        for (int side = 0; side < cSides; ++side)
        {
            TetSolver& rail = rails[static_cast<std::size_t>(side)];
            failed = failed || !common::PushRailBeforeStep(rail, struck, step, inImpulse);
            const double cpu_start = ThreadCpuMs();
            const auto wall_start = std::chrono::steady_clock::now();
            const Result<TetStepResult> result = rail.Step(common::cPushedRailStep);
            wall[side].push_back(ElapsedMs(wall_start));
            cpu[side].push_back(ThreadCpuMs() - cpu_start);
            failed = failed || !result || HasEvent(result.Get().mEvents, ETetStepEvent::Diverged);
            newton[side] += result ? result.Get().mNewtonIterations : 0;
            cg[side] += result ? result.Get().mSolverIterations : 0;
        }
        failed = failed || !common::PushRailBeforeStep(reference, struck, step, inImpulse) ||
                 !reference.Step(common::cPushedRailStep);
    }
    // Error: the links whose state differs from the converged solve's, over the links it broke.
    const int cracked = reference.GetBrokenLinkCount();
    double total_cpu[cSides];
    for (int side = 0; side < cSides; ++side)
    {
        total_cpu[side] = std::accumulate(cpu[side].begin(), cpu[side].end(), 0.0);
        refreshes[side] = rails[static_cast<std::size_t>(side)].GetFactorRefreshCount();
    }
    for (int side = 0; side < cSides; ++side)
    {
        const int differing = CountDiffering(rails[static_cast<std::size_t>(side)].GetBrokenLinks(),
                                             reference.GetBrokenLinks());
        ioTable.Add(
            {"fem_cracks", "pushed_rail/" + std::to_string(static_cast<int>(inImpulse)) + "Ns/" + names[side],
             Median(wall[side]), failed || cracked == 0 ? -1.0 : static_cast<double>(differing) / cracked,
             "links_off_converged_over_links_cracked",
             "cpu_ms=" + FormatExtra(Median(cpu[side])) + ";total_cpu_ms=" + FormatExtra(total_cpu[side]) +
                 ";total_wall_ms=" + FormatExtra(std::accumulate(wall[side].begin(), wall[side].end(), 0.0)) +
                 ";cpu_over_energy_test_alone=" + FormatExtra(total_cpu[side] / total_cpu[1]) +
                 ";newton_iterations=" + std::to_string(newton[side]) + ";cg_iterations=" +
                 std::to_string(cg[side]) + ";refreshes=" + std::to_string(refreshes[side]) +
                 ";links_off=" + std::to_string(differing) + ";links_converged=" + std::to_string(cracked) +
                 ";steps=" + std::to_string(common::cPushedRailSteps) +
                 (failed ? ";error=step_failed" : "")});
    }
}

} // namespace

void RunCrackBoundBenchmarks(BenchTable& ioTable, const BenchOptions& inOptions)
{
    // 200 and 300 N s per push step (the test's impulses); --quick only the first.
    CrackBoundCase(ioTable, 200.0);
    if (!inOptions.mQuick)
        CrackBoundCase(ioTable, 300.0);
}

#else

void RunCrackBoundBenchmarks(BenchTable&, const BenchOptions&) {}

#endif

} // namespace crumple::bench
