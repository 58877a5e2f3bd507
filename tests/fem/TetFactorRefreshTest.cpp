// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// The factored preconditioner refreshed at the element frames (TetSolverSettings::mFactorRefreshIterations):
// the numeric refactorisation against a fresh one, the assembled system at frames against the matrix-free
// operator, the node rotations relative to the frames, and a struck slab's solves against a fully converged
// one.
#include "AllocationCounter.h"
#include "AssembledSystemCheck.h"
#include "ConjugateGradient.h"
#include "DrawVec3.h"
#include "NodeBlockCholesky.h"
#include "PushedRail.h"
#include "SmallTetBlock.h"
#include "TetElementPass.h"
#include "TetFactoredPreconditioner.h"
#include "TetRestSystemBlocks.h"

#include <crumple/fem/FemMaterial.h>
#include <crumple/fem/TetElementRest.h>
#include <crumple/fem/TetGrid.h>
#include <crumple/fem/TetSolver.h>

#include <SkipTest.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <random>

using namespace crumple;
using namespace crumple::fem;

namespace
{

Quat RandomRotation(std::mt19937& ioRandom)
{
    std::normal_distribution<double> normal;
    // sequenced, last component first (common::DrawVec3)
    const double d = normal(ioRandom), c = normal(ioRandom), b = normal(ioRandom), a = normal(ioRandom);
    Eigen::Vector4d q(a, b, c, d);
    return Quat(q.normalized());
}

// A random SPD block system over inNodes nodes: random couplings (repeats included) made SPD by diagonal
// dominance, with the same pattern for every seed of the values.
std::vector<NodeBlock> RandomSystem(int inNodes, std::uint32_t inPatternSeed, std::uint32_t inValueSeed)
{
    std::mt19937 pattern(inPatternSeed);
    std::mt19937 values(inValueSeed);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::vector<NodeBlock> blocks;
    std::vector<double> row_sums(static_cast<std::size_t>(inNodes), 0.0);
    for (int edge = 0; edge < 3 * inNodes; ++edge)
    {
        const int i = static_cast<int>(pattern() % static_cast<std::uint32_t>(inNodes));
        const int j = static_cast<int>(pattern() % static_cast<std::uint32_t>(inNodes));
        if (i == j)
            continue;
        Mat3 block;
        for (int entry = 0; entry < 9; ++entry)
            block(entry / 3, entry % 3) = unit(values);
        blocks.push_back({std::max(i, j), std::min(i, j), block});
        row_sums[static_cast<std::size_t>(i)] += block.cwiseAbs().sum();
        row_sums[static_cast<std::size_t>(j)] += block.cwiseAbs().sum();
    }
    for (int node = 0; node < inNodes; ++node)
        blocks.push_back({node, node, (row_sums[static_cast<std::size_t>(node)] + 1.0) * Mat3::Identity()});
    return blocks;
}

bool SameBits(const std::vector<Vec3>& inA, const std::vector<Vec3>& inB)
{
    return inA.size() == inB.size() && std::memcmp(inA.data(), inB.data(), inA.size() * sizeof(Vec3)) == 0;
}

// A 2 m rail of 0.1 m x 0.1 m of a soft barrier material (E = 100 MPa), its end faces anchored, pushed in
// the middle as a car pushes a fence (Push): it bends by a third of a metre within a few steps, and around
// the struck nodes neighbouring elements turn apart.
TetSolver StruckRail(const TetSolverSettings& inSettings)
{
    TetGridSettings grid;
    grid.mSize = Vec3(2.0, 0.1, 0.1);
    grid.mCellCount = {40, 2, 2};
    FemMaterialSettings material;
    material.mYoungsModulus = 1.0e8;
    material.mPoissonRatio = 0.3;
    material.mDensity = 600.0;
    TetSolver rail = TetSolver::Create(TetGrid(grid).Get(), material, inSettings).Get();
    for (int i : {0, 40})
        for (int j = 0; j <= 2; ++j)
            for (int k = 0; k <= 2; ++k)
                REQUIRE(rail.SetNodeFixed(TetGridNode(grid.mCellCount, i, j, k), true).IsValid());
    return rail;
}

// The car's push: 60 N s on each of the three struck nodes in each of the first six steps. False when the
// solver refused one (checked by the caller: no assertion here, where allocations may be counted).
bool Push(TetSolver& ioRail, int inStep)
{
    bool applied = true;
    if (inStep >= 6)
        return applied;
    for (int k = 0; k <= 2; ++k)
        applied = ioRail.ApplyImpulse(TetGridNode({40, 2, 2}, 20, 0, k), Vec3(0.0, 60.0, 0.0)).IsValid() && applied;
    return applied;
}

// The rail refreshing after 3 iterations, pushed for three steps: it has refreshed its factor.
TetSolver RefreshedRail()
{
    TetSolverSettings settings;
    settings.mFactorRefreshIterations = 3;
    TetSolver rail = StruckRail(settings);
    for (int step = 0; step < 3; ++step)
    {
        REQUIRE(Push(rail, step));
        REQUIRE(rail.Step(1.0 / 240.0).IsValid());
    }
    REQUIRE(rail.GetFactorRefreshCount() > 0);
    return rail;
}

// Both solvers pushed and stepped alike for five more steps: true when they end bit for bit the same.
bool ContinueAlike(TetSolver& ioA, TetSolver& ioB)
{
    for (int step = 3; step < 8; ++step)
    {
        REQUIRE(Push(ioA, step));
        REQUIRE(Push(ioB, step));
        REQUIRE(ioA.Step(1.0 / 240.0).IsValid());
        REQUIRE(ioB.Step(1.0 / 240.0).IsValid());
    }
    return SameBits(ioA.GetPositions(), ioB.GetPositions()) && SameBits(ioA.GetVelocities(), ioB.GetVelocities());
}

double MaxDifference(const std::vector<Vec3>& inA, const std::vector<Vec3>& inB)
{
    double largest = 0.0;
    for (std::size_t node = 0; node < inA.size(); ++node)
        largest = std::max(largest, (inA[node] - inB[node]).cwiseAbs().maxCoeff());
    return largest;
}

} // namespace

