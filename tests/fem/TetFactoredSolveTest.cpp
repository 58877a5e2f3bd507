// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// The implicit solve preconditioned by the factored rest system (EImplicitPreconditioner::RestFactorization)
// against the matrix-free operator, block Jacobi, a fully converged solve and SolveStatic.
#include "AllocationCounter.h"
#include "AssembledSystemCheck.h"
#include "CantileverScene.h"
#include "DrawVec3.h"
#include "NodeBlockCholesky.h"
#include "SmallTetBlock.h"
#include "TetElementPass.h"
#include "TetRestSystemBlocks.h"

#include <crumple/fem/FemMaterial.h>
#include <crumple/fem/TetElementRest.h>
#include <crumple/fem/TetFence.h>
#include <crumple/fem/TetGrid.h>
#include <crumple/fem/TetSolver.h>

#include <BrittleMaterial.h>
#include <SkipTest.h>
#include <ThreadJobSystem.h>

#include <Eigen/OrderingMethods>
#include <Eigen/SparseCore>
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <random>

using namespace crumple;
using namespace crumple::fem;
using common::CantileverScene;

namespace
{

constexpr double cStep = 1.0 / 60.0; // s

CantileverScene MakeBeam(EElasticModel inModel, EImplicitPreconditioner inPreconditioner, int inLengthCells = 10,
                         int inSectionCells = 2)
{
    common::CantileverSettings settings;
    settings.mLengthCells = inLengthCells;
    settings.mSectionCells = inSectionCells;
    settings.mMaterial.mModel = inModel;
    settings.mSolver.mPreconditioner = inPreconditioner;
    Result<CantileverScene> beam = CantileverScene::Create(settings);
    REQUIRE(beam.IsValid());
    return std::move(beam).Get();
}

// The same beam solved to round-off: CG to 1e-12, Newton until its correction is below 1e-14 of the step's
// energy (the "fully converged implicit answer").
CantileverScene MakeConvergedBeam(EElasticModel inModel)
{
    common::CantileverSettings settings;
    settings.mLengthCells = 10;
    settings.mSectionCells = 2;
    settings.mMaterial.mModel = inModel;
    settings.mSolver.mCgRelativeTolerance = 1.0e-12;
    settings.mSolver.mCgMaxIterations = 100000;
    settings.mSolver.mImplicitTolerance = 1.0e-14;
    settings.mSolver.mImplicitMaxIterations = 30;
    Result<CantileverScene> beam = CantileverScene::Create(settings);
    REQUIRE(beam.IsValid());
    return std::move(beam).Get();
}

double MaxNorm(const std::vector<Vec3>& inValues)
{
    double largest = 0.0;
    for (const Vec3& value : inValues)
        largest = std::max(largest, value.cwiseAbs().maxCoeff());
    return largest;
}

// A 2 m x 0.2 m x 1 m brittle wall of 0.2 m cubes (E = 10 GPa, implicit), anchored along its base, hit on
// its front face around (1.6, 0, 0.8) with 4 x 2000 N s: it cracks within a few 1 ms steps.
TetSolver HitBrittleWall(double inMassDamping)
{
    TetGridSettings grid;
    grid.mSize = Vec3(2.0, 0.2, 1.0);
    grid.mCellCount = {10, 1, 5};
    FemMaterialSettings material = common::StiffBrittleMaterial();
    material.mMassDamping = inMassDamping;
    TetSolver wall = TetSolver::Create(TetGrid(grid).Get(), material, TetSolverSettings()).Get();
    for (int i = 0; i <= 10; ++i)
        for (int j = 0; j <= 1; ++j)
            REQUIRE(wall.SetNodeFixed(TetGridNode(grid.mCellCount, i, j, 0), true).IsValid());
    for (int k = 3; k <= 4; ++k)
        for (int i = 7; i <= 8; ++i)
            REQUIRE(wall.ApplyImpulse(TetGridNode(grid.mCellCount, i, 0, k), Vec3(0.0, 2000.0, 0.0)).IsValid());
    return wall;
}

} // namespace

