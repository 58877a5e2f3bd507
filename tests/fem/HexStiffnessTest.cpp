// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/HexElementStiffness.h>
#include <crumple/fem/HexStaticPrecompute.h>
#include <crumple/fem/HexStaticSolve.h>
#include <crumple/fem/HexStiffness.h>

#include <catch2/catch.hpp>

#include <cstdint>
#include <cstring>

using namespace crumple;
using namespace crumple::fem;

namespace
{

constexpr int cCells = 4;

// A 4 x 4 x 4 unit cube with every node moved by up to +-0.2 of a cell (a fixed pseudo-random sequence), so no
// element is a box and no face is planar.
HexMesh DistortedCube()
{
    HexMeshSettings settings;
    settings.mCellCount = {cCells, cCells, cCells};
    const HexMesh grid = HexMesh::Create(settings).Get();
    HexNodeMatrix nodes = grid.GetNodes();
    std::uint64_t state = 0x9E3779B97F4A7C15ull;
    for (int n = 0; n < nodes.rows(); ++n)
        for (int axis = 0; axis < 3; ++axis)
        {
            state = state * 6364136223846793005ull + 1442695040888963407ull;
            const double unit = static_cast<double>(state >> 11) / 9007199254740992.0; // [0, 1)
            nodes(n, axis) += (unit - 0.5) * 0.4 / cCells;
        }
    return HexMesh::Create(nodes, grid.GetElements()).Get();
}

bool OnBoundary(int inNode)
{
    const int i = inNode % (cCells + 1);
    const int j = (inNode / (cCells + 1)) % (cCells + 1);
    const int k = inNode / ((cCells + 1) * (cCells + 1));
    return i == 0 || j == 0 || k == 0 || i == cCells || j == cCells || k == cCells;
}

HexMaterial Material(EHexFormulation inFormulation)
{
    HexMaterialSettings settings;
    settings.mFormulation = inFormulation;
    return HexMaterial::Create(settings).Get();
}

} // namespace

TEST_CASE("Hex patch test: a linear field on the boundary of a distorted mesh is reproduced inside", "[fem][hex]")
{
    const EHexFormulation formulation =
        GENERATE(EHexFormulation::IncompatibleModes, EHexFormulation::FullIntegration);
    CAPTURE(static_cast<int>(formulation));
    const HexMesh mesh = DistortedCube();
    const HexMaterial material = Material(formulation);

    // u(x) = a + G x, prescribed on the 98 boundary nodes; the 27 interior nodes are free and unloaded.
    const Vec3 a(1.0e-3, -2.0e-3, 0.5e-3);
    Mat3 gradient;
    gradient << 1.0e-3, 0.2e-3, -0.3e-3, 0.4e-3, -0.5e-3, 0.1e-3, 0.25e-3, 0.15e-3, 0.7e-3;
    Eigen::VectorXd exact(3 * mesh.GetNodeCount());
    std::vector<int> boundary;
    for (int n = 0; n < mesh.GetNodeCount(); ++n)
    {
        exact.segment<3>(3 * n) = a + gradient * mesh.GetNodes().row(n).transpose();
        if (OnBoundary(n))
            boundary.push_back(n);
    }
    REQUIRE(boundary.size() == 98);

    const Result<HexStaticData> data = HexStaticPrecompute(mesh, material, boundary);
    REQUIRE(data.IsValid());
    const Result<Eigen::VectorXd> u = HexStaticSolve(data.Get(), Eigen::VectorXd::Zero(exact.size()), exact);
    REQUIRE(u.IsValid());
    const double error = (u.Get() - exact).lpNorm<Eigen::Infinity>() / exact.lpNorm<Eigen::Infinity>();
    WARN("patch test, formulation " << static_cast<int>(formulation) << ": max relative error " << error);
    CHECK(error < 1.0e-10);
    // The boundary values are returned exactly as prescribed.
    for (int n : boundary)
        CHECK(u.Get().segment<3>(3 * n) == exact.segment<3>(3 * n));
}

TEST_CASE("Hex global stiffness: small rigid motions cost no force, assembly is symmetric and reproducible",
          "[fem][hex]")
{
    const EHexFormulation formulation =
        GENERATE(EHexFormulation::IncompatibleModes, EHexFormulation::FullIntegration);
    const HexMesh mesh = DistortedCube();
    const HexMaterial material = Material(formulation);
    const Result<Eigen::SparseMatrix<double>> assembled = HexStiffness(mesh, material);
    REQUIRE(assembled.IsValid());
    const Eigen::SparseMatrix<double>& k = assembled.Get();
    REQUIRE(k.rows() == 3 * 125);
    CHECK((k - Eigen::SparseMatrix<double>(k.transpose())).norm() == 0.0);

    // Translation t plus infinitesimal rotation w x x (1e-3 rad, 1 mm).
    const Vec3 t(1.0e-3, -0.5e-3, 2.0e-3);
    const Vec3 w(0.3e-3, -1.0e-3, 0.6e-3);
    Eigen::VectorXd u(3 * mesh.GetNodeCount());
    for (int n = 0; n < mesh.GetNodeCount(); ++n)
        u.segment<3>(3 * n) = t + w.cross(Vec3(mesh.GetNodes().row(n).transpose()));
    const Eigen::VectorXd force = k * u;
    // Compare with the force the same displacements would raise in a single loaded dof: |K|_max |u|_max.
    const double scale = Eigen::MatrixXd(k).cwiseAbs().maxCoeff() * u.lpNorm<Eigen::Infinity>();
    WARN("rigid motion: max |K u| = " << force.lpNorm<Eigen::Infinity>() << " N against a force scale of " << scale
                                      << " N");
    CHECK(force.lpNorm<Eigen::Infinity>() < 1.0e-12 * scale);

    // The sum of the element stiffnesses, and bitwise the same on a second assembly.
    const Eigen::SparseMatrix<double> again = HexStiffness(mesh, material).Get();
    REQUIRE(again.nonZeros() == k.nonZeros());
    CHECK(std::memcmp(again.valuePtr(), k.valuePtr(), sizeof(double) * static_cast<std::size_t>(k.nonZeros())) == 0);
    const HexElementStiffnessMatrix k0 = HexElementStiffness(mesh.GetCorners(0), material).Get();
    // Node 0 is a corner of element 0 only, so its diagonal block is that element's block.
    CHECK(Eigen::MatrixXd(k).block<3, 3>(0, 0) == k0.block<3, 3>(0, 0));
}

TEST_CASE("Hex global stiffness couples exactly the nodes that share an element", "[fem][hex]")
{
    HexMeshSettings settings;
    settings.mCellCount = {3, 2, 1};
    const HexMesh mesh = HexMesh::Create(settings).Get();
    const Eigen::SparseMatrix<double> k = HexStiffness(mesh, Material(EHexFormulation::IncompatibleModes)).Get();
    CHECK(k.rows() == 3 * 24);
    // Each node couples to the nodes of its elements: corner node 0 to 8 nodes, 24 entries per column.
    CHECK(k.col(0).nonZeros() == 24);
    // Node (1, 1, 0) touches 4 cells: 18 neighbours (3 x 3 x 2).
    CHECK(k.col(3 * mesh.GetGridNodeIndex(1, 1, 0)).nonZeros() == 54);
}