TEST_CASE("NodeBlockCholesky: Refactor of the same pattern is bitwise a fresh Factor, another pattern is factored afresh",
          "[fem]")
{
    for (std::uint32_t trial = 0; trial < 10; ++trial)
    {
        const int n = 5 + static_cast<int>(trial) * 7;
        const std::vector<NodeBlock> first = RandomSystem(n, 100 + trial, 1);
        const std::vector<NodeBlock> second = RandomSystem(n, 100 + trial, 2);
        REQUIRE(first.size() == second.size());
        NodeBlockCholesky reused, fresh;
        REQUIRE(reused.Factor(n, first));
        REQUIRE(reused.Refactor(n, second));
        REQUIRE(fresh.Factor(n, second));
        CHECK(reused.GetBlockCount() == fresh.GetBlockCount());
        std::mt19937 random(trial);
        std::uniform_real_distribution<double> unit(-1.0, 1.0);
        std::vector<Vec3> rhs(static_cast<std::size_t>(n));
        for (Vec3& value : rhs)
            value = common::DrawVec3([&] { return unit(random); });
        std::vector<Vec3> a = rhs, b = rhs;
        reused.Solve(a);
        fresh.Solve(b);
        CHECK(SameBits(a, b));

        // Another pattern (other couplings) through Refactor: the ordering is made anew, as Factor would.
        const std::vector<NodeBlock> other = RandomSystem(n, 900 + trial, 3);
        NodeBlockCholesky other_fresh;
        REQUIRE(reused.Refactor(n, other));
        REQUIRE(other_fresh.Factor(n, other));
        a = rhs;
        b = rhs;
        reused.Solve(a);
        other_fresh.Solve(b);
        CHECK(SameBits(a, b));

        // An indefinite matrix of the analysed pattern is refused and leaves no factor.
        std::vector<NodeBlock> indefinite = other;
        indefinite.back().mBlock = -1.0e6 * Mat3::Identity();
        CHECK_FALSE(reused.Refactor(n, indefinite));
        CHECK_FALSE(reused.IsFactored());
        CHECK(reused.GetBlockCount() == 0);
    }
}

