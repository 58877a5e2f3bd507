// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// The factored preconditioner with the ground's filter (FactorGroundFilter): on filtered vectors it inverts
// the filtered system S A S exactly (against a dense solve on the filter's range), and a refreshing solver
// whose nodes the ground holds solves in as few iterations as one that nothing holds.
#include "AssembledSystemCheck.h"
#include "SmallTetBlock.h"
#include "TetElementPass.h"
#include "TetFactoredPreconditioner.h"
#include "TetRestSystemBlocks.h"

#include <crumple/fem/FemMaterial.h>
#include <crumple/fem/TetElementRest.h>
#include <crumple/fem/TetGrid.h>
#include <crumple/fem/TetSolver.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>

using namespace crumple;
using namespace crumple::fem;

namespace
{

// Orthonormal columns spanning the filter's range over the free nodes (3 x #free rows, in free order): three
// axes at a free node, the two directions across inNormal at a held one.
Eigen::MatrixXd FilterRange(std::span<const int> inFreeIndex, std::span<const std::uint8_t> inHeld,
                            const Vec3& inNormal, int inFreeCount)
{
    Vec3 across = inNormal.unitOrthogonal();
    const Vec3 across2 = inNormal.cross(across);
    std::vector<Eigen::VectorXd> columns;
    for (std::size_t node = 0; node < inFreeIndex.size(); ++node)
    {
        const int index = inFreeIndex[node];
        if (index < 0)
            continue;
        const auto add = [&](const Vec3& inDirection)
        {
            Eigen::VectorXd column = Eigen::VectorXd::Zero(3 * inFreeCount);
            column.segment<3>(3 * index) = inDirection;
            columns.push_back(column);
        };
        if (inHeld[node] != 0)
        {
            add(across);
            add(across2);
        }
        else
        {
            add(Vec3::UnitX());
            add(Vec3::UnitY());
            add(Vec3::UnitZ());
        }
    }
    Eigen::MatrixXd range(3 * inFreeCount, static_cast<Eigen::Index>(columns.size()));
    for (std::size_t column = 0; column < columns.size(); ++column)
        range.col(static_cast<Eigen::Index>(column)) = columns[column];
    return range;
}

// Largest difference between the factor's answer to r = S A S z (filtered) and z, over z's largest entry,
// for random z in the filter's range.
double FilteredInverseError(const TetFactoredPreconditioner& inFactor, const Eigen::MatrixXd& inSystem,
                            const Eigen::MatrixXd& inRange, std::span<const int> inFreeIndex,
                            std::mt19937& ioRandom)
{
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    Eigen::VectorXd reduced(inRange.cols());
    for (Eigen::Index entry = 0; entry < reduced.size(); ++entry)
        reduced[entry] = unit(ioRandom);
    const Eigen::VectorXd z = inRange * reduced;
    const Eigen::VectorXd r = inRange * (inRange.transpose() * (inSystem * z)); // S A S z, filtered
    const std::size_t node_count = inFreeIndex.size();
    std::vector<Vec3> residual(node_count, Vec3::Zero()), answer(node_count);
    for (std::size_t node = 0; node < node_count; ++node)
        if (const int index = inFreeIndex[node]; index >= 0)
            residual[node] = r.segment<3>(3 * index);
    inFactor.Apply(residual, answer);
    double difference = 0.0;
    for (std::size_t node = 0; node < node_count; ++node)
        if (const int index = inFreeIndex[node]; index >= 0)
            difference =
                std::max(difference, (answer[node] - Vec3(z.segment<3>(3 * index))).cwiseAbs().maxCoeff());
    return difference / z.cwiseAbs().maxCoeff();
}

// A steel bar 1 m x 0.1 m x 0.1 m (10 x 1 x 1 cells) on the ground z = 0 under gravity, solved as a held
// prop's solver is (refreshed after 6 iterations and by cost), sent sliding at 12 m/s with its top pushed
// into the ground at 6 m/s (a bumper driving a fence rail down): the nodes the ground holds change as it
// bends and bounces. inRoundOff: CG and Newton solved to round-off (the reference of the accuracy test).
TetSolver MakeDrivenBar(bool inRoundOff = false)
{
    TetGridSettings grid;
    grid.mSize = Vec3(1.0, 0.1, 0.1);
    grid.mCellCount = {10, 1, 1};
    FemMaterialSettings material;
    material.mYoungsModulus = 2.0e11;
    material.mDensity = 7850.0;
    TetSolverSettings settings;
    settings.mGravity = Vec3(0.0, 0.0, -9.81);
    settings.mGround = GroundPlane{true, Vec3::UnitZ(), 0.0, 0.6};
    settings.mFactorRefreshIterations = 6;
    settings.mFactorRefreshByCost = true;
    settings.mFactorGroundFilter = true;
    if (inRoundOff)
    {
        settings.mCgRelativeTolerance = 1.0e-13;
        settings.mCgMaxIterations = 100000;
        settings.mImplicitTolerance = 1.0e-14;
        settings.mImplicitMaxIterations = 40;
    }
    TetSolver bar = TetSolver::Create(TetGrid(grid).Get(), material, settings).Get();
    std::vector<Vec3> velocities(bar.GetVelocities().size());
    for (std::size_t node = 0; node < velocities.size(); ++node)
        velocities[node] = Vec3(12.0, 0.0, bar.GetPositions()[node].z() > 0.05 ? -6.0 : 0.0);
    REQUIRE(bar.SetVelocities(velocities).IsValid());
    return bar;
}

} // namespace

