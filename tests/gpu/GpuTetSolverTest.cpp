// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// The FEM solver as compute shaders against the CPU: parity with the float build of the same equations and
// with the double CPU solver, the cantilever within float limits, stability under random impulses, a
// diverging step restored, determinism, refusals. Runs on llvmpipe where no GPU exists; skips without EGL.
#include "CantileverScene.h"
#include "FloatTetReference.h"
#include "GpuTestDevice.h"
#include "GpuTestScenes.h"

#include <crumple/fem/TetGrid.h>
#include <crumple/gpu/GpuTetSolver.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <tuple>

using namespace crumple;
using namespace crumple::fem;
using namespace crumple::gpu;

namespace
{

using test::SoftBarMaterial;

using test::ClampedBar;

// Explicit, under gravity, sleep off.
TetSolver ClampedBar(EElasticModel inModel)
{
    TetSolverSettings settings;
    settings.mIntegrator = EIntegrator::SymplecticEuler;
    settings.mSleepSpeed = 0.0;
    return ClampedBar(SoftBarMaterial(inModel), settings);
}

// Explicit, no gravity, sleep on: the sleep tests' bar.
TetSolver ClampedBarWithoutGravity(const FemMaterialSettings& inMaterial)
{
    TetSolverSettings settings;
    settings.mIntegrator = EIntegrator::SymplecticEuler;
    settings.mGravity = Vec3::Zero();
    return ClampedBar(inMaterial, settings);
}

// The tip corner node and an impulse that bends and twists the bar (N s).
constexpr int cTipNode = test::cBarTipNode;
const Vec3 cHit(0.3, -2.0, 4.0);

using test::MaxDistance;

} // namespace

TEST_CASE("GPU parity: the shaders match the float CPU build of the same equations and the double CPU solver",
          "[gpu]")
{
    const std::shared_ptr<ComputeDevice> device = test::DeviceOrSkip();
    const EElasticModel model = GENERATE(EElasticModel::CorotatedLinear, EElasticModel::StVenantKirchhoff);
    CAPTURE(ToString(model));

    TetSolver cpu = ClampedBar(model);
    Result<GpuTetSolver> created = GpuTetSolver::CreateFrom(device, cpu);
    REQUIRE(created.IsValid());
    GpuTetSolver& gpu = created.Get();
    test::FloatTetReference reference(cpu);

    REQUIRE(cpu.ApplyImpulse(cTipNode, cHit).IsValid());
    REQUIRE(gpu.ApplyImpulse(cTipNode, cHit).IsValid());
    reference.ApplyImpulse(cTipNode, cHit);
    const std::vector<Vec3> rest = cpu.GetPositions();
    double largest_motion = 0.0, float_gap = 0.0, double_gap = 0.0;
    std::vector<Vec3> positions;
    for (int step = 0; step < 30; ++step)
    {
        const Result<TetStepResult> gpu_step = gpu.Step(1.0 / 60.0);
        REQUIRE(gpu_step.IsValid());
        REQUIRE_FALSE(HasEvent(gpu_step.Get().mEvents, ETetStepEvent::Diverged));
        REQUIRE(cpu.Step(1.0 / 60.0).IsValid());
        reference.Step(1.0 / 60.0);
        CHECK(gpu_step.Get().mSubSteps == static_cast<int>(std::ceil(1.0 / 60.0 / cpu.GetStableTimeStep())));
        gpu.ReadPositions(positions);
        largest_motion = std::max(largest_motion, MaxDistance(positions, rest));
        float_gap = std::max(float_gap, MaxDistance(positions, reference.GetPositions()));
        double_gap = std::max(double_gap, MaxDistance(positions, cpu.GetPositions()));
    }
    // Float round-off: positions near 0.6 m carry an ulp of 6e-8 m, and the two builds round differently
    // (the GLSL compiler may fuse multiply-adds and orders 3x3 products its own way); over ~3,000 sub-steps
    // of a stable, damped system the gap stays a few ulps per step's worth: measured 2.7e-5 of the motion
    // against the float CPU build, so 1e-4 leaves margin without hiding a wrong equation (a missing term
    // gives gaps of order 1). Against the double solver the gap adds float's own error.
    INFO("largest motion " << largest_motion << " m; GPU vs float CPU " << float_gap << " m; GPU vs double CPU "
                           << double_gap << " m");
    REQUIRE(largest_motion > 0.01);
    CHECK(float_gap < 1.0e-4 * largest_motion);
    CHECK(double_gap < 1.0e-3 * largest_motion);
}

