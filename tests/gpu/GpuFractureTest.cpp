// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// Fracture on the GPU against the CPU: the same links open at the same threshold, the same fragments come
// out, and a wall hit on the GPU breaks where it is hit, the same way every run.
#include <crumple/fem/TetGrid.h>
#include "GpuTestDevice.h"
#include "GpuTestScenes.h"

#include <crumple/gpu/GpuTetSolver.h>

#include <BrittleMaterial.h>
#include <catch2/catch.hpp>

#include <cmath>

using namespace crumple;
using namespace crumple::fem;
using namespace crumple::gpu;

namespace
{

constexpr double cStrength = common::cBrittleStrength; // Pa
constexpr double cYoung = common::cBrittleYoung;       // Pa
constexpr double cPoisson = common::cBrittlePoisson;
using common::BrittleMaterial;

TetSolverSettings Explicit()
{
    TetSolverSettings settings;
    settings.mIntegrator = EIntegrator::SymplecticEuler;
    settings.mGravity = Vec3::Zero();
    return settings;
}

// The free 1 m x 0.5 m x 0.5 m bar of 4 x 2 x 2 cubes stretched to a uniaxial stress along x (as the CPU
// fracture test), on the CPU and on the GPU, then stepped by 1 us (one sub-step).
struct Pair
{
    TetSolver mCpu;
    GpuTetSolver mGpu;
};

Pair StretchedBar(const std::shared_ptr<ComputeDevice>& inDevice, double inStress, EFractureMode inMode)
{
    TetGridSettings grid;
    grid.mSize = Vec3(1.0, 0.5, 0.5);
    grid.mCellCount = {4, 2, 2};
    const TetMesh mesh = TetGrid(grid).Get();
    TetSolver cpu = TetSolver::Create(mesh, BrittleMaterial(inMode), Explicit()).Get();
    const double strain = inStress / cYoung;
    std::vector<Vec3> positions = cpu.GetPositions();
    for (Vec3& x : positions)
        x = Vec3(x.x() * (1.0 + strain), x.y() * (1.0 - cPoisson * strain), x.z() * (1.0 - cPoisson * strain));
    REQUIRE(cpu.SetPositions(positions).IsValid());
    GpuTetSolver gpu = GpuTetSolver::CreateFrom(inDevice, cpu).Get();
    REQUIRE(cpu.Step(1.0e-6).IsValid());
    const Result<TetStepResult> step = gpu.Step(1.0e-6);
    REQUIRE(step.IsValid());
    CHECK(step.Get().mSubSteps == 1);
    return Pair{std::move(cpu), std::move(gpu)};
}

void CheckSameFragments(const std::vector<TetFragment>& inCpu, const std::vector<TetFragment>& inGpu)
{
    REQUIRE(inGpu.size() == inCpu.size());
    for (std::size_t index = 0; index < inCpu.size(); ++index)
    {
        CHECK(inGpu[index].mElements == inCpu[index].mElements);
        CHECK(inGpu[index].mMass == Approx(inCpu[index].mMass).epsilon(1e-12));
        CHECK((inGpu[index].mCenterOfMass - inCpu[index].mCenterOfMass).norm() < 1e-5);
    }
}

} // namespace

TEST_CASE("GPU fracture opens the same links as the CPU at the tensile strength, into the same fragments", "[gpu]")
{
    const std::shared_ptr<ComputeDevice> device = test::DeviceOrSkip();
    const Pair below = StretchedBar(device, 0.95 * cStrength, EFractureMode::CrackPlane);
    CHECK(below.mGpu.GetBrokenLinks() == below.mCpu.GetBrokenLinks());
    CHECK(below.mGpu.GetNodeCount() == below.mCpu.GetNodeCount());

    const Pair above = StretchedBar(device, 1.05 * cStrength, EFractureMode::CrackPlane);
    CHECK(above.mCpu.GetBrokenLinkCount() == 12);
    CHECK(above.mGpu.GetBrokenLinks() == above.mCpu.GetBrokenLinks());
    CHECK(above.mGpu.GetElementNodes() == above.mCpu.GetElementNodes());
    CheckSameFragments(above.mCpu.ComputeFragments(), above.mGpu.ComputeFragments());

    const Pair detached = StretchedBar(device, 1.05 * cStrength, EFractureMode::DetachGroup);
    CHECK(detached.mGpu.GetNodeCount() == 16 * 8);
    CheckSameFragments(detached.mCpu.ComputeFragments(), detached.mGpu.ComputeFragments());
}

TEST_CASE("GPU fracture: a wall hit at one spot breaks there as on the CPU, the same way every run", "[gpu]")
{
    const std::shared_ptr<ComputeDevice> device = test::DeviceOrSkip();
    // The CPU test's wall: 2 m x 0.2 m x 1 m of 0.2 m cubes anchored along its base, hit with 100 N s on
    // the front face of cell (7, 0, 3).
    auto run = [&](std::vector<TetFragment>& outFragments, std::vector<std::uint8_t>& outBroken, bool inGpu)
    {
        TetSolverSettings settings = Explicit();
        settings.mGravity = Vec3(0.0, 0.0, -9.81);
        TetSolver cpu = test::StruckBrittleWall(settings, 100.0);
        if (inGpu)
        {
            GpuTetSolver gpu = GpuTetSolver::CreateFrom(device, cpu).Get();
            for (int step = 0; step < 10; ++step)
                REQUIRE(gpu.Step(1.0e-4).IsValid());
            outFragments = gpu.ComputeFragments();
            outBroken = gpu.GetBrokenLinks();
        }
        else
        {
            for (int step = 0; step < 10; ++step)
                REQUIRE(cpu.Step(1.0e-4).IsValid());
            outFragments = cpu.ComputeFragments();
            outBroken = cpu.GetBrokenLinks();
        }
    };
    std::vector<TetFragment> cpu_fragments, gpu_fragments, again_fragments;
    std::vector<std::uint8_t> cpu_broken, gpu_broken, again_broken;
    run(cpu_fragments, cpu_broken, false);
    run(gpu_fragments, gpu_broken, true);
    run(again_fragments, again_broken, true);
    int opened = 0;
    for (std::uint8_t broken : cpu_broken)
        opened += broken;
    INFO("links opened on the CPU: " << opened);
    REQUIRE(opened > 0);
    CHECK(gpu_broken == cpu_broken);
    CheckSameFragments(cpu_fragments, gpu_fragments);
    CHECK(again_broken == gpu_broken);
    CheckSameFragments(gpu_fragments, again_fragments);
}