TEST_CASE(
    "Factored preconditioner with the ground's filter: it inverts the filtered system exactly on filtered "
    "vectors, after a refresh with other held nodes too",
    "[fem]")
{
    const TetMesh mesh = test::SmallTetBlock();
    const std::vector<TetElementRest> rest = TetRestData(mesh);
    const FemMaterial material = FemMaterial::Create(FemMaterialSettings{}).Get();
    const TetElementPassInput input{mesh.GetTets(),
                                    rest,
                                    &material.GetMaterialMatrix(),
                                    material.GetLambda(),
                                    material.GetShearModulus(),
                                    EElasticModel::CorotatedLinear,
                                    {}};
    const int node_count = mesh.GetNodeCount();
    std::vector<double> masses(static_cast<std::size_t>(node_count), 2.0);
    std::vector<std::uint8_t> free(static_cast<std::size_t>(node_count), 1);
    free[0] = 0; // an anchored node on the ground: the filter leaves it out
    std::vector<int> free_index(static_cast<std::size_t>(node_count), -1);
    int free_count = 0;
    for (int node = 0; node < node_count; ++node)
        if (free[static_cast<std::size_t>(node)] != 0)
            free_index[static_cast<std::size_t>(node)] = free_count++;

    // The bottom face held against a tilted ground; later the top face instead.
    const Vec3 normal = Vec3(0.3, -0.2, 1.0).normalized();
    std::vector<std::uint8_t> bottom(static_cast<std::size_t>(node_count), 0), top = bottom;
    for (int node = 0; node < node_count; ++node)
    {
        bottom[static_cast<std::size_t>(node)] =
            mesh.GetRestPositions()[static_cast<std::size_t>(node)].z() < 1.0e-9 ? 1 : 0;
        top[static_cast<std::size_t>(node)] =
            mesh.GetRestPositions()[static_cast<std::size_t>(node)].z() > 0.1 ? 1 : 0;
    }

    std::mt19937 random(7u);
    std::vector<Quat> frames(rest.size()), other_frames(rest.size());
    std::normal_distribution<double> gauss;
    const auto random_rotation = [&]
    {
        const double d = gauss(random), c = gauss(random), b = gauss(random), a = gauss(random);
        return Quat(Eigen::Vector4d(a, b, c, d).normalized());
    };
    for (std::size_t tet = 0; tet < rest.size(); ++tet)
    {
        frames[tet] = random_rotation();
        other_frames[tet] = random_rotation();
    }

    const double a = 1.0, b = 1.0e-4;
    const auto dense = [&](std::span<const Quat> inFrames)
    {
        std::vector<NodeBlock> blocks;
        TetRestSystemBlocks(input, masses, free_index, a, b, blocks, nullptr, inFrames);
        return test::DenseSymmetric(blocks, free_count);
    };

    TetFactoredPreconditioner filtered;
    REQUIRE(filtered.Precompute(input, masses, free, a, b, true, frames, FactorGroundFilter{bottom, normal}));
    const Eigen::MatrixXd system = dense(frames);
    const Eigen::MatrixXd bottom_range = FilterRange(free_index, bottom, normal, free_count);
    for (int trial = 0; trial < 3; ++trial)
        CHECK(FilteredInverseError(filtered, system, bottom_range, free_index, random) <= 1.0e-9);

    // The unfiltered factor, the preconditioner before the filter, misses by far more: the check can see it.
    TetFactoredPreconditioner unfiltered;
    REQUIRE(unfiltered.Precompute(input, masses, free, a, b, true, frames));
    CHECK(FilteredInverseError(unfiltered, system, bottom_range, free_index, random) >= 1.0e-2);

    // Refreshed at other frames with other held nodes (the same pattern, the analysis reused): exact again.
    REQUIRE(filtered.Refresh(input, masses, other_frames, FactorGroundFilter{top, normal}));
    const Eigen::MatrixXd other_system = dense(other_frames);
    const Eigen::MatrixXd top_range = FilterRange(free_index, top, normal, free_count);
    for (int trial = 0; trial < 3; ++trial)
        CHECK(FilteredInverseError(filtered, other_system, top_range, free_index, random) <= 1.0e-9);

    // A refresh with none held is the unfiltered factor at those frames.
    REQUIRE(filtered.Refresh(input, masses, other_frames));
    const Eigen::MatrixXd full_range =
        FilterRange(free_index, std::vector<std::uint8_t>(bottom.size(), 0), normal, free_count);
    CHECK(FilteredInverseError(filtered, other_system, full_range, free_index, random) <= 1.0e-9);
}