TEST_CASE("GPU cantilever: settles on the CPU's static deflection within float limits", "[gpu]")
{
    const std::shared_ptr<ComputeDevice> device = test::DeviceOrSkip();
    // A soft version of the cantilever (E = 10 MPa, 1 N at the tip, 20 x 2 x 2 cells) so the
    // explicit sub-steps stay few; mass damping critical for the first bending mode.
    common::CantileverSettings settings;
    settings.mMaterial.mYoungsModulus = 1.0e7;
    settings.mMaterial.mDensity = 1000.0;
    settings.mLoad = 1.0;
    settings.mSolver.mIntegrator = EIntegrator::SymplecticEuler;
    test::DampedCantilever beam = test::MakeDampedCantilever(device, settings);
    const common::CantileverScene& scene = beam.mScene;
    const common::CantileverScene& reference = beam.mStatic;
    GpuTetSolver& gpu = beam.mGpu;
    for (int step = 0; step < 90; ++step)
        REQUIRE(gpu.Step(1.0 / 60.0).IsValid());
    std::vector<Vec3> positions;
    gpu.ReadPositions(positions);
    double gpu_tip = 0.0, static_tip = 0.0;
    for (int node : scene.GetTipNodes())
    {
        gpu_tip += (scene.GetSolver().GetPositions()[node] - positions[node]).z();
        static_tip += (scene.GetSolver().GetPositions()[node] - reference.GetSolver().GetPositions()[node]).z();
    }
    const double timoshenko = common::TimoshenkoDeflection(settings);
    const double count = static_cast<double>(scene.GetTipNodes().size());
    INFO("mean tip deflection: GPU " << gpu_tip / count << " m, CPU static " << static_tip / count
                                     << " m, Timoshenko " << timoshenko << " m (the coarse mesh is stiffer)");
    CHECK(gpu_tip == Approx(static_tip).epsilon(1.0e-3));
}

TEST_CASE("GPU stress: random impulses up to 1e5 N s never leave a NaN, a blow-up is restored and reported",
          "[gpu]")
{
    const std::shared_ptr<ComputeDevice> device = test::DeviceOrSkip();
    TetSolver cpu = ClampedBar(EElasticModel::CorotatedLinear);
    GpuTetSolver gpu = GpuTetSolver::CreateFrom(device, cpu).Get();
    const test::BlowCounts blows = test::RandomBlows(gpu, 1.0 / 30.0, 5);
    INFO(blows.mDiverged << " of 20 steps diverged (restored), " << blows.mMoved << " moved the bar");
    CHECK(blows.mMoved >= 18);
    // 1e30 N s overflows float: the step is retried, then restored bit for bit and reported.
    test::CheckBlowUpRestored(gpu, cTipNode);
}

TEST_CASE("GPU runs are deterministic: the same inputs give bitwise the same positions", "[gpu]")
{
    const std::shared_ptr<ComputeDevice> device = test::DeviceOrSkip();
    auto run = [&]()
    {
        GpuTetSolver gpu = GpuTetSolver::CreateFrom(device, ClampedBar(EElasticModel::CorotatedLinear)).Get();
        REQUIRE(gpu.ApplyImpulse(cTipNode, cHit).IsValid());
        for (int step = 0; step < 10; ++step)
            REQUIRE(gpu.Step(1.0 / 60.0).IsValid());
        std::vector<Vec3> positions;
        gpu.ReadPositions(positions);
        return positions;
    };
    CHECK(run() == run());
}

