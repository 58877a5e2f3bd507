// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/HexMesh.h>
#include <crumple/fem/HexNodesInBox.h>

#include <catch2/catch.hpp>

#include <limits>

using namespace crumple;
using namespace crumple::fem;

namespace
{

HexMeshSettings Box()
{
    HexMeshSettings settings;
    settings.mOrigin = Vec3(-0.5, 1.0, 2.0);
    settings.mSize = Vec3(2.0, 1.0, 0.5);
    settings.mCellCount = {4, 2, 1};
    return settings;
}

// Signed volume of a box-shaped element from its corners 0, 1, 3, 4 (edges along xi, eta, zeta).
double BoxVolume(const HexCornerMatrix& inCorners)
{
    const Vec3 origin = inCorners.row(0).transpose();
    const Vec3 ex = inCorners.row(1).transpose() - origin;
    const Vec3 ey = inCorners.row(3).transpose() - origin;
    const Vec3 ez = inCorners.row(4).transpose() - origin;
    return ex.cross(ey).dot(ez);
}

} // namespace

TEST_CASE("HexMesh numbers a structured box as documented", "[fem][hex]")
{
    const HexMesh mesh = HexMesh::Create(Box()).Get();
    REQUIRE(mesh.IsStructured());
    CHECK(mesh.GetNodeCount() == 5 * 3 * 2);
    CHECK(mesh.GetElementCount() == 4 * 2 * 1);
    CHECK(mesh.GetGridNodeIndex(4, 2, 1) == 29);
    // Node (i, j, k) sits at origin + size * (i / nx, j / ny, k / nz), exactly at the far faces.
    CHECK(mesh.GetNodes().row(mesh.GetGridNodeIndex(0, 0, 0)) == Eigen::RowVector3d(-0.5, 1.0, 2.0));
    CHECK(mesh.GetNodes().row(mesh.GetGridNodeIndex(4, 2, 1)) == Eigen::RowVector3d(1.5, 2.0, 2.5));
    CHECK(mesh.GetNodes().row(mesh.GetGridNodeIndex(1, 1, 0)) == Eigen::RowVector3d(0.0, 1.5, 2.0));
    // Cell (3, 1, 0) = element 7: corner order (-,-,-), (+,-,-), (+,+,-), (-,+,-), then the same at +z.
    const auto corners = mesh.GetElements().row(7);
    CHECK(corners(0) == mesh.GetGridNodeIndex(3, 1, 0));
    CHECK(corners(1) == mesh.GetGridNodeIndex(4, 1, 0));
    CHECK(corners(2) == mesh.GetGridNodeIndex(4, 2, 0));
    CHECK(corners(3) == mesh.GetGridNodeIndex(3, 2, 0));
    CHECK(corners(4) == mesh.GetGridNodeIndex(3, 1, 1));
    CHECK(corners(6) == mesh.GetGridNodeIndex(4, 2, 1));
    // Every element is right-handed with the cell volume 0.5 x 0.5 x 0.5 m.
    for (int e = 0; e < mesh.GetElementCount(); ++e)
        CHECK(BoxVolume(mesh.GetCorners(e)) == Approx(0.125).epsilon(1.0e-14));
}

TEST_CASE("HexMesh refuses bad settings with a clear error", "[fem][hex]")
{
    SECTION("zero cells")
    {
        HexMeshSettings settings = Box();
        settings.mCellCount = {4, 0, 1};
        Result<HexMesh> mesh = HexMesh::Create(settings);
        REQUIRE(mesh.HasError());
        CHECK(mesh.GetError().mCode == EError::InvalidArgument);
        CHECK(mesh.GetError().mMessage.find("mCellCount.y = 0") != std::string::npos);
    }
    SECTION("too many cells")
    {
        HexMeshSettings settings = Box();
        settings.mCellCount = {2000, 1, 1};
        CHECK(HexMesh::Create(settings).GetError().mCode == EError::InvalidArgument);
        settings.mCellCount = {1000, 1000, 1};
        const Result<HexMesh> mesh = HexMesh::Create(settings);
        CHECK(mesh.GetError().mCode == EError::InvalidArgument);
        CHECK(mesh.GetError().mMessage.find("1000000 cells") != std::string::npos);
    }
    SECTION("zero or negative size")
    {
        HexMeshSettings settings = Box();
        settings.mSize.z() = 0.0;
        CHECK(HexMesh::Create(settings).GetError().mCode == EError::DegenerateGeometry);
        settings.mSize.z() = -1.0;
        const Result<HexMesh> mesh = HexMesh::Create(settings);
        CHECK(mesh.GetError().mCode == EError::DegenerateGeometry);
        CHECK(mesh.GetError().mMessage.find("mSize.z = -1") != std::string::npos);
    }
    SECTION("NaN and Inf")
    {
        HexMeshSettings settings = Box();
        settings.mSize.x() = std::numeric_limits<double>::quiet_NaN();
        CHECK(HexMesh::Create(settings).GetError().mCode == EError::NonFinite);
        settings = Box();
        settings.mOrigin.y() = std::numeric_limits<double>::infinity();
        CHECK(HexMesh::Create(settings).GetError().mCode == EError::NonFinite);
    }
}