TEST_CASE(
    "Factored preconditioner with the ground's filter: a steel bar driven into the ground solves in few "
    "iterations after each refresh",
    "[fem]")
{
    // Its frames turn fast: most solves stop after 2 iterations and refresh. With the filter the rest takes
    // 1-2 (1,090 iterations in 332 solves, 252 refreshes); without it the factor misses the filtered system
    // by a rank-k difference, k the nodes the ground holds, and the rest took ~19 (6,814 in 320 solves: the
    // fem_ground bench's 50-tetrahedron rows).
    TetSolver bar = MakeDrivenBar();
    int solves = 0, iterations = 0, refreshes_before = bar.GetFactorRefreshCount();
    for (int step = 0; step < 120; ++step)
    {
        const Result<TetStepResult> result = bar.Step(1.0 / 240.0);
        REQUIRE(result.IsValid());
        CHECK_FALSE(HasEvent(result.Get().mEvents, ETetStepEvent::Diverged));
        solves += result.Get().mNewtonIterations;
        iterations += result.Get().mSolverIterations;
    }
    const int refreshes = bar.GetFactorRefreshCount() - refreshes_before;
    INFO(solves << " solves, " << iterations << " CG iterations, " << refreshes << " refreshes");
    CHECK(solves > 0);
    CHECK(iterations <= 4 * solves);
}

TEST_CASE("Ground: a step whose held nodes changed at its last iterate solves again, so the driven bar's "
          "friction follows the converged steps",
          "[fem]")
{
    // The friction reads the ground's impulses from the last iterate. An iterate at which the ground let go
    // of a node, or just after it caught one (its velocity set, not solved for), passed the Newton test on
    // its residual alone, which cannot see those nodes' normal imbalance: the filtered factor's test, which
    // reads the filtered system's remaining energy, then stopped after one solve with a node let go on a
    // residual of the solve's own round-off, and the driven bar slid away from the converged answer, 6.5e-2
    // m after these 120 steps (measured 4.2e-7 m with such iterates solved again).
    TetSolver bar = MakeDrivenBar();
    TetSolver converged = MakeDrivenBar(true);
    for (int step = 0; step < 120; ++step)
    {
        REQUIRE(bar.Step(1.0 / 240.0).IsValid());
        REQUIRE(converged.Step(1.0 / 240.0).IsValid());
    }
    double farthest = 0.0;
    for (std::size_t node = 0; node < bar.GetPositions().size(); ++node)
        farthest = std::max(farthest, (bar.GetPositions()[node] - converged.GetPositions()[node]).norm());
    CHECK(farthest <= 1.0e-5);
}
