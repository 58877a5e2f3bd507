// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// contact_mass: TetSolver::ContactEffectiveMass (the mass a held prop body stands in with) on the two fences
// the samples and tests drive through, with the factored rest system and with block Jacobi, alternated; error
// against the mass one converged implicit step shows.
#include "Benchmarks.h"

#if defined(CRUMPLE_BENCH_FEM)
#include <crumple/fem/PropMaterialPreset.h>
#include <crumple/fem/TetFence.h>
#include <crumple/fem/TetSolver.h>
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

namespace crumple::bench
{

#if defined(CRUMPLE_BENCH_FEM)

using namespace crumple::fem;

namespace
{

constexpr double cStep = 1.0 / 120.0; // s: the engine scenes' step

struct FenceCase
{
    const char* mName;
    double mThickness;   // m
    double mCellSize;    // m
    double mPostSpacing; // m
};

Result<TetSolver> MakeFence(const FenceCase& inCase, const TetSolverSettings& inSettings)
{
    TetFenceSettings settings;
    settings.mLength = 4.0;
    settings.mHeight = 1.2;
    settings.mThickness = inCase.mThickness;
    settings.mCellSize = inCase.mCellSize;
    settings.mPostSpacing = inCase.mPostSpacing;
    Result<TetFence> fence = MakeTetFence(settings);
    if (!fence)
        return fence.GetError();
    Result<PropMaterialPreset> wood = MakePropMaterialPreset(EPropMaterial::Wood);
    if (!wood)
        return wood.GetError();
    Result<TetSolver> solver = TetSolver::Create(fence.Get().mMesh, wood.Get().mMaterial, inSettings);
    if (!solver)
        return solver;
    if (Status fixed = solver.Get().SetNodesFixed(fence.Get().mGroundNodes, true); !fixed)
        return fixed.GetError();
    if (Status prepared = solver.Get().Prepare(cStep); !prepared)
        return prepared.GetError();
    return solver;
}

void ContactMassCase(BenchTable& ioTable, const FenceCase& inCase, int inRepetitions)
{
    TetSolverSettings factored, jacobi, converged;
    for (TetSolverSettings* settings : {&factored, &jacobi, &converged})
        settings->mGravity = Vec3::Zero();
    jacobi.mPreconditioner = EImplicitPreconditioner::BlockJacobi;
    converged.mCgRelativeTolerance = 1.0e-12;
    converged.mCgMaxIterations = 100000;
    converged.mImplicitTolerance = 1.0e-14;
    converged.mImplicitMaxIterations = 30;
    Result<TetSolver> sides[2] = {MakeFence(inCase, factored), MakeFence(inCase, jacobi)};
    Result<TetSolver> reference = MakeFence(inCase, converged);
    if (!sides[0] || !sides[1] || !reference)
    {
        std::printf("contact_mass/%s: could not build the fence\n", inCase.mName);
        return;
    }
    // The lower rail's front face half-way between two posts, every free node within 0.1 m, equal shares.
    const Vec3 point(0.5 * inCase.mPostSpacing, 0.0, 0.4);
    std::vector<int> nodes;
    double lumped = 0.0, whole = 0.0;
    const TetSolver& shape = reference.Get();
    for (int node = 0; node < shape.GetNodeCount(); ++node)
    {
        whole += shape.GetMasses()[static_cast<std::size_t>(node)];
        if ((shape.GetPositions()[static_cast<std::size_t>(node)] - point).norm() < 0.1 &&
            shape.GetInverseMasses()[static_cast<std::size_t>(node)] > 0.0)
        {
            nodes.push_back(node);
            lumped += shape.GetMasses()[static_cast<std::size_t>(node)];
        }
    }
    const std::vector<double> shares(nodes.size(), 1.0);
    // The mass one converged step shows a 1 mN s impulse (the step is linear in so small a push).
    TetSolver probe = reference.Get();
    for (int node : nodes)
        (void)probe.ApplyImpulse(node, Vec3(0.0, 1.0e-3 / static_cast<double>(nodes.size()), 0.0));
    (void)probe.Step(cStep);
    double velocity = 0.0;
    for (int node : nodes)
        velocity +=
            probe.GetVelocities()[static_cast<std::size_t>(node)].y() / static_cast<double>(nodes.size());
    const double shown = 1.0e-3 / velocity;

    std::vector<double> wall[2], cpu[2];
    double mass[2] = {0.0, 0.0};
    int iterations[2] = {0, 0};
    bool finished[2] = {false, false};
    for (int rep = 0; rep < inRepetitions; ++rep)
        for (int side = 0; side < 2; ++side)
        {
            const double cpu_start = ThreadCpuMs();
            const auto wall_start = std::chrono::steady_clock::now();
            const Result<TetContactMass> result =
                sides[side].Get().ContactEffectiveMass(nodes, shares, Vec3::UnitY(), cStep);
            wall[side].push_back(ElapsedMs(wall_start));
            cpu[side].push_back(ThreadCpuMs() - cpu_start);
            mass[side] = result ? result.Get().mMass : -1.0;
            iterations[side] = result ? result.Get().mIterations : 0;
            finished[side] = result && result.Get().mConverged;
        }
    const std::string mesh = std::to_string(shape.GetElementNodes().size()) + "_tets";
    const char* names[2] = {"rest_factor", "block_jacobi"};
    for (int side = 0; side < 2; ++side)
        ioTable.Add({"contact_mass", std::string(inCase.mName) + "/" + mesh + "/mid_rail_0.1m/" + names[side],
                     Median(wall[side]), mass[side] > 0.0 ? std::abs(mass[side] - shown) / shown : -1.0,
                     "rel_vs_one_converged_step",
                     "cpu_ms=" + FormatExtra(Median(cpu[side])) + ";mass_kg=" + FormatExtra(mass[side]) +
                         ";cg_iterations=" + std::to_string(iterations[side]) + ";converged=" +
                         (finished[side] ? "1" : "0") + ";struck_nodes=" + std::to_string(nodes.size()) +
                         ";struck_nodes_own_kg=" + FormatExtra(lumped) +
                         ";whole_fence_kg=" + FormatExtra(whole) +
                         (side == 1 ? ";cpu_ratio_to_rest_factor=" +
                                          FormatExtra(Median(cpu[1]) / std::max(Median(cpu[0]), 1e-9))
                                    : "")});
}

} // namespace

void RunContactMassBenchmarks(BenchTable& ioTable, const BenchOptions& inOptions)
{
    // The racing fence (10 cm timbers in 5 cm cubes, posts 4 m apart) and the drive-through test's (5 cm
    // planks in 2.5 cm cubes, posts 2 m apart).
    ContactMassCase(ioTable, {"racing_fence", 0.1, 0.05, 4.0}, inOptions.mQuick ? 3 : 15);
    if (!inOptions.mQuick)
        ContactMassCase(ioTable, {"drive_through_fence", 0.05, 0.025, 2.0}, 7);
}

#else

void RunContactMassBenchmarks(BenchTable&, const BenchOptions&) {}

#endif

} // namespace crumple::bench
