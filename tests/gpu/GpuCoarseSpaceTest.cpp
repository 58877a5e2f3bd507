// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// The GPU implicit step's coarse correction (fem::TetCoarseSpace): a stiff beam converges in a fraction of
// block Jacobi's iterations to the same answer, a small prop keeps block Jacobi alone, and a breakable prop's
// space follows its cracks. Runs on llvmpipe where no GPU exists; skips without EGL.
#include "BrittleMaterial.h"
#include "CantileverScene.h"
#include "GpuTestDevice.h"
#include "GpuTestScenes.h"

#include <crumple/fem/TetGrid.h>
#include <crumple/gpu/GpuTetSolver.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

using namespace crumple;
using namespace crumple::fem;
using namespace crumple::gpu;

namespace
{

// The fem_realtime beam (1 m steel, 0.1 m square, 25 x 3 x 3 cells: 1,125 tetrahedra, 1 kN at the tip from
// rest, undamped), stepped on the GPU with inPreconditioner.
struct BeamRun
{
    double mTip = 0.0;   ///< Mean tip deflection after the steps (m, down)
    int mIterations = 0; ///< CG iterations, all steps
    int mCoarseUnknowns = 0;
    bool mConverged = true; ///< No step stopped at a solver limit
};

common::CantileverSettings StiffBeam(EImplicitPreconditioner inPreconditioner)
{
    common::CantileverSettings settings;
    settings.mLengthCells = 25;
    settings.mSectionCells = 3;
    settings.mMaterial.mMassDamping = 0.0;
    settings.mMaterial.mStiffnessDamping = 0.0;
    settings.mSolver.mPreconditioner = inPreconditioner;
    return settings;
}

constexpr int cSteps = 10;
// A refresh threshold no solve reaches: the coarse space is never turned (kept as built)
constexpr int cNeverTurn = std::numeric_limits<int>::max();
constexpr double cStep = 1.0 / 60.0;

BeamRun RunBeam(const std::shared_ptr<ComputeDevice>& inDevice, EImplicitPreconditioner inPreconditioner)
{
    common::CantileverScene scene = common::CantileverScene::Create(StiffBeam(inPreconditioner)).Get();
    GpuTetSolver gpu = GpuTetSolver::CreateFrom(inDevice, scene.GetSolver()).Get();
    BeamRun run;
    for (int step = 0; step < cSteps; ++step)
    {
        const Result<TetStepResult> stepped = gpu.Step(cStep);
        REQUIRE(stepped.IsValid());
        REQUIRE_FALSE(HasEvent(stepped.Get().mEvents, ETetStepEvent::Diverged));
        run.mIterations += stepped.Get().mSolverIterations;
        run.mConverged =
            run.mConverged && !HasEvent(stepped.Get().mEvents, ETetStepEvent::SolverNotConverged);
    }
    std::vector<Vec3> positions;
    gpu.ReadPositions(positions);
    REQUIRE(positions.size() == static_cast<std::size_t>(gpu.GetNodeCount()));
    run.mTip = scene.TipDeflection(positions);
    run.mCoarseUnknowns = gpu.GetCoarseUnknowns();
    return run;
}

} // namespace