TEST_CASE("NodeBlockCholesky: the numeric factorisation's block products are counted from the pattern",
          "[fem]")
{
    // A chain of 50 nodes factors without fill (one block below each diagonal but the last's): 49. Twelve
    // nodes all coupled: column c from the end holds c blocks below its diagonal, sum of c (c + 1) / 2 over
    // c = 0..11 = 13 * 12 * 11 / 6 = 286.
    const auto tridiagonal = [](int inNodes)
    {
        std::vector<NodeBlock> blocks;
        for (int node = 0; node < inNodes; ++node)
        {
            blocks.push_back({node, node, 4.0 * Mat3::Identity()});
            if (node > 0)
                blocks.push_back({node, node - 1, -Mat3::Identity()});
        }
        return blocks;
    };
    std::vector<NodeBlock> dense;
    for (int i = 0; i < 12; ++i)
        for (int j = 0; j <= i; ++j)
            dense.push_back({i, j, Mat3((i == j ? 24.0 : 1.0) * Mat3::Identity())});
    NodeBlockCholesky chain, full, none;
    REQUIRE(chain.Factor(50, tridiagonal(50)));
    REQUIRE(full.Factor(12, dense));
    CHECK(chain.GetNumericBlockProducts() == 49);
    CHECK(full.GetNumericBlockProducts() == 286);
    CHECK(none.GetNumericBlockProducts() == 0);
}

TEST_CASE("Rest system at element frames: the assembled blocks apply the corotated implicit operator of a deformed mesh exactly",
          "[fem]")
{
    const TetMesh mesh = test::SmallTetBlock();
    const std::vector<TetElementRest> rest = TetRestData(mesh);
    FemMaterialSettings settings;
    settings.mYoungsModulus = 2.0e11;
    const FemMaterial material = FemMaterial::Create(settings).Get();
    const TetElementPassInput input{mesh.GetTets(), rest, &material.GetMaterialMatrix(), material.GetLambda(),
                                    material.GetShearModulus(), EElasticModel::CorotatedLinear, {}};

    // A strongly and unevenly deformed state: each node moved by up to a third of a cell.
    std::mt19937 random(5u);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const int node_count = mesh.GetNodeCount();
    std::vector<Vec3> positions = mesh.GetRestPositions();
    for (Vec3& position : positions)
        position += 0.06 * common::DrawVec3([&] { return unit(random); });
    std::vector<Quat> rotations(rest.size(), Quat::Identity());
    std::vector<TetLinearization> linearization(rest.size());
    std::vector<Vec3> forces(static_cast<std::size_t>(node_count));
    TetElasticForces(input, positions, {}, 0.0, rotations, linearization, forces);

    std::vector<double> masses(static_cast<std::size_t>(node_count));
    std::vector<int> free_index(static_cast<std::size_t>(node_count));
    int free_count = 0;
    for (int node = 0; node < node_count; ++node)
    {
        masses[static_cast<std::size_t>(node)] = 1.0 + 0.1 * node;
        free_index[static_cast<std::size_t>(node)] = node % 4 == 0 ? -1 : free_count++;
    }
    const double a = 1.25, b = 3.0e-4;
    std::vector<NodeBlock> blocks, rest_blocks;
    TetRestSystemBlocks(input, masses, free_index, a, b, blocks, nullptr, rotations);
    TetRestSystemBlocks(input, masses, free_index, a, b, rest_blocks);
    REQUIRE(blocks.size() == rest_blocks.size());
    for (std::size_t index = 0; index < blocks.size(); ++index)
    {
        // The pattern is the rest system's: a refresh reuses its analysis.
        CHECK(blocks[index].mRow == rest_blocks[index].mRow);
        CHECK(blocks[index].mColumn == rest_blocks[index].mColumn);
    }
    const Eigen::MatrixXd system = test::DenseSymmetric(blocks, free_count);
    for (int trial = 0; trial < 5; ++trial)
    {
        const test::OperatorDifference check =
            test::AssembledAgainstMatrixFree(input, linearization, system, masses, free_index, a, b, random);
        CHECK(check.mDifference <= 1.0e-12 * check.mScale);
    }
}

