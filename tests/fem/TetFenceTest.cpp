// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/TetFence.h>
#include <crumple/fem/TetSolver.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

using namespace crumple;
using namespace crumple::fem;

TEST_CASE("MakeTetFence cuts posts and rails from one lattice: counts, volume, one connected piece", "[fem]")
{
    // 4 m x 1.2 m x 0.1 m, 0.1 m cubes: three posts (x = 0, 2, 4, flush at the ends) of 1 x 1 x 12 cubes and
    // two rails (centred at 0.4 and 0.8 m) of 40 cubes each, 2 x 3 cubes shared: 36 + 80 - 6 = 110 cubes.
    const Result<TetFence> fence = MakeTetFence(TetFenceSettings{});
    REQUIRE(fence.IsValid());
    const TetMesh& mesh = fence.Get().mMesh;
    CHECK(mesh.GetTetCount() == 110 * 5);
    CHECK(mesh.GetTotalVolume() == Approx(110 * 0.001).epsilon(1e-12));
    // The post bottoms: 3 posts x 2 x 2 nodes.
    CHECK(fence.Get().mGroundNodes.size() == 12u);
    for (int node : fence.Get().mGroundNodes)
        CHECK(mesh.GetRestPositions()[node].z() == 0.0);

    // Posts and rails conform: an unbreakable solver sees one piece, and anchored at the ground it carries
    // its own weight with a small sag.
    TetSolver solver = TetSolver::Create(mesh, FemMaterialSettings{}, TetSolverSettings{}).Get();
    CHECK(solver.ComputeFragments().size() == 1u);
    for (int node : fence.Get().mGroundNodes)
        REQUIRE(solver.SetNodeFixed(node, true).IsValid());
    REQUIRE(solver.SolveStatic().IsValid());
    double sag = 0.0;
    for (int node = 0; node < solver.GetNodeCount(); ++node)
        sag = std::max(sag, mesh.GetRestPositions()[node].z() - solver.GetPositions()[node].z());
    CHECK(sag > 0.0);
    CHECK(sag < 0.01);
}

TEST_CASE("MakeTetFence refuses bad sizes, naming the field", "[fem]")
{
    TetFenceSettings settings;
    settings.mPostWidth = -0.1;
    Result<TetFence> refused = MakeTetFence(settings);
    REQUIRE(refused.HasError());
    CHECK(refused.GetError().mMessage.find("mPostWidth") != std::string::npos);
    settings = TetFenceSettings{};
    settings.mHeight = std::numeric_limits<double>::quiet_NaN();
    CHECK(MakeTetFence(settings).HasError());
    settings = TetFenceSettings{};
    settings.mRailCount = 0;
    CHECK(MakeTetFence(settings).HasError());
    settings = TetFenceSettings{};
    settings.mCellSize = 1e-6;
    refused = MakeTetFence(settings);
    REQUIRE(refused.HasError());
    CHECK(refused.GetError().mMessage.find("mCellSize") != std::string::npos);
}
