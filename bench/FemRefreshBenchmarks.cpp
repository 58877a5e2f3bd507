// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "Benchmarks.h"

#if defined(CRUMPLE_BENCH_FEM)
#include <crumple/fem/TetGrid.h>
#include <crumple/fem/TetSolver.h>
#endif

#include <algorithm>
#include <chrono>
#include <iterator>
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
constexpr int cSteps = 48;            ///< 0.2 s: the push, then the rail swinging back and settling
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

// The refresh policies compared, stepped in turn step by step: never, after 3 iterations, after 6 (the held
// props' setting before mFactorRefreshByCost), after 6 and by cost (the held props' setting).
struct RefreshSide
{
    const char* mName;
    int mIterations;
    bool mByCost;
};
constexpr RefreshSide cSides[] = {{"rest_factor", 0, false},
                                  {"refresh_after_3", 3, false},
                                  {"refresh_after_6", 6, false},
                                  {"refresh_by_cost", 6, true}};
constexpr int cSideCount = static_cast<int>(std::size(cSides));

void RefreshCase(BenchTable& ioTable, const RailMesh& inMesh)
{
    TetSolverSettings converged;
    converged.mCgRelativeTolerance = 1.0e-12;
    converged.mCgMaxIterations = 100000;
    converged.mImplicitTolerance = 1.0e-14;
    converged.mImplicitMaxIterations = 30;
    std::vector<TetSolver> rails;
    for (const RefreshSide& side : cSides)
    {
        TetSolverSettings settings;
        settings.mFactorRefreshIterations = side.mIterations;
        settings.mFactorRefreshByCost = side.mByCost;
        rails.push_back(MakeRail(inMesh, settings));
    }
    TetSolver reference = MakeRail(inMesh, converged);
    for (TetSolver& rail : rails)
        (void)rail.Prepare(cStep);
    (void)reference.Prepare(cStep);
    std::vector<double> wall[cSideCount], cpu[cSideCount];
    int iterations[cSideCount] = {};
    double worst_error[cSideCount] = {};
    double largest_displacement = 0.0;
    bool failed = false;
    for (int step = 0; step < cSteps; ++step)
    {
        for (int side = 0; side < cSideCount; ++side)
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
            for (int side = 0; side < cSideCount; ++side)
                worst_error[side] = std::max(worst_error[side],
                                             (rails[static_cast<std::size_t>(side)].GetPositions()[node] - reference.GetPositions()[node]).norm());
        }
    }
    const std::string mesh = std::to_string(rails[0].GetElementNodes().size()) + "_tets";
    for (int side = 0; side < cSideCount; ++side)
    {
        const TetSolver& rail = rails[static_cast<std::size_t>(side)];
        ioTable.Add(
            {"fem_refresh", "pushed_rail/" + mesh + "/" + cSides[side].mName, Median(wall[side]),
             failed ? -1.0 : worst_error[side] / largest_displacement, "max_node_error_over_max_displacement",
             "cpu_ms=" + FormatExtra(Median(cpu[side])) +
                 ";total_cpu_ms=" + FormatExtra(std::accumulate(cpu[side].begin(), cpu[side].end(), 0.0)) +
                 ";cg_iterations=" + std::to_string(iterations[side]) +
                 ";refreshes=" + std::to_string(rail.GetFactorRefreshCount()) +
                 ";factorizations=" + std::to_string(rail.GetFactorizationCount()) +
                 ";refresh_cost_iterations=" + FormatExtra(rail.GetFactorRefreshCost()) + ";steps=" +
                 std::to_string(cSteps) + ";max_displacement_m=" + FormatExtra(largest_displacement) +
                 (failed ? ";error=step_failed" : "")});
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