TEST_CASE("GPU implicit step: the coarse correction cuts a stiff beam's iterations and lands where block "
          "Jacobi does",
          "[gpu]")
{
    const std::shared_ptr<ComputeDevice> device = test::DeviceOrSkip();
    const BeamRun coarse = RunBeam(device, EImplicitPreconditioner::RestFactorization);
    const BeamRun jacobi = RunBeam(device, EImplicitPreconditioner::BlockJacobi);

    // The answer both approach: the CPU's steps solved to round-off.
    common::CantileverSettings tight = StiffBeam(EImplicitPreconditioner::RestFactorization);
    tight.mSolver.mImplicitTolerance = 1.0e-12;
    tight.mSolver.mImplicitMaxIterations = 50;
    tight.mSolver.mCgRelativeTolerance = 1.0e-12;
    common::CantileverScene reference = common::CantileverScene::Create(tight).Get();
    for (int step = 0; step < cSteps; ++step)
        REQUIRE(reference.GetSolver().Step(cStep).IsValid());
    const double expected = reference.TipDeflection();
    INFO("tip after " << cSteps << " steps: CPU converged " << expected << " m, GPU coarse " << coarse.mTip
                      << " m (" << coarse.mIterations << " CG iterations, " << coarse.mCoarseUnknowns
                      << " coarse unknowns), GPU block Jacobi " << jacobi.mTip << " m (" << jacobi.mIterations
                      << ")");
    CHECK(coarse.mCoarseUnknowns > 0);
    CHECK(jacobi.mCoarseUnknowns == 0);
    CHECK(coarse.mConverged);
    CHECK(jacobi.mConverged);
    // Measured: 592 against 3,048 iterations (96 coarse unknowns: 16 aggregates of the 400 free nodes).
    CHECK(3 * coarse.mIterations < jacobi.mIterations);
    // Float state: the tip moves about 0.16 mm at x = 1 m, where a float carries an ulp of 1.2e-7 m.
    CHECK(std::abs(coarse.mTip - expected) < 2.0e-3 * std::abs(expected));
    CHECK(std::abs(jacobi.mTip - expected) < 2.0e-3 * std::abs(expected));
}

TEST_CASE("GPU implicit step: a prop of a few aggregates keeps block Jacobi alone", "[gpu]")
{
    const std::shared_ptr<ComputeDevice> device = test::DeviceOrSkip();
    // The parity tests' bar (6 x 2 x 2 cells, 54 free nodes): two aggregates, where the coarse correction
    // costs iterations instead of saving them (fem::TetCoarseSpaceSettings::mMinAggregates).
    TetSolverSettings settings;
    settings.mSleepSpeed = 0.0;
    TetSolver cpu = test::ClampedBar(test::SoftBarMaterial(), settings);
    GpuTetSolver gpu = GpuTetSolver::CreateFrom(device, cpu).Get();
    REQUIRE(gpu.ApplyImpulse(test::cBarTipNode, Vec3(0.0, 0.0, 10.0)).IsValid());
    REQUIRE(gpu.Step(1.0 / 60.0).IsValid());
    CHECK(gpu.GetCoarseUnknowns() == 0);
}