TEST_CASE("Rest system: the assembled a M + b K0 blocks apply exactly the matrix-free implicit operator at rest",
          "[fem]")
{
    const TetMesh mesh = test::SmallTetBlock();
    const std::vector<TetElementRest> rest = TetRestData(mesh);
    std::mt19937 random(7u);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (EElasticModel model : {EElasticModel::CorotatedLinear, EElasticModel::StVenantKirchhoff})
    {
        FemMaterialSettings settings;
        settings.mModel = model;
        settings.mYoungsModulus = 2.0e11;
        settings.mPoissonRatio = 0.3;
        const FemMaterial material = FemMaterial::Create(settings).Get();
        const TetElementPassInput input{mesh.GetTets(), rest, &material.GetMaterialMatrix(), material.GetLambda(),
                                        material.GetShearModulus(), model, {}};

        // The linearisation at rest, the masses, some anchored nodes.
        const int node_count = mesh.GetNodeCount();
        std::vector<Quat> rotations(rest.size(), Quat::Identity());
        std::vector<TetLinearization> linearization(rest.size());
        std::vector<Vec3> forces(node_count);
        TetElasticForces(input, mesh.GetRestPositions(), {}, 0.0, rotations, linearization, forces);
        std::vector<double> masses(node_count);
        std::vector<int> free_index(node_count);
        int free_count = 0;
        for (int node = 0; node < node_count; ++node)
        {
            masses[node] = 1.0 + 0.1 * node;
            free_index[node] = node % 5 == 0 ? -1 : free_count++;
        }
        const double a = 1.25, b = 3.0e-4;
        std::vector<NodeBlock> blocks;
        TetRestSystemBlocks(input, masses, free_index, a, b, blocks);
        for (const NodeBlock& block : blocks)
            REQUIRE(block.mRow >= block.mColumn);
        const Eigen::MatrixXd system = test::DenseSymmetric(blocks, free_count);
        CHECK((system - system.transpose()).cwiseAbs().maxCoeff() <= 1.0e-15 * system.cwiseAbs().maxCoeff());

        // Random directions on the free nodes, zero on anchored ones.
        for (int trial = 0; trial < 5; ++trial)
        {
            const test::OperatorDifference check =
                test::AssembledAgainstMatrixFree(input, linearization, system, masses, free_index, a, b, random);
            CHECK(check.mDifference <= 1.0e-12 * check.mScale);
        }
    }
}

TEST_CASE("Rest system: kept element stiffness gives the blocks bit for bit, and follows a new rest shape and material",
          "[fem]")
{
    const TetMesh mesh = test::SmallTetBlock();
    std::vector<TetElementRest> rest = TetRestData(mesh);
    FemMaterialSettings settings;
    settings.mYoungsModulus = 2.0e11;
    settings.mPoissonRatio = 0.3;
    const FemMaterial steel = FemMaterial::Create(settings).Get();
    settings.mYoungsModulus = 1.0e10;
    const FemMaterial wood = FemMaterial::Create(settings).Get();
    const int node_count = mesh.GetNodeCount();
    std::vector<double> masses(static_cast<std::size_t>(node_count));
    std::vector<int> free_index(static_cast<std::size_t>(node_count));
    int free_count = 0;
    for (int node = 0; node < node_count; ++node)
    {
        masses[static_cast<std::size_t>(node)] = 1.0 + 0.1 * node;
        free_index[static_cast<std::size_t>(node)] = node % 5 == 0 ? -1 : free_count++;
    }
    const auto same = [](const std::vector<NodeBlock>& inA, const std::vector<NodeBlock>& inB)
    {
        if (inA.size() != inB.size())
            return false;
        for (std::size_t i = 0; i < inA.size(); ++i)
            if (inA[i].mRow != inB[i].mRow || inA[i].mColumn != inB[i].mColumn ||
                std::memcmp(inA[i].mBlock.data(), inB[i].mBlock.data(), sizeof(Mat3)) != 0)
                return false;
        return true;
    };
    TetRestStiffnessCache cache;
    for (const FemMaterial* material : {&steel, &steel, &wood})
    {
        const TetElementPassInput input{mesh.GetTets(), rest, &material->GetMaterialMatrix(), material->GetLambda(),
                                        material->GetShearModulus(), EElasticModel::CorotatedLinear, {}};
        std::vector<NodeBlock> afresh, kept;
        TetRestSystemBlocks(input, masses, free_index, 1.25, 3.0e-4, afresh);
        TetRestSystemBlocks(input, masses, free_index, 1.25, 3.0e-4, kept, &cache);
        CHECK(same(afresh, kept));
    }
    // A plastic flow changes an element's rest shape: its entry is made anew.
    rest[2].mRestEdgeInverse *= 1.01;
    const TetElementPassInput input{mesh.GetTets(), rest, &wood.GetMaterialMatrix(), wood.GetLambda(), wood.GetShearModulus(),
                                    EElasticModel::CorotatedLinear, {}};
    std::vector<NodeBlock> afresh, kept;
    TetRestSystemBlocks(input, masses, free_index, 1.25, 3.0e-4, afresh);
    TetRestSystemBlocks(input, masses, free_index, 1.25, 3.0e-4, kept, &cache);
    CHECK(same(afresh, kept));
}

