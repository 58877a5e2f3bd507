// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// Inputs past what the FEM can hold are refused where they enter, and a refused call leaves the solver as it
// was: finite values whose squares or products overflow later (a review of the fem API found each of these).
#include <crumple/fem/FemMaterial.h>
#include <crumple/fem/HexComplianceFile.h>
#include <crumple/fem/HexComplianceSolve.h>
#include <crumple/fem/HexMaterial.h>
#include <crumple/fem/HexMesh.h>
#include <crumple/fem/TetFence.h>
#include <crumple/fem/TetGrid.h>
#include <crumple/fem/TetSolver.h>

#include <catch2/catch.hpp>

#include <limits>

using namespace crumple;
using namespace crumple::fem;

namespace
{

TetMesh Bar()
{
    TetGridSettings grid;
    grid.mSize = Vec3(1.0, 0.1, 0.1);
    grid.mCellCount = {10, 1, 1};
    return TetGrid(grid).Get();
}

// A bar anchored at x = 0 under a tip load, implicit.
TetSolver LoadedBar()
{
    TetSolverSettings settings;
    settings.mGravity = Vec3::Zero();
    TetSolver solver = TetSolver::Create(Bar(), FemMaterialSettings{}, settings).Get();
    for (int node = 0; node < solver.GetNodeCount(); ++node)
    {
        const Vec3& rest = solver.GetMesh().GetRestPositions()[static_cast<std::size_t>(node)];
        if (rest.x() < 1.0e-9)
            REQUIRE(solver.SetNodeFixed(node, true));
        if (rest.x() > 1.0 - 1.0e-9)
            REQUIRE(solver.SetExternalForce(node, Vec3(0.0, 0.0, -1.0e3)));
    }
    return solver;
}

} // namespace

TEST_CASE("A refused static solve leaves the next step as it would have been", "[fem]")
{
    // The failed solve's force pass must not stand in for the next step's first one.
    TetSolver refused = LoadedBar();
    TetSolver twin = LoadedBar();
    REQUIRE(refused.Step(1.0 / 60.0));
    REQUIRE(twin.Step(1.0 / 60.0));
    REQUIRE(refused.SolveStatic(1, 1.0e-12, 2).HasError());
    REQUIRE(refused.Step(1.0 / 60.0));
    REQUIRE(twin.Step(1.0 / 60.0));
    CHECK(refused.GetPositions() == twin.GetPositions());
    CHECK(refused.GetVelocities() == twin.GetVelocities());
}

TEST_CASE("FEM settings, materials and states beyond their bounds are refused, changing nothing", "[fem]")
{
    SECTION("a grid whose cell count overflows before the check")
    {
        TetGridSettings grid;
        grid.mCellCount = {1 << 22, 1 << 22, 1 << 20};
        CHECK(TetGrid(grid).GetError().mCode == EError::InvalidArgument);
    }
    SECTION("a hexahedral grid too large to place its nodes")
    {
        HexMeshSettings hex;
        hex.mSize = Vec3(1.0e308, 1.0, 1.0);
        hex.mCellCount = {2, 1, 1};
        CHECK(HexMesh::Create(hex).GetError().mCode == EError::NonFinite);
    }
    SECTION("materials whose derived quantities overflow")
    {
        for (int field = 0; field < 5; ++field)
        {
            FemMaterialSettings material;
            switch (field)
            {
            case 0: material.mYoungsModulus = 1.5e308; break;
            case 1: material.mDensity = 1.0e-310; break;
            case 2: material.mDensity = 1.0e9; break;
            case 3: material.mStiffnessDamping = 1.0e300; break;
            case 4: material.mMassDamping = 1.0e300; break;
            }
            INFO("field " << field);
            CHECK(FemMaterial::Create(material).GetError().mCode == EError::OutOfRange);
        }
        HexMaterialSettings hex;
        hex.mYoungsModulus = 1.5e308;
        CHECK(HexMaterial::Create(hex).GetError().mCode == EError::OutOfRange);
        FemMaterialSettings steel;
        steel.mYoungsModulus = 2.0e11;
        steel.mDensity = 7850.0;
        CHECK(FemMaterial::Create(steel));
    }
    SECTION("states past 1e100")
    {
        TetSolver solver = LoadedBar();
        const std::vector<Vec3> positions = solver.GetPositions(), velocities = solver.GetVelocities();
        const std::vector<Vec3> forces = solver.GetExternalForces();
        CHECK(solver.SetGravity(Vec3(0.0, 0.0, -1.0e300)).GetError().mCode == EError::OutOfRange);
        CHECK(solver.SetExternalForce(3, Vec3(1.0e300, 0.0, 0.0)).GetError().mCode == EError::OutOfRange);
        CHECK(solver.ApplyImpulse(solver.GetNodeCount() - 1, Vec3(1.0e300, 0.0, 0.0)).GetError().mCode == EError::OutOfRange);
        std::vector<Vec3> far = positions;
        far[5].x() = 1.0e200;
        CHECK(solver.SetPositions(far).GetError().mCode == EError::OutOfRange);
        std::vector<Vec3> fast(velocities.size(), Vec3(1.0e200, 0.0, 0.0));
        CHECK(solver.SetVelocities(fast).GetError().mCode == EError::OutOfRange);
        CHECK(solver.GetPositions() == positions);
        CHECK(solver.GetVelocities() == velocities);
        CHECK(solver.GetExternalForces() == forces);
        // The solver steps on as before.
        const Result<TetStepResult> stepped = solver.Step(1.0 / 60.0);
        REQUIRE(stepped);
        CHECK_FALSE(HasEvent(stepped.Get().mEvents, ETetStepEvent::Diverged));
    }
    SECTION("a fence with more posts or rails than cells")
    {
        TetFenceSettings fence;
        fence.mRailCount = std::numeric_limits<int>::max();
        CHECK(MakeTetFence(fence).HasError());
        fence = {};
        fence.mPostSpacing = 2.0e-9;
        CHECK(MakeTetFence(fence).HasError());
        CHECK(MakeTetFence(TetFenceSettings{}));
    }
    SECTION("a compliance no file could hold, and one that gives no finite displacement")
    {
        HexCompliance compliance;
        compliance.mNodeCount = 4;
        compliance.mLoadNodes = {1};
        compliance.mOutputNodes = {2, 3};
        compliance.mMatrix = Eigen::MatrixXd::Identity(6, 3);
        REQUIRE(EncodeHexCompliance(compliance));
        HexCompliance bad = compliance;
        bad.mLoadNodes = {7};
        CHECK(EncodeHexCompliance(bad).HasError());
        bad = compliance;
        bad.mOutputNodes = {2, 2};
        CHECK(EncodeHexCompliance(bad).HasError());
        bad = compliance;
        bad.mMatrix(1, 1) = std::numeric_limits<double>::quiet_NaN();
        CHECK(EncodeHexCompliance(bad).GetError().mCode == EError::NonFinite);
        CHECK(HexComplianceSolve(bad, Eigen::Vector3d(1.0, 1.0, 1.0)).GetError().mCode == EError::NonFinite);
        CHECK(HexComplianceSolve(compliance, Eigen::Vector3d(1.0, 1.0, 1.0)));
    }
}
