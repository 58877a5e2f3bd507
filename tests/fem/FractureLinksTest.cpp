// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/FractureLinks.h>
#include <crumple/fem/TetGrid.h>

#include <catch2/catch.hpp>

#include <cmath>

using namespace crumple;
using namespace crumple::fem;

namespace
{

TetMesh Grid(int inX, int inY, int inZ, ECubeSplit inSplit = ECubeSplit::Five)
{
    TetGridSettings grid;
    grid.mSize = Vec3(inX, inY, inZ);
    grid.mCellCount = {inX, inY, inZ};
    grid.mSplit = inSplit;
    return TetGrid(grid).Get();
}

} // namespace

TEST_CASE("FractureLinks joins face-sharing cubes, with the shared nodes and the A-to-B normal", "[fem]")
{
    const ECubeSplit split = GENERATE(ECubeSplit::Five, ECubeSplit::Six);
    const TetMesh mesh = Grid(2, 1, 1, split);
    const FractureLinks links = BuildFractureLinks(mesh);
    REQUIRE(links.GetGroupCount() == 2);
    REQUIRE(links.GetLinkCount() == 1);
    CHECK(links.mLinkGroups[0] == std::array<int, 2>{0, 1});
    CHECK((links.mLinkRestNormals[0] - Vec3::UnitX()).norm() < 1e-15);
    CHECK(links.mLinkFaceOffsets[1] == 2); // a square face: two triangles
    const std::vector<int> shared(links.mLinkNodes.begin(), links.mLinkNodes.end());
    CHECK(shared == std::vector<int>{TetGridNode({2, 1, 1}, 1, 0, 0), TetGridNode({2, 1, 1}, 1, 1, 0),
                                     TetGridNode({2, 1, 1}, 1, 0, 1), TetGridNode({2, 1, 1}, 1, 1, 1)});
    // Each face triangle belongs to group A and its normal points to B.
    for (const FractureLinkFace& face : links.mLinkFaces)
    {
        CHECK(links.mGroupOfElement[face.mElement] == 0);
        const TetIndices& nodes = mesh.GetTets()[face.mElement];
        const Vec3& x0 = mesh.GetRestPositions()[nodes[face.mCorners[0]]];
        const Vec3 normal = (mesh.GetRestPositions()[nodes[face.mCorners[1]]] - x0)
                                .cross(mesh.GetRestPositions()[nodes[face.mCorners[2]]] - x0);
        CHECK(normal.dot(Vec3::UnitX()) > 0.0);
    }
}

TEST_CASE("FractureLinks of a 3x3x3 block: one link per interior cube face, nodes see their groups", "[fem]")
{
    const TetMesh mesh = Grid(3, 3, 3);
    const FractureLinks links = BuildFractureLinks(mesh);
    CHECK(links.GetGroupCount() == 27);
    CHECK(links.GetLinkCount() == 3 * 2 * 3 * 3); // 2 interior planes of 9 faces along each axis
    for (int link = 0; link < links.GetLinkCount(); ++link)
    {
        // Axis-aligned unit normals and four shared nodes.
        const Vec3& n = links.mLinkRestNormals[link];
        CHECK(std::abs(n.cwiseAbs().maxCoeff() - 1.0) < 1e-15);
        CHECK(links.mLinkNodeOffsets[link + 1] - links.mLinkNodeOffsets[link] == 4);
        CHECK(links.mLinkGroups[link][0] < links.mLinkGroups[link][1]);
    }
    // The centre node (1,1,1) touches 8 cubes and 12 links; a corner node 1 cube and no link.
    const int centre = TetGridNode({3, 3, 3}, 1, 1, 1);
    CHECK(links.mNodeGroupOffsets[centre + 1] - links.mNodeGroupOffsets[centre] == 8);
    CHECK(links.mNodeLinkOffsets[centre + 1] - links.mNodeLinkOffsets[centre] == 12);
    CHECK(links.mNodeLinkOffsets[1] - links.mNodeLinkOffsets[0] == 0);
}

TEST_CASE("FractureLinks with one group per tetrahedron links the faces inside a 5-tet cube", "[fem]")
{
    const TetMesh cube = Grid(1, 1, 1);
    std::vector<int> groups{0, 1, 2, 3, 4};
    const TetMesh split = TetMesh::Create(cube.GetRestPositions(), cube.GetTets(), groups).Get();
    const FractureLinks links = BuildFractureLinks(split);
    CHECK(links.GetLinkCount() == 4); // the central tetrahedron against each corner one
    for (int link = 0; link < 4; ++link)
        CHECK(links.mLinkNodeOffsets[link + 1] - links.mLinkNodeOffsets[link] == 3);
}