TEST_CASE("NodeBlockCholesky: solves random sparse SPD block systems as a dense LLT does, refuses indefinite ones",
          "[fem]")
{
    std::mt19937 random(11u);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int trial = 0; trial < 20; ++trial)
    {
        // A random sparse graph of n nodes (random edges, duplicates included), SPD by diagonal dominance.
        const int n = 1 + static_cast<int>(random() % 40u);
        std::vector<NodeBlock> blocks;
        Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(3 * n, 3 * n);
        const int edges = static_cast<int>(random() % static_cast<std::uint32_t>(3 * n + 1));
        for (int edge = 0; edge < edges; ++edge)
        {
            const int i = static_cast<int>(random() % static_cast<std::uint32_t>(n));
            const int j = static_cast<int>(random() % static_cast<std::uint32_t>(n));
            if (i == j)
                continue;
            Mat3 block;
            for (int entry = 0; entry < 9; ++entry)
                block(entry / 3, entry % 3) = unit(random);
            blocks.push_back({std::max(i, j), std::min(i, j), block});
            const int row = std::max(i, j), column = std::min(i, j);
            dense.block<3, 3>(3 * row, 3 * column) += block;
            dense.block<3, 3>(3 * column, 3 * row) += block.transpose();
        }
        for (int node = 0; node < n; ++node)
        {
            const double dominance = dense.block(3 * node, 0, 3, 3 * n).cwiseAbs().sum() + 1.0 + unit(random) * 0.5;
            blocks.push_back({node, node, dominance * Mat3::Identity()});
            dense.block<3, 3>(3 * node, 3 * node) += dominance * Mat3::Identity();
        }
        NodeBlockCholesky cholesky;
        REQUIRE(cholesky.Factor(n, blocks));
        std::vector<Vec3> x(n);
        Eigen::VectorXd rhs(3 * n);
        for (int node = 0; node < n; ++node)
        {
            x[node] = common::DrawVec3([&] { return unit(random); });
            rhs.segment<3>(3 * node) = x[node];
        }
        cholesky.Solve(x);
        const Eigen::VectorXd expected = dense.llt().solve(rhs);
        double difference = 0.0;
        for (int node = 0; node < n; ++node)
            difference = std::max(difference, (x[node] - Vec3(expected.segment<3>(3 * node))).cwiseAbs().maxCoeff());
        CHECK(difference <= 1.0e-12 * expected.cwiseAbs().maxCoeff());

        // The same matrix shifted to be indefinite is refused.
        blocks.push_back({n - 1, n - 1, -1.0e6 * Mat3::Identity()});
        NodeBlockCholesky indefinite;
        CHECK_FALSE(indefinite.Factor(n, blocks));
        CHECK_FALSE(indefinite.IsFactored());
    }
}