TEST_CASE("Factored preconditioner: a factor at frames F inverts the system at frames Q F through the node rotations Q",
          "[fem]")
{
    // Exact for any F when every element turned by the same Q since the factor: R A_F^-1 R^T = A_QF^-1.
    TetGridSettings grid;
    grid.mSize = Vec3(0.4, 0.4, 0.2);
    grid.mCellCount = {2, 2, 1};
    const TetMesh mesh = TetGrid(grid).Get();
    const std::vector<TetElementRest> rest = TetRestData(mesh);
    const FemMaterial material = FemMaterial::Create(FemMaterialSettings{}).Get();
    const TetElementPassInput input{mesh.GetTets(), rest, &material.GetMaterialMatrix(), material.GetLambda(),
                                    material.GetShearModulus(), EElasticModel::CorotatedLinear, {}};
    const int node_count = mesh.GetNodeCount();
    std::vector<double> masses(static_cast<std::size_t>(node_count), 2.0);
    std::vector<std::uint8_t> free(static_cast<std::size_t>(node_count), 1);
    free[0] = 0;
    std::vector<int> free_index(static_cast<std::size_t>(node_count), -1);
    int free_count = 0;
    for (int node = 0; node < node_count; ++node)
        if (free[static_cast<std::size_t>(node)] != 0)
            free_index[static_cast<std::size_t>(node)] = free_count++;

    std::mt19937 random(3u);
    std::vector<Quat> frames(rest.size());
    for (Quat& frame : frames)
        frame = RandomRotation(random); // uneven: no node rotation could fit these
    const Quat turn = RandomRotation(random);
    std::vector<Quat> turned(rest.size());
    for (std::size_t tet = 0; tet < rest.size(); ++tet)
        turned[tet] = turn * frames[tet];

    const double a = 1.0, b = 1.0e-4;
    TetFactoredPreconditioner factor;
    REQUIRE(factor.Precompute(input, masses, free, a, b, false, frames));
    factor.SetNodeRotations(mesh.GetTets(), turned, true);

    std::vector<NodeBlock> blocks;
    TetRestSystemBlocks(input, masses, free_index, a, b, blocks, nullptr, turned);
    const Eigen::MatrixXd system = test::DenseSymmetric(blocks, free_count);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    Eigen::VectorXd x(3 * free_count);
    for (int entry = 0; entry < 3 * free_count; ++entry)
        x[entry] = unit(random);
    const Eigen::VectorXd ax = system * x;
    std::vector<Vec3> r(static_cast<std::size_t>(node_count), Vec3::Zero()), z(static_cast<std::size_t>(node_count));
    for (int node = 0; node < node_count; ++node)
        if (const int index = free_index[static_cast<std::size_t>(node)]; index >= 0)
            r[static_cast<std::size_t>(node)] = ax.segment<3>(3 * index);
    factor.Apply(r, z);
    double difference = 0.0;
    for (int node = 0; node < node_count; ++node)
        if (const int index = free_index[static_cast<std::size_t>(node)]; index >= 0)
            difference = std::max(difference, (z[static_cast<std::size_t>(node)] - Vec3(x.segment<3>(3 * index))).cwiseAbs().maxCoeff());
        else
            CHECK(z[static_cast<std::size_t>(node)] == Vec3::Zero());
    CHECK(difference <= 1.0e-9 * x.cwiseAbs().maxCoeff());

    // Refreshed at the turned frames the factor needs no node rotation: the same answer.
    REQUIRE(factor.Refresh(input, masses, turned));
    factor.SetNodeRotations(mesh.GetTets(), turned, true);
    std::vector<Vec3> refreshed(static_cast<std::size_t>(node_count));
    factor.Apply(r, refreshed);
    CHECK(MaxDifference(refreshed, z) <= 1.0e-9 * x.cwiseAbs().maxCoeff());
}

