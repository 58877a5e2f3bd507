// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "GpuTestScenes.h"

#include <crumple/fem/TetGrid.h>

#include <BrittleMaterial.h>
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>

namespace crumple::test
{

fem::FemMaterialSettings SoftBarMaterial(fem::EElasticModel inModel)
{
    fem::FemMaterialSettings material;
    material.mYoungsModulus = 1.0e7;
    material.mPoissonRatio = 0.3;
    material.mDensity = 1000.0;
    material.mMassDamping = 1.0;
    material.mStiffnessDamping = 1.0e-4;
    material.mModel = inModel;
    return material;
}

fem::TetSolver ClampedBar(const fem::FemMaterialSettings& inMaterial,
                          const fem::TetSolverSettings& inSettings)
{
    fem::TetGridSettings grid;
    grid.mSize = Vec3(0.6, 0.2, 0.2);
    grid.mCellCount = {6, 2, 2};
    fem::TetSolver solver = fem::TetSolver::Create(fem::TetGrid(grid).Get(), inMaterial, inSettings).Get();
    for (int k = 0; k <= 2; ++k)
        for (int j = 0; j <= 2; ++j)
            REQUIRE(solver.SetNodeFixed(fem::TetGridNode(grid.mCellCount, 0, j, k), true).IsValid());
    return solver;
}

fem::TetSolver StruckBrittleWall(const fem::TetSolverSettings& inSettings, double inImpulse)
{
    fem::TetGridSettings grid;
    grid.mSize = Vec3(2.0, 0.2, 1.0);
    grid.mCellCount = {10, 1, 5};
    fem::FemMaterialSettings material = common::StiffBrittleMaterial();
    material.mMassDamping = 2.0;
    fem::TetSolver wall = fem::TetSolver::Create(fem::TetGrid(grid).Get(), material, inSettings).Get();
    for (int i = 0; i <= 10; ++i)
        for (int j = 0; j <= 1; ++j)
            REQUIRE(wall.SetNodeFixed(fem::TetGridNode(grid.mCellCount, i, j, 0), true).IsValid());
    for (int k = 3; k <= 4; ++k)
        for (int i = 7; i <= 8; ++i)
            REQUIRE(wall.ApplyImpulse(fem::TetGridNode(grid.mCellCount, i, 0, k),
                                      Vec3(0.0, 0.25 * inImpulse, 0.0))
                        .IsValid());
    return wall;
}

DampedCantilever MakeDampedCantilever(const std::shared_ptr<gpu::ComputeDevice>& inDevice,
                                      common::CantileverSettings inSettings)
{
    inSettings.mLengthCells = 20;
    inSettings.mSectionCells = 2;
    inSettings.mMaterial.mMassDamping =
        2.0 * 2.0 * 3.14159265358979 * common::EulerBernoulliFrequency(inSettings);
    common::CantileverScene scene = common::CantileverScene::Create(inSettings).Get();
    Result<gpu::GpuTetSolver> gpu = gpu::GpuTetSolver::CreateFrom(inDevice, scene.GetSolver());
    REQUIRE(gpu.IsValid());
    common::CantileverScene solved = common::CantileverScene::Create(inSettings).Get();
    REQUIRE(solved.GetSolver().SolveStatic().IsValid());
    return DampedCantilever{std::move(scene), std::move(gpu.Get()), std::move(solved)};
}

double MaxDistance(const std::vector<Vec3>& inA, const std::vector<Vec3>& inB)
{
    double largest = 0.0;
    for (std::size_t node = 0; node < inA.size(); ++node)
        largest = std::max(largest, (inA[node] - inB[node]).norm());
    return largest;
}

BlowCounts RandomBlows(gpu::GpuTetSolver& ioGpu, double inDeltaTime, std::uint64_t inSeed)
{
    BlowCounts counts;
    std::mt19937_64 random(inSeed);
    std::vector<Vec3> positions, previous;
    ioGpu.ReadPositions(previous);
    for (int step = 0; step < 20; ++step)
    {
        const double magnitude = std::pow(10.0, -3.0 + 8.0 * static_cast<double>(random() >> 11) * 0x1.0p-53);
        const int node = static_cast<int>(random() % static_cast<std::uint64_t>(ioGpu.GetNodeCount()));
        REQUIRE(ioGpu.ApplyImpulse(node, magnitude * Vec3(0.6, -0.48, 0.64)).IsValid());
        const Result<fem::TetStepResult> stepped = ioGpu.Step(inDeltaTime);
        REQUIRE(stepped.IsValid());
        counts.mDiverged += fem::HasEvent(stepped.Get().mEvents, fem::ETetStepEvent::Diverged) ? 1 : 0;
        ioGpu.ReadPositions(positions);
        for (const Vec3& x : positions)
            REQUIRE(IsFinite(x));
        counts.mMoved += positions != previous ? 1 : 0;
        previous = positions;
    }
    return counts;
}

void CheckBlowUpRestored(gpu::GpuTetSolver& ioGpu, int inNode)
{
    std::vector<Vec3> before, after;
    ioGpu.ReadPositions(before);
    REQUIRE(ioGpu.ApplyImpulse(inNode, Vec3(0.0, 0.0, 1.0e30)).IsValid());
    const Result<fem::TetStepResult> blown = ioGpu.Step(1.0 / 60.0);
    REQUIRE(blown.IsValid());
    CHECK(fem::HasEvent(blown.Get().mEvents, fem::ETetStepEvent::Diverged));
    ioGpu.ReadPositions(after);
    CHECK(after == before);
}

} // namespace crumple::test
