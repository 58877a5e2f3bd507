// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/HexNodesInBox.h>
#include <crumple/fem/HexStaticPrecompute.h>
#include <crumple/fem/HexStaticSolve.h>

#include <catch2/catch.hpp>

#include <limits>

using namespace crumple;
using namespace crumple::fem;

namespace
{

// The cantilever of the FEM issue: 1 m x 0.1 m x 0.1 m steel, clamped at x = 0.
constexpr double cLength = 1.0;
constexpr double cWidth = 0.1;
constexpr double cHeight = 0.1;
constexpr double cLoad = 1000.0; // N, total, along -z

HexMesh Cantilever(int inNx, int inNy, int inNz)
{
    HexMeshSettings settings;
    settings.mSize = Vec3(cLength, cWidth, cHeight);
    settings.mCellCount = {inNx, inNy, inNz};
    return HexMesh::Create(settings).Get();
}

HexMaterial Steel(EHexFormulation inFormulation)
{
    HexMaterialSettings settings;
    settings.mYoungsModulus = 200.0e9;
    settings.mPoissonRatio = 0.3;
    settings.mFormulation = inFormulation;
    return HexMaterial::Create(settings).Get();
}

std::vector<int> ClampedFace(const HexMesh& inMesh)
{
    return HexNodesInBox(inMesh, Vec3(0.0, -1.0, -1.0), Vec3(0.0, 1.0, 1.0));
}

// The tip load as the consistent nodal forces of a uniform shear traction on the face x = L: each node gets the
// share of the face area of its surrounding cells (interior 1, edge 1/2, corner 1/4 cell).
Eigen::VectorXd TipLoad(const HexMesh& inMesh)
{
    const std::array<int, 3>& n = inMesh.GetGridCellCount();
    Eigen::VectorXd forces = Eigen::VectorXd::Zero(3 * inMesh.GetNodeCount());
    for (int k = 0; k <= n[2]; ++k)
        for (int j = 0; j <= n[1]; ++j)
        {
            const double share = (j == 0 || j == n[1] ? 0.5 : 1.0) * (k == 0 || k == n[2] ? 0.5 : 1.0);
            forces[3 * inMesh.GetGridNodeIndex(n[0], j, k) + 2] = -cLoad * share / (n[1] * n[2]);
        }
    return forces;
}

// Mean z displacement of the tip-face nodes (m).
double TipDeflection(const HexMesh& inMesh, const Eigen::VectorXd& inDisplacements)
{
    const std::array<int, 3>& n = inMesh.GetGridCellCount();
    double sum = 0.0;
    for (int k = 0; k <= n[2]; ++k)
        for (int j = 0; j <= n[1]; ++j)
            sum += inDisplacements[3 * inMesh.GetGridNodeIndex(n[0], j, k) + 2];
    return -sum / ((n[1] + 1) * (n[2] + 1));
}

// Timoshenko beam: delta = P L^3 / (3 E I) + P L / (kappa G A), kappa = 5/6 for a rectangle, I = b h^3 / 12.
double TimoshenkoDeflection()
{
    const double e = 200.0e9;
    const double g = e / (2.0 * (1.0 + 0.3));
    const double inertia = cWidth * cHeight * cHeight * cHeight / 12.0;
    const double area = cWidth * cHeight;
    return cLoad * cLength * cLength * cLength / (3.0 * e * inertia) + cLoad * cLength / (5.0 / 6.0 * g * area);
}

double RelativeTipError(int inNx, int inNy, int inNz, EHexFormulation inFormulation)
{
    const HexMesh mesh = Cantilever(inNx, inNy, inNz);
    const Result<HexStaticData> data = HexStaticPrecompute(mesh, Steel(inFormulation), ClampedFace(mesh));
    REQUIRE(data.IsValid());
    const Result<Eigen::VectorXd> u = HexStaticSolve(data.Get(), TipLoad(mesh));
    REQUIRE(u.IsValid());
    const double measured = TipDeflection(mesh, u.Get());
    const double analytic = TimoshenkoDeflection();
    const double error = (measured - analytic) / analytic;
    WARN(inNx << " x " << inNy << " x " << inNz << " cantilever, "
              << (inFormulation == EHexFormulation::IncompatibleModes ? "incompatible modes" : "full integration")
              << ": tip deflection " << measured * 1.0e3 << " mm, Timoshenko " << analytic * 1.0e3 << " mm, error "
              << error * 100.0 << " %");
    return error;
}

} // namespace