TEST_CASE("Factor refresh: a struck rail follows the fully converged solve in fewer iterations, 0 never refreshes",
          "[fem]")
{
    TetSolverSettings refreshing;
    refreshing.mFactorRefreshIterations = 3;
    TetSolverSettings never;
    never.mFactorRefreshIterations = 0;
    TetSolverSettings converged;
    converged.mCgRelativeTolerance = 1.0e-12;
    converged.mCgMaxIterations = 100000;
    converged.mImplicitTolerance = 1.0e-14;
    converged.mImplicitMaxIterations = 30;
    TetSolver fast = StruckRail(refreshing);
    TetSolver plain = StruckRail(never);
    TetSolver reference = StruckRail(converged);
    int fast_iterations = 0, plain_iterations = 0;
    constexpr double cStep = 1.0 / 240.0;
    for (int step = 0; step < 12; ++step)
    {
        REQUIRE(Push(fast, step));
        REQUIRE(Push(plain, step));
        REQUIRE(Push(reference, step));
        const TetStepResult a = fast.Step(cStep).Get();
        const TetStepResult b = plain.Step(cStep).Get();
        REQUIRE(reference.Step(cStep).IsValid());
        CHECK_FALSE(HasEvent(a.mEvents, ETetStepEvent::SolverNotConverged));
        fast_iterations += a.mSolverIterations;
        plain_iterations += b.mSolverIterations;
    }
    // The Newton tolerance (1e-3 of the step's energy), not the preconditioner, sets how far both stray from
    // the converged answer in this violent push: the refresh changes the cost of the solves, not their answer.
    double displacement = 0.0;
    for (std::size_t node = 0; node < reference.GetPositions().size(); ++node)
        displacement = std::max(displacement, (reference.GetPositions()[node] - reference.GetMesh().GetRestPositions()[node]).norm());
    REQUIRE(displacement > 0.1);
    const double fast_error = MaxDifference(fast.GetPositions(), reference.GetPositions());
    const double plain_error = MaxDifference(plain.GetPositions(), reference.GetPositions());
    INFO("CG iterations over 12 steps: refreshing " << fast_iterations << " (" << fast.GetFactorRefreshCount()
                                                    << " refreshes), never " << plain_iterations << "; errors "
                                                    << fast_error << ", " << plain_error << " m of " << displacement);
    CHECK(fast.GetFactorRefreshCount() > 0);
    CHECK(plain.GetFactorRefreshCount() == 0);
    CHECK(fast.GetFactorizationCount() == 1);
    CHECK(2 * fast_iterations < plain_iterations);
    CHECK(fast_error <= 1.01 * plain_error);
    CHECK(MaxDifference(fast.GetPositions(), plain.GetPositions()) <= 1.0e-3 * displacement);
}

TEST_CASE("Factor refresh: steps that refresh allocate nothing once the solver has refreshed", "[fem]")
{
    if (!test::AllocationCounter::IsAvailable())
        common::SkipTest("allocations are not counted under AddressSanitizer (its runtime owns operator new)");
    TetSolverSettings settings;
    settings.mFactorRefreshIterations = 1; // refresh at every solve that needs a second iteration
    TetSolver slab = StruckRail(settings);
    REQUIRE(Push(slab, 0));
    REQUIRE(slab.Step(1.0 / 240.0).IsValid());
    REQUIRE(Push(slab, 1));
    REQUIRE(slab.Step(1.0 / 240.0).IsValid());
    REQUIRE(slab.GetFactorRefreshCount() > 0);
    const int before = slab.GetFactorRefreshCount();
    std::uint64_t allocations = 0;
    bool stepped = true;
    {
        const test::AllocationCounter counter;
        for (int step = 2; step < 6; ++step)
            stepped = Push(slab, step) && slab.Step(1.0 / 240.0).IsValid() && stepped;
        allocations = counter.Count();
    }
    CHECK(stepped);
    CHECK(slab.GetFactorRefreshCount() > before);
    CHECK(allocations == 0);
}

TEST_CASE("Factor refresh: a negative iteration count is refused", "[fem]")
{
    TetSolverSettings settings;
    settings.mFactorRefreshIterations = -1;
    TetGridSettings grid;
    const Result<TetSolver> refused = TetSolver::Create(TetGrid(grid).Get(), FemMaterialSettings{}, settings);
    REQUIRE_FALSE(refused.IsValid());
    CHECK(refused.GetError().mMessage.find("mFactorRefreshIterations") != std::string::npos);
}