TEST_CASE("GPU implicit step: a breakable wall's coarse space follows its cracks", "[gpu]")
{
    const std::shared_ptr<ComputeDevice> device = test::DeviceOrSkip();
    // A brittle wall 2 m x 0.2 m x 1 m of 0.1 m cubes (2,000 tetrahedra, 630 free nodes) anchored along its
    // base, hit on its face with 4 kN s at 1/60 s: a crack adds nodes, and a space made for the old count is
    // not used (GetCoarseUnknowns would read 0), so a space after the cracks is one built for them.
    TetGridSettings grid;
    grid.mSize = Vec3(2.0, 0.2, 1.0);
    grid.mCellCount = {20, 2, 10};
    FemMaterialSettings material = common::StiffBrittleMaterial();
    material.mMassDamping = 2.0;
    struct WallRun
    {
        int mMadeNodes = 0, mNodes = 0, mIterations = 0, mUnconverged = 0, mStepsAfterCracks = 0, mBuilds = 0,
            mTurns = 0;
        bool mCoarseAfterCracks = true; // every step after a crack used a coarse space
    };
    const auto run = [&](EImplicitPreconditioner inPreconditioner, int inRefreshIterations)
    {
        TetSolverSettings settings;
        settings.mSleepSpeed = 0.0;
        settings.mPreconditioner = inPreconditioner;
        settings.mFactorRefreshIterations = inRefreshIterations;
        TetSolver cpu = TetSolver::Create(TetGrid(grid).Get(), material, settings).Get();
        for (int i = 0; i <= 20; ++i)
            for (int j = 0; j <= 2; ++j)
                REQUIRE(cpu.SetNodeFixed(TetGridNode(grid.mCellCount, i, j, 0), true).IsValid());
        for (int k = 6; k <= 7; ++k)
            for (int i = 14; i <= 15; ++i)
                REQUIRE(cpu.ApplyImpulse(TetGridNode(grid.mCellCount, i, 0, k), Vec3(0.0, 1000.0, 0.0))
                            .IsValid());
        GpuTetSolver gpu = GpuTetSolver::CreateFrom(device, cpu).Get();
        WallRun result;
        result.mMadeNodes = gpu.GetNodeCount();
        for (int step = 0; step < 5; ++step)
        {
            const int nodes_before = gpu.GetNodeCount();
            const Result<TetStepResult> stepped = gpu.Step(1.0 / 60.0);
            REQUIRE(stepped.IsValid());
            REQUIRE_FALSE(HasEvent(stepped.Get().mEvents, ETetStepEvent::Diverged));
            result.mIterations += stepped.Get().mSolverIterations;
            result.mUnconverged += HasEvent(stepped.Get().mEvents, ETetStepEvent::SolverNotConverged) ? 1 : 0;
            if (nodes_before > result.mMadeNodes)
            {
                ++result.mStepsAfterCracks;
                result.mCoarseAfterCracks = result.mCoarseAfterCracks && gpu.GetCoarseUnknowns() > 0;
            }
        }
        result.mNodes = gpu.GetNodeCount();
        result.mBuilds = gpu.GetCoarseSpaceBuilds();
        result.mTurns = gpu.GetCoarseSpaceTurns();
        return result;
    };
    // The space kept as built, turned with its aggregates before every step but the first (the default
    // refresh 0), and block Jacobi alone.
    const WallRun coarse = run(EImplicitPreconditioner::RestFactorization, cNeverTurn);
    const WallRun turned = run(EImplicitPreconditioner::RestFactorization, 0);
    const WallRun jacobi = run(EImplicitPreconditioner::BlockJacobi, 0);
    INFO("coarse as built: nodes " << coarse.mMadeNodes << " -> " << coarse.mNodes << ", "
                                   << coarse.mIterations << " CG iterations, " << coarse.mUnconverged
                                   << " steps at a solver limit; turned: nodes -> " << turned.mNodes << ", "
                                   << turned.mIterations << ", " << turned.mUnconverged
                                   << "; block Jacobi: nodes -> " << jacobi.mNodes << ", "
                                   << jacobi.mIterations << ", " << jacobi.mUnconverged
                                   << "; spaces built: " << coarse.mBuilds << " and " << turned.mBuilds
                                   << ", turned " << turned.mTurns << " times");
    for (const WallRun* with_space : {&coarse, &turned})
    {
        CHECK(with_space->mNodes > with_space->mMadeNodes);
        CHECK(with_space->mStepsAfterCracks > 0);
        CHECK(with_space->mCoarseAfterCracks);
        CHECK(with_space->mUnconverged == 0);
        CHECK(with_space->mIterations < jacobi.mIterations);
    }
    // A space is built on the first step and after each step that cracked; turned before every step but the
    // first (each follows a solve of more than 0 iterations), a build's included.
    CHECK(coarse.mBuilds < 5);
    CHECK(coarse.mTurns == 0);
    CHECK(turned.mBuilds == coarse.mBuilds);
    CHECK(turned.mTurns == 4);
    CHECK(jacobi.mBuilds == 0);
}

