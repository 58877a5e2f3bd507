// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/FractureTopology.h>
#include <crumple/fem/TetFragment.h>
#include <crumple/fem/TetGrid.h>

#include <catch2/catch.hpp>

using namespace crumple;
using namespace crumple::fem;

namespace
{

constexpr double cDensity = 600.0; // kg/m^3

struct Block
{
    TetMesh mMesh;
    FractureLinks mLinks;
    std::vector<double> mElementMasses;
};

Block MakeBlock(const Vec3& inSize, std::array<int, 3> inCells)
{
    TetGridSettings grid;
    grid.mOrigin = Vec3(0.3, -0.2, 1.0);
    grid.mSize = inSize;
    grid.mCellCount = inCells;
    Block block{TetGrid(grid).Get(), {}, {}};
    block.mLinks = BuildFractureLinks(block.mMesh);
    for (int tet = 0; tet < block.mMesh.GetTetCount(); ++tet)
        block.mElementMasses.push_back(cDensity * block.mMesh.GetRestVolume(tet));
    return block;
}

// Inertia of a solid box about its centre (kg m^2).
Mat3 BoxInertia(double inMass, const Vec3& inSize)
{
    const Vec3 s = inSize.cwiseProduct(inSize);
    return (inMass / 12.0 * Vec3(s.y() + s.z(), s.x() + s.z(), s.x() + s.y())).asDiagonal();
}

} // namespace

TEST_CASE("TetFragments of an intact box: one piece with the box's exact mass, centre and inertia", "[fem]")
{
    const Vec3 size(2.0, 0.5, 1.0);
    const Block block = MakeBlock(size, {4, 1, 2});
    std::vector<double> inverse_masses(block.mMesh.GetNodeCount(), 1.0);
    const std::vector<TetFragment> fragments =
        TetFragments(block.mLinks, block.mMesh.GetTets(),
                     block.mElementMasses, block.mMesh.GetRestPositions(), inverse_masses);
    REQUIRE(fragments.size() == 1);
    const double mass = cDensity * size.prod();
    CHECK(fragments[0].mMass == Approx(mass).epsilon(1e-13));
    CHECK((fragments[0].mCenterOfMass - (Vec3(0.3, -0.2, 1.0) + 0.5 * size)).norm() < 1e-13);
    CHECK((fragments[0].mInertia - BoxInertia(mass, size)).norm() < 1e-11 * BoxInertia(mass, size).norm());
    CHECK(static_cast<int>(fragments[0].mNodes.size()) == block.mMesh.GetNodeCount());
    CHECK_FALSE(fragments[0].mAnchored);
}

TEST_CASE("TetFragments of a box broken everywhere: one cube each, anchored where a node is fixed", "[fem]")
{
    const Vec3 size(2.0, 0.5, 1.0);
    const Block block = MakeBlock(size, {4, 1, 2});
    const std::vector<std::uint8_t> broken(block.mLinks.GetLinkCount(), 1);
    const FractureConnectivity connectivity = FractureTopology(block.mMesh, block.mLinks, broken).Get();
    std::vector<Vec3> positions;
    for (int origin : connectivity.mNodeOrigin)
        positions.push_back(block.mMesh.GetRestPositions()[origin]);
    std::vector<double> inverse_masses(positions.size(), 1.0);
    inverse_masses[0] = 0.0; // node 0 stays with cube 0

    const std::vector<TetFragment> fragments = TetFragments(block.mLinks, connectivity.mElementNodes,
                                                            block.mElementMasses, positions, inverse_masses);
    REQUIRE(fragments.size() == 8);
    const Vec3 cell(0.5, 0.5, 0.5);
    const double mass = cDensity * cell.prod();
    for (std::size_t index = 0; index < fragments.size(); ++index)
    {
        const TetFragment& fragment = fragments[index];
        CHECK(fragment.mGroups == std::vector<int>{static_cast<int>(index)});
        CHECK(fragment.mElements.size() == 5u);
        CHECK(fragment.mNodes.size() == 8u);
        CHECK(fragment.mMass == Approx(mass).epsilon(1e-13));
        CHECK((fragment.mInertia - BoxInertia(mass, cell)).norm() < 1e-11 * BoxInertia(mass, cell).norm());
        CHECK(fragment.mAnchored == (index == 0));
    }
}

TEST_CASE("TetFragments follows the current positions: a rotated piece has the rotated inertia", "[fem]")
{
    const Vec3 size(1.0, 0.2, 0.4);
    const Block block = MakeBlock(size, {2, 1, 1});
    const Mat3 rotation = Eigen::AngleAxisd(0.7, Vec3(1.0, 2.0, -0.5).normalized()).toRotationMatrix();
    const Vec3 shift(5.0, -1.0, 2.0);
    std::vector<Vec3> positions;
    for (const Vec3& rest : block.mMesh.GetRestPositions())
        positions.push_back(rotation * rest + shift);
    const std::vector<TetFragment> fragments =
        TetFragments(block.mLinks, block.mMesh.GetTets(), block.mElementMasses,
                     positions, std::vector<double>(positions.size(), 1.0));
    REQUIRE(fragments.size() == 1);
    const double mass = cDensity * size.prod();
    const Mat3 expected = rotation * BoxInertia(mass, size) * rotation.transpose();
    CHECK((fragments[0].mInertia - expected).norm() < 1e-11 * expected.norm());
    CHECK((fragments[0].mCenterOfMass - (rotation * (Vec3(0.3, -0.2, 1.0) + 0.5 * size) + shift)).norm() < 1e-12);
}

TEST_CASE("TetFragments keeps a group whose elements share no node one piece, with all their nodes", "[fem]")
{
    // Two separate tetrahedra that a mesh put in one group (nothing requires a group to be connected), and a
    // third on its own; a node of the second tetrahedron is fixed. The group is one piece: every node of both
    // its elements, anchored through the second.
    std::vector<Vec3> positions;
    std::vector<TetIndices> tets;
    for (int t = 0; t < 3; ++t)
    {
        const Vec3 origin(2.0 * t, 0.0, 0.0);
        for (const Vec3& corner : {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)})
            positions.push_back(origin + corner);
        tets.push_back({4 * t, 4 * t + 1, 4 * t + 2, 4 * t + 3});
    }
    const TetMesh mesh = TetMesh::Create(positions, tets, {0, 1, 0}).Get();
    const FractureLinks links = BuildFractureLinks(mesh);
    std::vector<double> inverse_masses(positions.size(), 1.0);
    inverse_masses[9] = 0.0; // a node of the third tetrahedron, which is in group 0 with the first
    const std::vector<double> masses{1.0, 1.0, 1.0};
    const std::vector<TetFragment> pieces = TetFragments(links, tets, masses, positions, inverse_masses);
    REQUIRE(pieces.size() == 2u);
    CHECK(pieces[0].mElements == std::vector<int>{0, 2});
    CHECK(pieces[0].mNodes == std::vector<int>{0, 1, 2, 3, 8, 9, 10, 11});
    CHECK(pieces[0].mAnchored);
    CHECK(pieces[0].mMass == 2.0);
    CHECK(pieces[1].mElements == std::vector<int>{1});
    CHECK(pieces[1].mNodes == std::vector<int>{4, 5, 6, 7});
    CHECK_FALSE(pieces[1].mAnchored);
}