TEST_CASE("GPU SetNodesFixed gives SetNodeFixed's state node by node, in one read and write", "[gpu]")
{
    const std::shared_ptr<ComputeDevice> device = test::DeviceOrSkip();
    const TetSolver bar = ClampedBar(EElasticModel::CorotatedLinear);
    GpuTetSolver one_by_one = GpuTetSolver::CreateFrom(device, bar).Get();
    GpuTetSolver together = GpuTetSolver::CreateFrom(device, bar).Get();
    for (GpuTetSolver* gpu : {&one_by_one, &together})
    {
        REQUIRE(gpu->ApplyImpulse(cTipNode, cHit).IsValid());
        REQUIRE(gpu->Step(1.0 / 240.0).IsValid());
    }
    // Unordered, spread over the bar (the range between holds nodes that must come back as they were), one twice.
    const std::vector<int> piece{cTipNode, 9, cTipNode - 1, 30, 9};
    for (int node : piece)
        REQUIRE(one_by_one.SetNodeFixed(node, true).IsValid());
    REQUIRE(together.SetNodesFixed(piece, true).IsValid());
    const auto state = [](const GpuTetSolver& inGpu) {
        std::vector<Vec3> positions, velocities;
        inGpu.ReadPositions(positions);
        inGpu.ReadVelocities(velocities);
        return std::make_tuple(positions, velocities, inGpu.GetInverseMasses());
    };
    CHECK(state(together) == state(one_by_one));
    for (int node : std::vector<int>{30, 9})
        REQUIRE(one_by_one.SetNodeFixed(node, false).IsValid());
    REQUIRE(together.SetNodesFixed(std::vector<int>{30, 9}, false).IsValid());
    for (GpuTetSolver* gpu : {&one_by_one, &together})
        for (int step = 0; step < 5; ++step)
            REQUIRE(gpu->Step(1.0 / 240.0).IsValid());
    CHECK(state(together) == state(one_by_one));

    const auto before = state(together);
    CHECK(together.SetNodesFixed(std::vector<int>{3, together.GetNodeCount()}, true).HasError());
    CHECK(state(together) == before);
}

TEST_CASE("GpuTetSolver refuses what it cannot do and bad input, changing nothing", "[gpu]")
{
    const std::shared_ptr<ComputeDevice> device = test::DeviceOrSkip();
    TetGridSettings grid;
    grid.mCellCount = {2, 1, 1};
    const TetMesh mesh = TetGrid(grid).Get();
    TetSolverSettings explicit_settings;
    explicit_settings.mIntegrator = EIntegrator::SymplecticEuler;
    FemMaterialSettings negative;
    negative.mDensity = -1.0;
    CHECK(GpuTetSolver::Create(device, mesh, negative, explicit_settings).HasError());

    GpuTetSolver gpu = GpuTetSolver::Create(device, mesh, FemMaterialSettings{}, explicit_settings).Get();
    std::vector<Vec3> before, after;
    gpu.ReadVelocities(before);
    CHECK(gpu.ApplyImpulse(-1, Vec3::UnitX()).HasError());
    CHECK(gpu.ApplyImpulse(0, Vec3(std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0)).HasError());
    CHECK(gpu.SetExternalForce(gpu.GetNodeCount(), Vec3::UnitX()).HasError());
    CHECK(gpu.Step(-1.0).HasError());
    CHECK(gpu.Step(std::numeric_limits<double>::infinity()).HasError());
    gpu.ReadVelocities(after);
    CHECK(after == before);
}