TEST_CASE("Factor refresh: a copy of a refreshing solver continues bit for bit", "[fem]")
{
    // The frames of the last refresh are the solver's state: the copy factors at them, not at its own.
    TetSolver rail = RefreshedRail();
    TetSolver copy = rail;
    CHECK(ContinueAlike(rail, copy));
}

TEST_CASE("Factor refresh: Prepare after a refresh and new anchors factors at the frames the anchors set, as "
          "a copy that "
          "never prepares does",
          "[fem]")
{
    TetSolver rail = RefreshedRail();
    TetSolver copy = rail;
    // New anchors on both make the factor stale and set its frames (solver state,
    // FollowFramesAfterNewSystem): the rail prepares (as a game at a hand-over), the copy not.
    for (TetSolver* solver : {&rail, &copy})
        REQUIRE(solver->SetNodeFixed(TetGridNode({40, 2, 2}, 10, 1, 1), true).IsValid());
    REQUIRE(rail.Prepare(1.0 / 240.0).IsValid());
    CHECK(ContinueAlike(rail, copy));
}

TEST_CASE("Factor refresh: new anchors on a bent rail factor it at its current frames, where the next solve "
          "is linearised",
          "[fem]")
{
    // A budget at the CG limit: frames that follow the solver (its refreshes) but no refresh ever, so the
    // only new frames are those the new anchors bring. Against it the rest factor (0: never framed).
    // One Newton iteration a step: the step's iterations are those of the solve linearised at its start.
    TetSolverSettings following;
    following.mFactorRefreshIterations = following.mCgMaxIterations;
    following.mImplicitMaxIterations = 1;
    TetSolverSettings rest = following;
    rest.mFactorRefreshIterations = 0;
    TetSolver framed = StruckRail(following);
    TetSolver plain = StruckRail(rest);
    for (int step = 0; step < 3; ++step)
        for (TetSolver* solver : {&framed, &plain})
        {
            REQUIRE(Push(*solver, step));
            REQUIRE(solver->Step(1.0 / 240.0).IsValid());
        }
    REQUIRE(framed.GetFactorRefreshCount() == 0);
    int iterations[2] = {0, 0}, newton[2] = {0, 0};
    for (int index = 0; index < 2; ++index)
    {
        TetSolver& solver = index == 0 ? framed : plain;
        REQUIRE(solver.SetNodeFixed(TetGridNode({40, 2, 2}, 5, 1, 1), true).IsValid());
        const TetStepResult result = solver.Step(1.0 / 240.0).Get();
        iterations[index] = result.mSolverIterations;
        newton[index] = result.mNewtonIterations;
    }
    // At the frames of the last pass the factor is the system the step's solve is linearised in: one
    // iteration. Measured: 1 against the rest factor's 14.
    INFO("CG iterations after the new anchor: framed "
         << iterations[0] << " (" << newton[0] << " Newton), rest " << iterations[1] << " (" << newton[1]
         << ")");
    CHECK(iterations[0] == 1);
    CHECK(iterations[1] > 1);
}

TEST_CASE("Factor refresh: a crack factors a cracking rail at its current frames, where the next solve is "
          "linearised",
          "[fem]")
{
    // The wooden rail of the crack tests, one Newton iteration a step, its frames following the solver but
    // never refreshed (as above): the step after the first crack solves in one iteration.
    TetSolverSettings following;
    following.mGravity = Vec3::Zero();
    following.mFactorRefreshIterations = following.mCgMaxIterations;
    following.mImplicitMaxIterations = 1;
    TetSolver rail = common::MakePushedRailSolver(following).Get();
    const std::vector<int> struck = common::PushedRailNodes(rail.GetPositions());
    int step = 0;
    for (; step < common::cPushedRailSteps && rail.GetBrokenLinkCount() == 0; ++step)
    {
        REQUIRE(common::PushRailBeforeStep(rail, struck, step, 300.0).IsValid());
        REQUIRE(rail.Step(common::cPushedRailStep).IsValid());
    }
    REQUIRE(rail.GetBrokenLinkCount() > 0);
    REQUIRE(step < common::cPushedRailSteps);
    const int factorizations = rail.GetFactorizationCount();
    REQUIRE(common::PushRailBeforeStep(rail, struck, step, 300.0).IsValid());
    const TetStepResult after = rail.Step(common::cPushedRailStep).Get();
    INFO("step " << step << " after the crack: " << after.mSolverIterations << " CG iterations");
    CHECK(rail.GetFactorizationCount() == factorizations + 1);
    CHECK(after.mSolverIterations == 1);
}

