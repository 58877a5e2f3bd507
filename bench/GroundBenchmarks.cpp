// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// fem_ground: what a ground (TetSolverSettings::mGround) costs and saves. A wooden rail left hanging at one
// end swings down under gravity; with the ground it lands, lies still and sleeps, without it swings through
// where the ground would be for as long as its damping lets it. The two are stepped alternately (A, B, A, B).
#include "Benchmarks.h"

#if defined(CRUMPLE_BENCH_FEM)
#include <crumple/fem/PropMaterialPreset.h>
#include <crumple/fem/TetGrid.h>
#include <crumple/fem/TetSolver.h>
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace crumple::bench
{

#if defined(CRUMPLE_BENCH_FEM)

using namespace crumple::fem;

namespace
{

constexpr double cStep = 1.0 / 240.0; // s: the racing samples' engine step
constexpr double cRailLength = 1.2;   // m
constexpr double cRailSection = 0.1;  // m, square
constexpr double cHingeHeight = 0.55; // m: the rail's top edge at its hinge

// Height of the rail's centre where it comes to rest, rigid: turned down about its hinge until its far lower
// corner meets the ground, cHingeHeight - L sin(a) - S cos(a) = 0 (bisection).
double RigidRestCentreHeight()
{
    double low = 0.0, high = 0.5 * 3.141592653589793;
    for (int i = 0; i < 200; ++i)
    {
        const double mid = 0.5 * (low + high);
        (cHingeHeight - cRailLength * std::sin(mid) - cRailSection * std::cos(mid) > 0.0 ? low : high) = mid;
    }
    const double angle = 0.5 * (low + high);
    return cHingeHeight - 0.5 * cRailLength * std::sin(angle) - 0.5 * cRailSection * std::cos(angle);
}

// A rail left hanging at one end (as the racing fence's, when a post's links break): 1.2 m of 10 cm timber
// of the wood preset made unbreakable (the hinge must hold for the comparison), 5 cm cubes, level at first,
// anchored along the top edge of one end only, so that gravity swings it down about that edge.
Result<TetSolver> MakeRail(bool inGround)
{
    TetGridSettings grid;
    grid.mOrigin = Vec3(0.0, 0.0, cHingeHeight - cRailSection);
    grid.mSize = Vec3(cRailLength, cRailSection, cRailSection);
    grid.mCellCount = {24, 2, 2};
    Result<TetMesh> mesh = TetGrid(grid);
    if (!mesh)
        return mesh.GetError();
    Result<PropMaterialPreset> wood = MakePropMaterialPreset(EPropMaterial::Wood);
    if (!wood)
        return wood.GetError();
    FemMaterialSettings material = wood.Get().mMaterial;
    material.mTensileStrength = std::numeric_limits<double>::infinity();
    TetSolverSettings settings;
    settings.mGravity = Vec3(0.0, 0.0, -9.81);
    settings.mGround = GroundPlane{inGround, Vec3::UnitZ(), 0.0, 0.6};
    Result<TetSolver> solver = TetSolver::Create(mesh.Get(), material, settings);
    if (!solver)
        return solver;
    std::vector<int> hinge;
    for (int j = 0; j <= grid.mCellCount[1]; ++j)
        hinge.push_back(TetGridNode(grid.mCellCount, 0, j, grid.mCellCount[2]));
    if (Status fixed = solver.Get().SetNodesFixed(hinge, true); !fixed)
        return fixed.GetError();
    if (Status prepared = solver.Get().Prepare(cStep); !prepared)
        return prepared.GetError();
    return solver;
}

} // namespace

void RunGroundBenchmarks(BenchTable& ioTable, const BenchOptions& inOptions)
{
    Result<TetSolver> sides[2] = {MakeRail(true), MakeRail(false)};
    if (!sides[0] || !sides[1])
    {
        std::printf("fem_ground: could not build the rail\n");
        return;
    }
    const int steps = static_cast<int>(std::lround((inOptions.mQuick ? 3.0 : 10.0) / cStep));
    std::vector<double> wall[2], cpu[2];
    int awake[2] = {0, 0}, fell_asleep_at[2] = {-1, -1};
    double deepest[2] = {0.0, 0.0};
    for (int step = 0; step < steps; ++step)
        for (int side = 0; side < 2; ++side)
        {
            TetSolver& solver = sides[side].Get();
            const double cpu_start = ThreadCpuMs();
            const auto wall_start = std::chrono::steady_clock::now();
            const Result<TetStepResult> result = solver.Step(cStep);
            const double wall_ms = ElapsedMs(wall_start), cpu_ms = ThreadCpuMs() - cpu_start;
            if (!result)
            {
                std::printf("fem_ground: step failed: %s\n", result.GetError().mMessage.c_str());
                return;
            }
            if (HasEvent(result.Get().mEvents, ETetStepEvent::Sleeping))
                continue;
            ++awake[side];
            wall[side].push_back(wall_ms);
            cpu[side].push_back(cpu_ms);
            if (HasEvent(result.Get().mEvents, ETetStepEvent::FellAsleep) && fell_asleep_at[side] < 0)
                fell_asleep_at[side] = step;
            for (const Vec3& position : solver.GetPositions())
                deepest[side] = std::max(deepest[side], -position.z());
        }
    // Error of the grounded rail: how far its centre rests from where a rigid rail would (on its hinge and
    // its far lower corner); the deepest any node went below the ground beside it.
    Vec3 centre = Vec3::Zero();
    double mass = 0.0;
    const TetSolver& grounded = sides[0].Get();
    for (std::size_t node = 0; node < grounded.GetPositions().size(); ++node)
    {
        centre += grounded.GetMasses()[node] * grounded.GetPositions()[node];
        mass += grounded.GetMasses()[node];
    }
    centre /= mass;
    const char* names[2] = {"with_ground", "without_ground"};
    const double simulated = steps * cStep;
    for (int side = 0; side < 2; ++side)
    {
        double total_cpu = 0.0, total_wall = 0.0;
        for (std::size_t i = 0; i < cpu[side].size(); ++i)
        {
            total_cpu += cpu[side][i];
            total_wall += wall[side][i];
        }
        ioTable.Add(
            {"fem_ground",
             "hanging_rail/" + std::to_string(grounded.GetElementNodes().size()) + "_tets/" + names[side],
             wall[side].empty() ? 0.0 : Median(wall[side]),
             side == 0 ? std::abs(centre.z() - RigidRestCentreHeight()) : -1.0,
             side == 0 ? "m_rest_centre_vs_rigid" : "none",
             "cpu_ms_per_awake_step=" + FormatExtra(cpu[side].empty() ? 0.0 : Median(cpu[side])) +
                 ";awake_steps=" + std::to_string(awake[side]) + "_of_" + std::to_string(steps) +
                 ";asleep_at_s=" +
                 FormatExtra(fell_asleep_at[side] < 0 ? -1.0 : fell_asleep_at[side] * cStep) +
                 ";fem_cpu_ms_in_all=" + FormatExtra(total_cpu) +
                 ";fem_wall_ms_in_all=" + FormatExtra(total_wall) + ";simulated_s=" + FormatExtra(simulated) +
                 ";deepest_below_ground_m=" + FormatExtra(deepest[side])});
    }
}

#else

void RunGroundBenchmarks(BenchTable&, const BenchOptions&) {}

#endif

} // namespace crumple::bench