TEST_CASE("HexMesh refuses bad explicit arrays", "[fem][hex]")
{
    const HexMesh box = HexMesh::Create(Box()).Get();
    HexNodeMatrix nodes = box.GetNodes();
    HexElementMatrix elements = box.GetElements();
    SECTION("a valid copy is accepted and unstructured")
    {
        const Result<HexMesh> mesh = HexMesh::Create(nodes, elements);
        REQUIRE(mesh.IsValid());
        CHECK_FALSE(mesh.Get().IsStructured());
        CHECK(mesh.Get().GetNodes() == nodes);
    }
    SECTION("an index out of range")
    {
        elements(2, 5) = 30;
        const Result<HexMesh> mesh = HexMesh::Create(nodes, elements);
        CHECK(mesh.GetError().mCode == EError::OutOfRange);
        CHECK(mesh.GetError().mMessage.find("element 2 corner 5 names node 30") != std::string::npos);
    }
    SECTION("a repeated node")
    {
        elements(1, 6) = elements(1, 0);
        CHECK(HexMesh::Create(nodes, elements).GetError().mCode == EError::DegenerateGeometry);
    }
    SECTION("an inverted element (corner order mirrored)")
    {
        for (int c = 0; c < 4; ++c)
            std::swap(elements(3, c), elements(3, c + 4));
        const Result<HexMesh> mesh = HexMesh::Create(nodes, elements);
        CHECK(mesh.GetError().mCode == EError::DegenerateGeometry);
        CHECK(mesh.GetError().mMessage.find("element 3 is inverted") != std::string::npos);
    }
    SECTION("a flattened element")
    {
        // Move the top face of cell (3, 1, 0) down onto its bottom face.
        for (int i = 3; i <= 4; ++i)
            for (int j = 1; j <= 2; ++j)
                nodes(box.GetGridNodeIndex(i, j, 1), 2) = 2.0;
        CHECK(HexMesh::Create(nodes, elements).GetError().mCode == EError::DegenerateGeometry);
    }
    SECTION("NaN position and no elements")
    {
        nodes(7, 1) = std::numeric_limits<double>::quiet_NaN();
        CHECK(HexMesh::Create(nodes, elements).GetError().mCode == EError::NonFinite);
        CHECK(HexMesh::Create(box.GetNodes(), HexElementMatrix(0, 8)).GetError().mCode == EError::InvalidArgument);
    }
}

TEST_CASE("HexNodesInBox selects faces, bounds included", "[fem][hex]")
{
    const HexMesh mesh = HexMesh::Create(Box()).Get();
    // The face x = -0.5 holds 3 x 2 nodes; the edge x = 1.5, z = 2.5 holds 3.
    const std::vector<int> face = HexNodesInBox(mesh, Vec3(-0.5, -10.0, -10.0), Vec3(-0.5, 10.0, 10.0));
    CHECK(face == std::vector<int>{0, 5, 10, 15, 20, 25});
    CHECK(HexNodesInBox(mesh, Vec3(1.5, -10.0, 2.5), Vec3(10.0, 10.0, 2.5)).size() == 3);
    CHECK(HexNodesInBox(mesh, Vec3(1.0, 0.0, 0.0), Vec3(0.0, 10.0, 10.0)).empty());
    CHECK(HexNodesInBox(mesh, Vec3::Constant(std::numeric_limits<double>::quiet_NaN()), Vec3::Constant(10.0)).empty());
}