TEST_CASE(
    "GPU implicit step with the coarse correction: random blows never leave a NaN, a blow-up is restored",
    "[gpu]")
{
    // The stiff beam (16 aggregates) hit at seeded random nodes with 1e-3 ... 1e5 N s, one blow per 1/30 s
    // step, with the space turned with its aggregates before every step (the default) and kept as built: the
    // coarse space must neither break a step nor hide a divergence.
    const std::shared_ptr<ComputeDevice> device = test::DeviceOrSkip();
    const int refresh = GENERATE(0, cNeverTurn);
    CAPTURE(refresh);
    common::CantileverSettings settings = StiffBeam(EImplicitPreconditioner::RestFactorization);
    settings.mSolver.mFactorRefreshIterations = refresh;
    common::CantileverScene scene = common::CantileverScene::Create(settings).Get();
    GpuTetSolver gpu = GpuTetSolver::CreateFrom(device, scene.GetSolver()).Get();
    const test::BlowCounts blows = test::RandomBlows(gpu, 1.0 / 30.0, 23);
    INFO(blows.mDiverged << " of 20 steps diverged (restored), " << blows.mMoved << " moved the beam; "
                         << gpu.GetCoarseSpaceBuilds() << " coarse spaces built, turned "
                         << gpu.GetCoarseSpaceTurns() << " times");
    CHECK(gpu.GetCoarseUnknowns() > 0);
    CHECK(gpu.GetCoarseSpaceTurns() == (refresh == 0 ? 19 : 0));
    CHECK(blows.mDiverged <= 2);
    CHECK(blows.mMoved >= 18);
    test::CheckBlowUpRestored(gpu, scene.GetTipNodes().front());
}

TEST_CASE("GPU implicit step: a beam bent far keeps its short solves when its coarse space turns with it",
          "[gpu]")
{
    // The stiff beam's mesh in a soft material (E = 10 MPa), 1 kN at the tip, damped: it bends until its tip
    // has dropped 0.84 m of its 1 m, turning its far aggregates by up to about 60 degrees, where their rest
    // modes no longer describe them. Turned with its aggregates before each step (the default), the space
    // keeps the solves short; kept as built they grow. Measured over steps 20-39: 1,352 against 5,392
    // iterations, the tip the same to 1 mm (0.841 and 0.840 m; with the first version's turns from 6: at 200
    // N 1,120 against 2,928; bent 63 mm: 1,120 and 1,128).
    const std::shared_ptr<ComputeDevice> device = test::DeviceOrSkip();
    const auto bend = [&](int inRefresh)
    {
        common::CantileverSettings settings = StiffBeam(EImplicitPreconditioner::RestFactorization);
        settings.mSolver.mFactorRefreshIterations = inRefresh;
        settings.mMaterial.mYoungsModulus = 1.0e7;
        settings.mMaterial.mMassDamping = 5.0;
        settings.mLoad = 1000.0;
        common::CantileverScene scene = common::CantileverScene::Create(settings).Get();
        GpuTetSolver gpu = GpuTetSolver::CreateFrom(device, scene.GetSolver()).Get();
        int late_iterations = 0;
        for (int step = 0; step < 40; ++step)
        {
            const Result<TetStepResult> stepped = gpu.Step(1.0 / 60.0);
            REQUIRE(stepped.IsValid());
            REQUIRE_FALSE(HasEvent(stepped.Get().mEvents, ETetStepEvent::Diverged));
            if (step >= 20)
                late_iterations += stepped.Get().mSolverIterations;
        }
        std::vector<Vec3> positions;
        gpu.ReadPositions(positions);
        return std::make_tuple(late_iterations, scene.TipDeflection(positions), gpu.GetCoarseSpaceTurns());
    };
    const auto [as_built, as_built_tip, no_turns] = bend(cNeverTurn);
    const auto [turned, turned_tip, turns] = bend(0);
    INFO("CG iterations in steps 20-39: " << as_built << " as built (tip " << as_built_tip << " m), "
                                          << turned << " turned (tip " << turned_tip << " m, " << turns
                                          << " turns)");
    CHECK(no_turns == 0);
    CHECK(turns == 39);
    CHECK(as_built_tip > 0.5);
    CHECK(2 * turned < as_built);
    CHECK(std::abs(turned_tip - as_built_tip) < 0.005);
}