TEST_CASE("NodeBlockCholesky: orders the nodes as Eigen's AMDOrdering orders the node graph", "[fem]")
{
    // The ordering hands Eigen's AMD routine the symmetric graph it builds itself; AMDOrdering, given the
    // graph as triplets, must find the same order (the same factor, bit for bit). Random graphs with repeated
    // edges, and a fence's element pattern.
    const auto reference = [](int inNodeCount, const std::vector<NodeBlock>& inBlocks)
    {
        std::vector<Eigen::Triplet<int>> entries;
        for (const NodeBlock& block : inBlocks)
        {
            entries.emplace_back(block.mRow, block.mColumn, 1);
            entries.emplace_back(block.mColumn, block.mRow, 1);
        }
        Eigen::SparseMatrix<int> graph(inNodeCount, inNodeCount);
        graph.setFromTriplets(entries.begin(), entries.end());
        Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> inverse;
        Eigen::AMDOrdering<int>()(graph, inverse);
        std::vector<int> rows(static_cast<std::size_t>(inNodeCount));
        for (int row = 0; row < inNodeCount; ++row)
            rows[static_cast<std::size_t>(inverse.indices()[row])] = row;
        return rows;
    };
    const auto diagonally_dominant = [](int inNodeCount, std::vector<NodeBlock> ioBlocks)
    {
        for (NodeBlock& block : ioBlocks)
            block.mBlock = block.mRow == block.mColumn ? Mat3(Mat3::Zero()) : Mat3(-Mat3::Identity());
        for (int node = 0; node < inNodeCount; ++node)
            ioBlocks.push_back({node, node, (1.0 + static_cast<double>(ioBlocks.size())) * Mat3::Identity()});
        return ioBlocks;
    };
    std::mt19937 random(5u);
    for (int trial = 0; trial < 30; ++trial)
    {
        const int n = 1 + static_cast<int>(random() % 300u);
        std::vector<NodeBlock> blocks;
        const int edges = static_cast<int>(random() % static_cast<std::uint32_t>(6 * n + 1));
        for (int edge = 0; edge < edges; ++edge)
        {
            const int i = static_cast<int>(random() % static_cast<std::uint32_t>(n));
            const int j = static_cast<int>(random() % static_cast<std::uint32_t>(n));
            blocks.push_back({std::max(i, j), std::min(i, j), Mat3::Zero()});
        }
        blocks = diagonally_dominant(n, blocks);
        NodeBlockCholesky cholesky;
        REQUIRE(cholesky.Factor(n, blocks));
        CHECK(cholesky.GetNodeRows() == reference(n, blocks));
    }
    TetFenceSettings fence_settings;
    fence_settings.mLength = 8.0;
    const TetFence fence = MakeTetFence(fence_settings).Get();
    std::vector<NodeBlock> blocks;
    for (const TetIndices& tet : fence.mMesh.GetTets())
        for (int a = 0; a < 4; ++a)
            for (int b = 0; b <= a; ++b)
                blocks.push_back({std::max(tet[a], tet[b]), std::min(tet[a], tet[b]), Mat3::Zero()});
    const int nodes = static_cast<int>(fence.mMesh.GetRestPositions().size());
    blocks = diagonally_dominant(nodes, blocks);
    NodeBlockCholesky cholesky;
    REQUIRE(cholesky.Factor(nodes, blocks));
    CHECK(cholesky.GetNodeRows() == reference(nodes, blocks));
}

TEST_CASE("Factored solve: the trajectory of the fully converged implicit solve, in a fraction of the iterations",
          "[fem]")
{
    for (EElasticModel model : {EElasticModel::CorotatedLinear, EElasticModel::StVenantKirchhoff})
    {
        CantileverScene factored = MakeBeam(model, EImplicitPreconditioner::RestFactorization);
        CantileverScene jacobi = MakeBeam(model, EImplicitPreconditioner::BlockJacobi);
        CantileverScene converged = MakeConvergedBeam(model);
        int factored_iterations = 0, jacobi_iterations = 0;
        for (int step = 0; step < 10; ++step)
        {
            const TetStepResult a = factored.GetSolver().Step(cStep).Get();
            const TetStepResult b = jacobi.GetSolver().Step(cStep).Get();
            REQUIRE(converged.GetSolver().Step(cStep).IsValid());
            CHECK_FALSE(HasEvent(a.mEvents, ETetStepEvent::SolverNotConverged));
            factored_iterations += a.mSolverIterations;
            jacobi_iterations += b.mSolverIterations;

            // Every step within 1e-5 of the converged tip: the default Newton tolerance (1e-3 of the step's
            // energy) stops St. Venant-Kirchhoff's second step after one Newton iteration, 4.3e-6 off, with
            // either preconditioner; the error then decays with the load's transient.
            const double reference = converged.TipDeflection();
            CHECK(std::abs(factored.TipDeflection() - reference) <= 1.0e-5 * std::abs(reference));
            CHECK(std::abs(jacobi.TipDeflection() - reference) <= 1.0e-5 * std::abs(reference));
            if (step == 9)
                CHECK(std::abs(factored.TipDeflection() - reference) <= 1.0e-8 * std::abs(reference));
        }
        INFO(ToString(model) << ": CG iterations over 10 steps, factored " << factored_iterations
                             << ", block Jacobi " << jacobi_iterations);
        CHECK(factored.GetSolver().GetFactorizationCount() == 1);
        CHECK(jacobi.GetSolver().GetFactorizationCount() == 0);
        CHECK(factored_iterations > 0);
        CHECK(10 * factored_iterations < jacobi_iterations);
    }
}