TEST_CASE("Hex cantilever 40 x 4 x 4: tip deflection within 5 % of Timoshenko beam theory", "[fem][hex]")
{
    // delta = 1000 * 1 / (3 * 200e9 * 8.333e-6) + 1000 * 1 / (5/6 * 76.92e9 * 0.01) = 0.2 mm + 1.56 um.
    CHECK(TimoshenkoDeflection() == Approx(2.0156e-4).epsilon(1.0e-4));
    // The default formulation (incompatible modes) measures -0.96 %: the clamp's Poisson restraint and the
    // 3D stress field at the root make the solid slightly stiffer than the beam.
    const double error = RelativeTipError(40, 4, 4, EHexFormulation::IncompatibleModes);
    CHECK(std::abs(error) < 0.05);
    CHECK(std::abs(error) < 0.015);
}

TEST_CASE("Plain fully integrated trilinear hexes shear-lock, incompatible modes do not", "[fem][hex]")
{
    // Same beam; full integration is -4.3 % on 40 x 4 x 4 (barely inside 5 %) and -13 % with 2 cells through
    // the depth, while incompatible modes stay near -1 % on both: the reason they are the default.
    const double full_fine = RelativeTipError(40, 4, 4, EHexFormulation::FullIntegration);
    const double full_coarse = RelativeTipError(20, 2, 2, EHexFormulation::FullIntegration);
    const double modes_coarse = RelativeTipError(20, 2, 2, EHexFormulation::IncompatibleModes);
    CHECK(full_fine < -0.03);
    CHECK(full_coarse < -0.10);
    CHECK(std::abs(modes_coarse) < 0.02);
}

TEST_CASE("HexStaticSolve ignores forces on fixed nodes and holds them at zero", "[fem][hex]")
{
    const HexMesh mesh = Cantilever(10, 2, 2);
    const std::vector<int> fixed = ClampedFace(mesh);
    const HexStaticData data = HexStaticPrecompute(mesh, Steel(EHexFormulation::IncompatibleModes), fixed).Get();
    CHECK(data.mFixedNodes == fixed);
    CHECK(data.mSmallestPivotRatio > cHexSingularPivotRatio);
    Eigen::VectorXd forces = TipLoad(mesh);
    const Eigen::VectorXd u = HexStaticSolve(data, forces).Get();
    for (int node : fixed)
    {
        CHECK(u.segment<3>(3 * node) == Vec3::Zero());
        forces.segment<3>(3 * node) = Vec3(1.0e9, -2.0e9, 3.0e9); // taken by the support
    }
    CHECK(HexStaticSolve(data, forces).Get() == u);
    // Linear: twice the load, twice the deflection (to rounding).
    CHECK((HexStaticSolve(data, 2.0 * TipLoad(mesh)).Get() - 2.0 * u).norm() < 1.0e-14 * u.norm());
}

TEST_CASE("HexStaticPrecompute refuses a singular system instead of inverting it", "[fem][hex]")
{
    const HexMesh mesh = Cantilever(10, 2, 2);
    const HexMaterial steel = Steel(EHexFormulation::IncompatibleModes);
    auto expect_singular = [&](const std::vector<int>& inFixed) {
        const Result<HexStaticData> data = HexStaticPrecompute(mesh, steel, inFixed);
        REQUIRE(data.HasError());
        CHECK(data.GetError().mCode == EError::DegenerateGeometry);
        CHECK(data.GetError().mMessage.find("singular") != std::string::npos);
        CHECK(data.GetError().mMessage.find("non-collinear") != std::string::npos);
    };
    SECTION("no fixed node: 6 rigid modes") { expect_singular({}); }
    SECTION("one fixed node: 3 rotations") { expect_singular({0}); }
    SECTION("two fixed nodes: a rotation about their line") { expect_singular({0, mesh.GetGridNodeIndex(0, 2, 2)}); }
    SECTION("a line of fixed nodes along the clamped edge")
    {
        expect_singular(HexNodesInBox(mesh, Vec3(0.0, -1.0, 0.0), Vec3(0.0, 1.0, 0.0)));
    }
    SECTION("three non-collinear nodes are enough")
    {
        const std::vector<int> three{0, mesh.GetGridNodeIndex(0, 2, 0), mesh.GetGridNodeIndex(0, 0, 2)};
        CHECK(HexStaticPrecompute(mesh, steel, three).IsValid());
    }
}