TEST_CASE(
    "Factor refresh by cost: a rail settling after its push refreshes once its extra iterations add up to "
    "a refresh, and solves for less",
    "[fem]")
{
    // The held props' setting (refresh after 6) with and without the refresh by cost, stepped alike: the
    // push, then the rail swinging back and settling at other frames than those of its last refresh.
    TetSolverSettings after_six;
    after_six.mFactorRefreshIterations = 6;
    TetSolverSettings by_cost = after_six;
    by_cost.mFactorRefreshByCost = true;
    TetSolver plain = StruckRail(after_six);
    TetSolver costed = StruckRail(by_cost);
    int plain_iterations = 0, costed_iterations = 0, plain_tail = 0, costed_tail = 0;
    constexpr int cSteps = 48, cTailStart = 24;
    for (int step = 0; step < cSteps; ++step)
    {
        REQUIRE(Push(plain, step));
        REQUIRE(Push(costed, step));
        const TetStepResult a = plain.Step(1.0 / 240.0).Get();
        const TetStepResult b = costed.Step(1.0 / 240.0).Get();
        CHECK_FALSE(HasEvent(b.mEvents, ETetStepEvent::SolverNotConverged));
        plain_iterations += a.mSolverIterations;
        costed_iterations += b.mSolverIterations;
        plain_tail += step >= cTailStart ? a.mSolverIterations : 0;
        costed_tail += step >= cTailStart ? b.mSolverIterations : 0;
    }
    const double cost = costed.GetFactorRefreshCost();
    REQUIRE(cost > 1.0);
    const double plain_work = plain_iterations + cost * plain.GetFactorRefreshCount();
    const double costed_work = costed_iterations + cost * costed.GetFactorRefreshCount();
    double displacement = 0.0;
    for (std::size_t node = 0; node < plain.GetPositions().size(); ++node)
        displacement = std::max(
            displacement, (plain.GetPositions()[node] - plain.GetMesh().GetRestPositions()[node]).norm());
    INFO("a refresh costs " << cost << " iterations; CG iterations over " << cSteps << " steps: after 6 "
                            << plain_iterations << " (" << plain_tail << " in the late half, "
                            << plain.GetFactorRefreshCount() << " refreshes), by cost " << costed_iterations
                            << " (" << costed_tail << ", " << costed.GetFactorRefreshCount()
                            << " refreshes); work " << plain_work << " against " << costed_work
                            << " iterations");
    CHECK(costed.GetFactorRefreshCount() > plain.GetFactorRefreshCount());
    CHECK(costed_tail < plain_tail);
    CHECK(costed_work < plain_work);
    // A preconditioner changes the cost of the solves, not their answer (the Newton tolerance sets that).
    CHECK(MaxDifference(plain.GetPositions(), costed.GetPositions()) <= 1.0e-3 * displacement);
}

TEST_CASE("Factor refresh by cost: a copy made in the middle of an account continues bit for bit", "[fem]")
{
    // The account of extra iterations is solver state: a copy that started a new one would refresh at
    // another step.
    TetSolverSettings settings;
    settings.mFactorRefreshIterations = 6;
    settings.mFactorRefreshByCost = true;
    TetSolver rail = StruckRail(settings);
    for (int step = 0; step < 3; ++step)
    {
        REQUIRE(Push(rail, step));
        REQUIRE(rail.Step(1.0 / 240.0).IsValid());
    }
    TetSolver copy = rail;
    CHECK(ContinueAlike(rail, copy));
}
