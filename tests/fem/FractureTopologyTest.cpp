// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/FractureTopology.h>
#include <crumple/fem/TetGrid.h>

#include <catch2/catch.hpp>

#include <set>

using namespace crumple;
using namespace crumple::fem;

namespace
{

TetMesh Grid(int inX, int inY, int inZ)
{
    TetGridSettings grid;
    grid.mSize = Vec3(inX, inY, inZ);
    grid.mCellCount = {inX, inY, inZ};
    return TetGrid(grid).Get();
}

} // namespace

TEST_CASE("FractureTopology without a broken link is the mesh itself", "[fem]")
{
    const TetMesh mesh = Grid(3, 2, 2);
    const FractureLinks links = BuildFractureLinks(mesh);
    const FractureConnectivity result = FractureTopology(mesh, links, std::vector<std::uint8_t>(links.GetLinkCount(), 0)).Get();
    CHECK(result.mElementNodes == mesh.GetTets());
    CHECK(static_cast<int>(result.mNodeOrigin.size()) == mesh.GetNodeCount());
}

TEST_CASE("FractureTopology duplicates the nodes of a broken face for the higher group", "[fem]")
{
    const TetMesh mesh = Grid(2, 1, 1);
    const FractureLinks links = BuildFractureLinks(mesh);
    const FractureConnectivity result = FractureTopology(mesh, links, std::vector<std::uint8_t>{1}).Get();
    REQUIRE(static_cast<int>(result.mNodeOrigin.size()) == mesh.GetNodeCount() + 4);
    // Cube 0 keeps the original nodes; cube 1 uses the copies at the shared face, and the copies come from
    // exactly those four nodes.
    std::set<int> cube0, cube1;
    for (int tet = 0; tet < mesh.GetTetCount(); ++tet)
        for (int node : result.mElementNodes[tet])
            (links.mGroupOfElement[tet] == 0 ? cube0 : cube1).insert(node);
    for (int node : cube0)
        CHECK(node < mesh.GetNodeCount());
    int shared = 0;
    for (int node : cube1)
        shared += cube0.count(node) != 0 ? 1 : 0;
    CHECK(shared == 0);
    for (int copy = mesh.GetNodeCount(); copy < mesh.GetNodeCount() + 4; ++copy)
        CHECK(result.mNodeOrigin[copy] == links.mLinkNodes[copy - mesh.GetNodeCount()]);
}

TEST_CASE("FractureTopology keeps nodes joined around an edge while any unbroken link joins them", "[fem]")
{
    // 2x2x1 cubes around the vertical centre edge. Breaking the single link between cubes 0 and 1 leaves
    // them joined at the centre edge through cubes 2 and 3, so no node is duplicated there; breaking both
    // links of cube 0 detaches it and duplicates the nodes it shared.
    const TetMesh mesh = Grid(2, 2, 1);
    const FractureLinks links = BuildFractureLinks(mesh);
    REQUIRE(links.GetLinkCount() == 4);
    std::vector<std::uint8_t> broken(4, 0);
    int link01 = -1;
    for (int link = 0; link < 4; ++link)
        if (links.mLinkGroups[link] == std::array<int, 2>{0, 1})
            link01 = link;
    REQUIRE(link01 >= 0);
    broken[link01] = 1;
    // The face between 0 and 1 has 4 nodes: 2 on the centre edge (still joined around it) and 2 on the
    // outer edge (only cubes 0 and 1 meet there): those 2 are duplicated.
    CHECK(FractureTopology(mesh, links, broken).Get().mNodeOrigin.size() == static_cast<std::size_t>(mesh.GetNodeCount() + 2));

    for (int link = 0; link < 4; ++link)
        if (links.mLinkGroups[link][0] == 0)
            broken[link] = 1;
    // Cube 0 shares 6 nodes with the others (two faces of 4 with the centre edge's 2 in common).
    CHECK(FractureTopology(mesh, links, broken).Get().mNodeOrigin.size() == static_cast<std::size_t>(mesh.GetNodeCount() + 6));
}

TEST_CASE("FractureTopology of an all-broken block gives every cube its own eight corners", "[fem]")
{
    const TetMesh mesh = Grid(3, 3, 3);
    const FractureLinks links = BuildFractureLinks(mesh);
    const FractureConnectivity result = FractureTopology(mesh, links, std::vector<std::uint8_t>(links.GetLinkCount(), 1)).Get();
    CHECK(result.mNodeOrigin.size() == 27u * 8u);
    // Pure function of the broken set: the same input gives the same numbering.
    CHECK(FractureTopology(mesh, links, std::vector<std::uint8_t>(links.GetLinkCount(), 1)).Get().mElementNodes ==
          result.mElementNodes);
}

TEST_CASE("FractureTopology separates groups that touch only along an edge (no face to hold them)", "[fem]")
{
    // A 2 x 2 x 1 lattice keeping the diagonal cells 0 and 3: they share the two nodes of the centre edge.
    TetGridSettings grid;
    grid.mSize = Vec3(2.0, 2.0, 1.0);
    grid.mCellCount = {2, 2, 1};
    const TetMesh mesh = TetGridCells(grid, std::vector<std::uint8_t>{1, 0, 0, 1}).Get();
    REQUIRE(mesh.GetNodeCount() == 14);
    const FractureLinks links = BuildFractureLinks(mesh);
    CHECK(links.GetLinkCount() == 0);
    CHECK(FractureTopology(mesh, links, {}).Get().mNodeOrigin.size() == 16u);
}
