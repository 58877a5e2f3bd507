// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "Benchmarks.h"

#if defined(CRUMPLE_BENCH_FEM)
#include <crumple/fem/TetGrid.h>
#include <crumple/fem/TetSolver.h>
#endif

#include <algorithm>
#include <chrono>
#include <numeric>
#include <string>
#include <vector>

namespace crumple::bench
{

#if defined(CRUMPLE_BENCH_FEM)

using namespace crumple::fem;

namespace
{

constexpr double cStep = 1.0 / 240.0; ///< The racing fence's step: one engine step (s)
constexpr int cSteps = 24;            ///< 0.1 s: the push, then the rail swinging back
constexpr int cPushSteps = 6;         ///< Steps in which the car pushes

/// A rail of a soft barrier material (E = 100 MPa), 10 cm square, its end faces anchored: cells along it and
/// across each side.
struct RailMesh
{
    double mLength;
    int mLengthCells;
    int mSectionCells;
};

TetGridSettings RailGrid(const RailMesh& inMesh)
{
    TetGridSettings grid;
    grid.mSize = Vec3(inMesh.mLength, 0.1, 0.1);
    grid.mCellCount = {inMesh.mLengthCells, inMesh.mSectionCells, inMesh.mSectionCells};
    return grid;
}

TetSolver MakeRail(const RailMesh& inMesh, const TetSolverSettings& inSettings)
{
    const TetGridSettings grid = RailGrid(inMesh);
    FemMaterialSettings material;
    material.mYoungsModulus = 1.0e8;
    material.mPoissonRatio = 0.3;
    material.mDensity = 600.0;
    TetSolver rail = TetSolver::Create(TetGrid(grid).Get(), material, inSettings).Get();
    for (int i : {0, inMesh.mLengthCells})
        for (int j = 0; j <= inMesh.mSectionCells; ++j)
            for (int k = 0; k <= inMesh.mSectionCells; ++k)
                (void)rail.SetNodeFixed(TetGridNode(grid.mCellCount, i, j, k), true);
    return rail;
}

// The car's push on the middle of the rail's front face: 180 N s per step in all, spread over the face's
// middle column of nodes.
void Push(const RailMesh& inMesh, TetSolver& ioRail)
{
    const TetGridSettings grid = RailGrid(inMesh);
    const double per_node = 180.0 / (inMesh.mSectionCells + 1);
    for (int k = 0; k <= inMesh.mSectionCells; ++k)
        (void)ioRail.ApplyImpulse(TetGridNode(grid.mCellCount, inMesh.mLengthCells / 2, 0, k), Vec3(0.0, per_node, 0.0));
}

void RefreshCase(BenchTable& ioTable, const RailMesh& inMesh)
{
    // Side 0 never refreshes, side 1 refreshes after 3 iterations; both stepped alternately, step by step.
    TetSolverSettings plain, refreshing, converged;
    refreshing.mFactorRefreshIterations = 3;
    converged.mCgRelativeTolerance = 1.0e-12;
    converged.mCgMaxIterations = 100000;
    converged.mImplicitTolerance = 1.0e-14;
    converged.mImplicitMaxIterations = 30;
    std::vector<TetSolver> rails = {MakeRail(inMesh, plain), MakeRail(inMesh, refreshing)};
    TetSolver reference = MakeRail(inMesh, converged);
    for (TetSolver& rail : rails)
        (void)rail.Prepare(cStep);
    (void)reference.Prepare(cStep);
    std::vector<double> wall[2], cpu[2];
    int iterations[2] = {0, 0};
    double worst_error[2] = {0.0, 0.0};
    double largest_displacement = 0.0;
    bool failed = false;
    for (int step = 0; step < cSteps; ++step)
    {
        for (int side = 0; side < 2; ++side)
        {
            TetSolver& rail = rails[static_cast<std::size_t>(side)];
            if (step < cPushSteps)
                Push(inMesh, rail);
            const double cpu_start = ThreadCpuMs();
            const auto wall_start = std::chrono::steady_clock::now();
            const Result<TetStepResult> result = rail.Step(cStep);
            wall[side].push_back(ElapsedMs(wall_start));
            cpu[side].push_back(ThreadCpuMs() - cpu_start);
            failed = failed || !result || HasEvent(result.Get().mEvents, ETetStepEvent::Diverged);
            iterations[side] += result ? result.Get().mSolverIterations : 0;
        }
        if (step < cPushSteps)
            Push(inMesh, reference);
        failed = failed || !reference.Step(cStep);
        // Error: the largest distance of a node from the converged solve's, at every step.
        for (std::size_t node = 0; node < reference.GetPositions().size(); ++node)
        {
            largest_displacement = std::max(largest_displacement, (reference.GetPositions()[node] - reference.GetMesh().GetRestPositions()[node]).norm());
            for (int side = 0; side < 2; ++side)
                worst_error[side] = std::max(worst_error[side],
                                             (rails[static_cast<std::size_t>(side)].GetPositions()[node] - reference.GetPositions()[node]).norm());
        }
    }
    const std::string mesh = std::to_string(rails[0].GetElementNodes().size()) + "_tets";
    for (int side = 0; side < 2; ++side)
    {
        const TetSolver& rail = rails[static_cast<std::size_t>(side)];
        ioTable.Add({"fem_refresh", "pushed_rail/" + mesh + (side == 0 ? "/rest_factor" : "/refresh_after_3"),
                     Median(wall[side]), failed ? -1.0 : worst_error[side] / largest_displacement, "max_node_error_over_max_displacement",
                     "cpu_ms=" + FormatExtra(Median(cpu[side])) +
                         ";total_cpu_ms=" + FormatExtra(std::accumulate(cpu[side].begin(), cpu[side].end(), 0.0)) + ";cg_iterations=" + std::to_string(iterations[side]) +
                         ";refreshes=" + std::to_string(rail.GetFactorRefreshCount()) +
                         ";factorizations=" + std::to_string(rail.GetFactorizationCount()) + ";steps=" + std::to_string(cSteps) +
                         ";max_displacement_m=" + FormatExtra(largest_displacement) + (failed ? ";error=step_failed" : "")});
    }
}

} // namespace

void RunFemRefreshBenchmarks(BenchTable& ioTable, const BenchOptions& inOptions)
{
    // About 800 and 6,400 tetrahedra (five per cell); --quick only the first.
    std::vector<RailMesh> meshes = {{2.0, 40, 2}};
    if (!inOptions.mQuick)
        meshes.push_back({4.0, 80, 4});
    for (const RailMesh& mesh : meshes)
        RefreshCase(ioTable, mesh);
}

#else

void RunFemRefreshBenchmarks(BenchTable&, const BenchOptions&) {}

#endif

} // namespace crumple::bench