TEST_CASE("HexStaticPrecompute and HexStaticSolve refuse bad input", "[fem][hex]")
{
    const HexMesh mesh = Cantilever(4, 1, 1);
    const HexMaterial steel = Steel(EHexFormulation::IncompatibleModes);
    const std::vector<int> clamp = ClampedFace(mesh);
    SECTION("fixed node out of range")
    {
        const Result<HexStaticData> data = HexStaticPrecompute(mesh, steel, std::vector<int>{0, 20});
        REQUIRE(data.HasError());
        CHECK(data.GetError().mCode == EError::OutOfRange);
        CHECK(data.GetError().mMessage.find("fixed node 20") != std::string::npos);
        CHECK(HexStaticPrecompute(mesh, steel, std::vector<int>{-1}).GetError().mCode == EError::OutOfRange);
    }
    SECTION("forces a soft material cannot take: displacements that overflow are refused")
    {
        HexMaterialSettings soft;
        soft.mYoungsModulus = 1.0e-300;
        const HexStaticData data = HexStaticPrecompute(mesh, HexMaterial::Create(soft).Get(), clamp).Get();
        Eigen::VectorXd forces = Eigen::VectorXd::Zero(3 * mesh.GetNodeCount());
        forces[3 * (mesh.GetNodeCount() - 1) + 2] = 1.0e300;
        CHECK(HexStaticSolve(data, forces).GetError().mCode == EError::NonFinite);
        forces[3 * (mesh.GetNodeCount() - 1) + 2] = 1.0e-300;
        CHECK(HexStaticSolve(data, forces));
    }
    SECTION("every node fixed")
    {
        std::vector<int> all(mesh.GetNodeCount());
        for (int n = 0; n < mesh.GetNodeCount(); ++n)
            all[n] = n;
        CHECK(HexStaticPrecompute(mesh, steel, all).GetError().mCode == EError::InvalidArgument);
    }
    SECTION("a free node outside every element")
    {
        HexNodeMatrix nodes(mesh.GetNodeCount() + 1, 3);
        nodes << mesh.GetNodes(), Eigen::RowVector3d(5.0, 5.0, 5.0);
        const HexMesh loose = HexMesh::Create(nodes, mesh.GetElements()).Get();
        const Result<HexStaticData> data = HexStaticPrecompute(loose, steel, clamp);
        CHECK(data.GetError().mCode == EError::DegenerateGeometry);
        CHECK(data.GetError().mMessage.find("node 20 belongs to no element") != std::string::npos);
    }
    SECTION("repeated fixed nodes are merged")
    {
        std::vector<int> twice = clamp;
        twice.insert(twice.end(), clamp.rbegin(), clamp.rend());
        CHECK(HexStaticPrecompute(mesh, steel, twice).Get().mFixedNodes == clamp);
    }
    SECTION("forces of the wrong length, NaN forces, an empty precomputation")
    {
        const HexStaticData data = HexStaticPrecompute(mesh, steel, clamp).Get();
        const Result<Eigen::VectorXd> short_forces = HexStaticSolve(data, Eigen::VectorXd::Zero(59));
        CHECK(short_forces.GetError().mCode == EError::InvalidArgument);
        CHECK(short_forces.GetError().mMessage.find("3 x #nodes = 60") != std::string::npos);
        Eigen::VectorXd forces = Eigen::VectorXd::Zero(60);
        forces[40] = std::numeric_limits<double>::quiet_NaN();
        CHECK(HexStaticSolve(data, forces).GetError().mCode == EError::NonFinite);
        CHECK(HexStaticSolve(HexStaticData{}, Eigen::VectorXd::Zero(60)).GetError().mCode == EError::InvalidArgument);
    }
}