TEST_CASE("Factored solve: damped steps settle on SolveStatic's equilibrium to 1e-6", "[fem]")
{
    for (EElasticModel model : {EElasticModel::CorotatedLinear, EElasticModel::StVenantKirchhoff})
    {
        // SolveStatic's default residual (1e-6 of the load) is the tightest round-off allows on this beam; it
        // puts the tip within ~4e-9 of equilibrium (the two preconditioners' answers differ by that).
        CantileverScene statics = MakeBeam(model, EImplicitPreconditioner::BlockJacobi);
        REQUIRE(statics.GetSolver().SolveStatic().IsValid());
        const double reference = statics.TipDeflection();

        // Mass damping near critical for the first mode: implicit Euler's fixed point is the equilibrium.
        common::CantileverSettings settings;
        settings.mLengthCells = 10;
        settings.mSectionCells = 2;
        settings.mMaterial.mModel = model;
        settings.mMaterial.mMassDamping = 1000.0;
        settings.mSolver.mCgRelativeTolerance = 1.0e-10;
        CantileverScene damped = CantileverScene::Create(settings).Get();
        for (int step = 0; step < 40; ++step)
            REQUIRE(damped.GetSolver().Step(cStep).IsValid());
        INFO(ToString(model) << ": static tip " << reference << " m, settled " << damped.TipDeflection() << " m");
        CHECK(std::abs(damped.TipDeflection() - reference) <= 1.0e-6 * reference);

        // And SolveStatic preconditioned by the factored stiffness finds the same equilibrium.
        CantileverScene factored_statics = MakeBeam(model, EImplicitPreconditioner::RestFactorization);
        const TetStaticResult solve = factored_statics.GetSolver().SolveStatic().Get();
        CHECK(factored_statics.GetSolver().GetFactorizationCount() == 1);
        CHECK(std::abs(factored_statics.TipDeflection() - reference) <= 1.0e-7 * reference);
        CHECK(solve.mSolverIterations < 100);
    }
}

TEST_CASE("Factored solve: factored once, again only after anchoring, a new step length or fracture", "[fem]")
{
    CantileverScene beam = MakeBeam(EElasticModel::CorotatedLinear, EImplicitPreconditioner::RestFactorization);
    TetSolver& solver = beam.GetSolver();
    CHECK(solver.GetFactorizationCount() == 0);
    for (int step = 0; step < 5; ++step)
        REQUIRE(solver.Step(cStep).IsValid());
    CHECK(solver.GetFactorizationCount() == 1);
    REQUIRE(solver.Step(0.5 * cStep).IsValid());
    CHECK(solver.GetFactorizationCount() == 2);
    REQUIRE(solver.SetNodeFixed(beam.GetTipNodes()[0], true).IsValid());
    REQUIRE(solver.Step(0.5 * cStep).IsValid());
    REQUIRE(solver.Step(0.5 * cStep).IsValid());
    CHECK(solver.GetFactorizationCount() == 3);

    // A brittle wall hit hard enough to crack: each step after one that opened links factors again, no other.
    TetSolver wall = HitBrittleWall(2.0);
    int fracture_steps = 0;
    bool fractured_before = false;
    for (int step = 0; step < 20; ++step)
    {
        const int before = wall.GetFactorizationCount();
        const TetStepResult result = wall.Step(1.0e-3).Get();
        CHECK(wall.GetFactorizationCount() == before + (step == 0 || fractured_before ? 1 : 0));
        fractured_before = HasEvent(result.mEvents, ETetStepEvent::Fractured);
        fracture_steps += fractured_before ? 1 : 0;
    }
    CHECK(fracture_steps > 0);
    CHECK(wall.GetBrokenLinkCount() > 0);
}

TEST_CASE("Factored solve: a copy continues bit for bit, and a run repeats bit for bit", "[fem]")
{
    CantileverScene first = MakeBeam(EElasticModel::CorotatedLinear, EImplicitPreconditioner::RestFactorization);
    CantileverScene second = MakeBeam(EElasticModel::CorotatedLinear, EImplicitPreconditioner::RestFactorization);
    for (int step = 0; step < 5; ++step)
    {
        REQUIRE(first.GetSolver().Step(cStep).IsValid());
        REQUIRE(second.GetSolver().Step(cStep).IsValid());
    }
    TetSolver copy = first.GetSolver();
    CHECK(copy.GetFactorizationCount() == first.GetSolver().GetFactorizationCount());
    for (int step = 0; step < 5; ++step)
    {
        REQUIRE(first.GetSolver().Step(cStep).IsValid());
        REQUIRE(second.GetSolver().Step(cStep).IsValid());
        REQUIRE(copy.Step(cStep).IsValid());
    }
    CHECK(copy.GetPositions() == first.GetSolver().GetPositions());
    CHECK(copy.GetVelocities() == first.GetSolver().GetVelocities());
    CHECK(second.GetSolver().GetPositions() == first.GetSolver().GetPositions());
    CHECK(MaxNorm(first.GetSolver().GetVelocities()) > 0.0);
}