TEST_CASE("GPU sleep: a prop made at rest, unloaded, sleeps at its first step without a readback", "[gpu]")
{
    // The held racing fence: made still, anchored, no gravity. Before, it integrated 30 quiet steps of
    // nothing (the GPU cannot see its state without reading it back) before it fell asleep.
    const std::shared_ptr<ComputeDevice> device = test::DeviceOrSkip();
    const FemMaterialSettings material = SoftBarMaterial(EElasticModel::CorotatedLinear);

    // Still: asleep at the first step, no element work.
    const TetSolver cpu = ClampedBarWithoutGravity(material);
    GpuTetSolver gpu = GpuTetSolver::CreateFrom(device, cpu).Get();
    const Result<TetStepResult> first = gpu.Step(1.0 / 60.0);
    REQUIRE(first.IsValid());
    CHECK(HasEvent(first.Get().mEvents, ETetStepEvent::FellAsleep));
    CHECK(gpu.GetElementWorkCount() == 0u);
    // A zero impulse or force keeps it so; a real one wakes it, and it moves.
    REQUIRE(gpu.ApplyImpulse(cTipNode, Vec3::Zero()).IsValid());
    REQUIRE(gpu.SetExternalForce(cTipNode, Vec3::Zero()).IsValid());
    CHECK(HasEvent(gpu.Step(1.0 / 60.0).Get().mEvents, ETetStepEvent::FellAsleep));
    CHECK(gpu.GetElementWorkCount() == 0u);
    REQUIRE(gpu.ApplyImpulse(cTipNode, cHit).IsValid());
    const Result<TetStepResult> hit = gpu.Step(1.0 / 60.0);
    REQUIRE(hit.IsValid());
    CHECK_FALSE(HasEvent(hit.Get().mEvents, ETetStepEvent::Sleeping));
    CHECK(gpu.GetElementWorkCount() > 0u);
    CHECK(hit.Get().mKineticEnergy > 0.0);

    // Gravity on a free node, a force, or a strained state made from the CPU: it steps.
    for (int variant = 0; variant < 3; ++variant)
    {
        TetSolver loaded = ClampedBarWithoutGravity(material);
        if (variant == 2)
        {
            std::vector<Vec3> bent = loaded.GetPositions();
            bent[cTipNode] += Vec3(0.0, 0.0, 1.0e-3);
            REQUIRE(loaded.SetPositions(bent).IsValid());
        }
        GpuTetSolver moving = GpuTetSolver::CreateFrom(device, loaded).Get();
        if (variant == 0)
            REQUIRE(moving.SetGravity(Vec3(0.0, 0.0, -9.81)).IsValid());
        if (variant == 1)
            REQUIRE(moving.SetExternalForce(cTipNode, Vec3(0.0, 0.0, -10.0)).IsValid());
        const Result<TetStepResult> step = moving.Step(1.0 / 60.0);
        REQUIRE(step.IsValid());
        INFO("variant " << variant);
        CHECK_FALSE(HasEvent(step.Get().mEvents, ETetStepEvent::Sleeping));
        CHECK(moving.GetElementWorkCount() > 0u);
    }
}

TEST_CASE("GPU sleep: a prop at rest stops dispatching until an input wakes it", "[gpu]")
{
    const std::shared_ptr<ComputeDevice> device = test::DeviceOrSkip();
    FemMaterialSettings material = SoftBarMaterial(EElasticModel::CorotatedLinear);
    material.mMassDamping = 20.0; // comes to rest within a second
    const TetSolver cpu = ClampedBarWithoutGravity(material);
    GpuTetSolver gpu = GpuTetSolver::CreateFrom(device, cpu).Get();
    REQUIRE(gpu.ApplyImpulse(cTipNode, cHit).IsValid());

    int fell_asleep_at = -1;
    double first_energy = 0.0;
    for (int step = 0; step < 240 && fell_asleep_at < 0; ++step)
    {
        const Result<TetStepResult> result = gpu.Step(1.0 / 60.0);
        REQUIRE(result.IsValid());
        if (step == 0)
            first_energy = result.Get().mKineticEnergy;
        if (HasEvent(result.Get().mEvents, ETetStepEvent::FellAsleep))
            fell_asleep_at = step;
    }
    INFO("kinetic energy after the first step " << first_energy << " J");
    CHECK(first_energy > 0.0);
    REQUIRE(fell_asleep_at > 0);
    CHECK(gpu.IsSleeping());

    // Asleep: no element work, no motion.
    const std::uint64_t work = gpu.GetElementWorkCount();
    std::vector<Vec3> before, after;
    gpu.ReadPositions(before);
    const Result<TetStepResult> asleep = gpu.Step(1.0 / 60.0);
    REQUIRE(asleep.IsValid());
    CHECK(HasEvent(asleep.Get().mEvents, ETetStepEvent::Sleeping));
    CHECK(gpu.GetElementWorkCount() == work);
    gpu.ReadPositions(after);
    CHECK(after == before);

    // An impulse wakes it.
    REQUIRE(gpu.ApplyImpulse(cTipNode, cHit).IsValid());
    CHECK_FALSE(gpu.IsSleeping());
    REQUIRE(gpu.Step(1.0 / 60.0).IsValid());
    CHECK(gpu.GetElementWorkCount() > work);
}