TEST_CASE("Factored solve: an implicit step allocates nothing once the solver has stepped", "[fem]")
{
    if (!test::AllocationCounter::IsAvailable())
        common::SkipTest("allocations are not counted under AddressSanitizer (its runtime owns operator new)");
    for (EElasticModel model : {EElasticModel::CorotatedLinear, EElasticModel::StVenantKirchhoff})
    {
        CantileverScene beam = MakeBeam(model, EImplicitPreconditioner::RestFactorization);
        REQUIRE(beam.GetSolver().Step(cStep).IsValid());
        std::uint64_t allocations = 0;
        int iterations = 0;
        {
            const test::AllocationCounter counter;
            for (int step = 0; step < 5; ++step)
            {
                const Result<TetStepResult> result = beam.GetSolver().Step(cStep);
                iterations += result.IsValid() ? result.Get().mSolverIterations : 0;
            }
            allocations = counter.Count();
        }
        INFO(ToString(model));
        CHECK(iterations > 0);
        CHECK(allocations == 0);
    }
}

TEST_CASE("Element passes on the host's jobs: bitwise the serial results for 1, 2 and 4 threads", "[fem]")
{
    // Implicit (factored) and explicit beams, and a brittle wall that cracks (the connectivity changes under
    // the gather), each stepped serially and on 2 and 4 threads.
    struct Run
    {
        std::vector<Vec3> mPositions;
        std::vector<Vec3> mVelocities;
        int mBroken = 0;
    };
    const auto beam_run = [](EIntegrator inIntegrator, const JobSystem* inJobs)
    {
        common::CantileverSettings settings;
        settings.mLengthCells = 30;
        settings.mSectionCells = 3;
        settings.mSolver.mIntegrator = inIntegrator;
        CantileverScene beam = CantileverScene::Create(settings).Get();
        beam.GetSolver().SetJobSystem(inJobs);
        const double step = inIntegrator == EIntegrator::ImplicitEuler ? cStep : 2.0e-5;
        for (int index = 0; index < 5; ++index)
            REQUIRE(beam.GetSolver().Step(step).IsValid());
        return Run{beam.GetSolver().GetPositions(), beam.GetSolver().GetVelocities(), 0};
    };
    const auto wall_run = [](const JobSystem* inJobs)
    {
        TetSolver wall = HitBrittleWall(0.0);
        wall.SetJobSystem(inJobs);
        for (int index = 0; index < 10; ++index)
            REQUIRE(wall.Step(1.0e-3).IsValid());
        return Run{wall.GetPositions(), wall.GetVelocities(), wall.GetBrokenLinkCount()};
    };

    const Run implicit_serial = beam_run(EIntegrator::ImplicitEuler, nullptr);
    const Run explicit_serial = beam_run(EIntegrator::SymplecticEuler, nullptr);
    const Run wall_serial = wall_run(nullptr);
    REQUIRE(wall_serial.mBroken > 0);
    for (int threads : {1, 2, 4})
    {
        const common::ThreadJobSystem jobs(threads);
        INFO(threads << " threads");
        const Run implicit_parallel = beam_run(EIntegrator::ImplicitEuler, &jobs.Get());
        CHECK(implicit_parallel.mPositions == implicit_serial.mPositions);
        CHECK(implicit_parallel.mVelocities == implicit_serial.mVelocities);
        const Run explicit_parallel = beam_run(EIntegrator::SymplecticEuler, &jobs.Get());
        CHECK(explicit_parallel.mPositions == explicit_serial.mPositions);
        CHECK(explicit_parallel.mVelocities == explicit_serial.mVelocities);
        const Run wall_parallel = wall_run(&jobs.Get());
        CHECK(wall_parallel.mBroken == wall_serial.mBroken);
        CHECK(wall_parallel.mPositions == wall_serial.mPositions);
        CHECK(wall_parallel.mVelocities == wall_serial.mVelocities);
    }
}
