// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// The public fracture and mass building blocks refuse arrays that do not fit each other (they read them by
// index) and change nothing when they do: LumpedNodeMass, ValidateFractureLinks, FractureTopology,
// GroupPrincipalStress, OpenCracks, BarycentricSearch.
#include <crumple/fem/BarycentricSearch.h>
#include <crumple/fem/FractureTopology.h>
#include <crumple/fem/LumpedNodeMass.h>
#include <crumple/fem/OpenCracks.h>
#include <crumple/fem/TetElementRest.h>
#include <crumple/fem/TetGrid.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

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

TEST_CASE("LumpedNodeMass refuses sizes that do not fit, nodes out of range and a bad density", "[fem]")
{
    const TetMesh mesh = Grid(2, 1, 1);
    const std::vector<TetElementRest> rest = TetRestData(mesh);
    REQUIRE(LumpedNodeMass(mesh.GetTets(), rest, mesh.GetNodeCount(), 1000.0).IsValid());
    CHECK(LumpedNodeMass(mesh.GetTets(), std::span(rest).first(rest.size() - 1), mesh.GetNodeCount(), 1000.0).HasError());
    CHECK(LumpedNodeMass(mesh.GetTets(), rest, mesh.GetNodeCount() - 1, 1000.0).GetError().mCode == EError::OutOfRange);
    CHECK(LumpedNodeMass(mesh.GetTets(), rest, -1, 1000.0).HasError());
    for (double density : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
        CHECK(LumpedNodeMass(mesh, density).HasError());
    std::vector<TetElementRest> flat = rest;
    flat[3].mRestVolume = 0.0;
    CHECK(LumpedNodeMass(mesh.GetTets(), flat, mesh.GetNodeCount(), 1000.0).HasError());
}

TEST_CASE("FractureTopology refuses another mesh's links, tampered links and a wrong number of flags", "[fem]")
{
    const TetMesh mesh = Grid(2, 2, 1);
    const FractureLinks links = BuildFractureLinks(mesh);
    const std::vector<std::uint8_t> none(static_cast<std::size_t>(links.GetLinkCount()), 0);
    REQUIRE(ValidateFractureLinks(links, mesh.GetTetCount(), mesh.GetNodeCount()).IsValid());
    REQUIRE(FractureTopology(mesh, links, none).IsValid());
    // One flag short.
    CHECK(FractureTopology(mesh, links, std::span(none).first(none.size() - 1)).HasError());
    // The links of a larger mesh.
    const FractureLinks larger = BuildFractureLinks(Grid(3, 2, 1));
    CHECK(ValidateFractureLinks(larger, mesh.GetTetCount(), mesh.GetNodeCount()).HasError());
    CHECK(FractureTopology(mesh, larger, std::vector<std::uint8_t>(static_cast<std::size_t>(larger.GetLinkCount()), 0)).HasError());
    // Indices past their arrays.
    FractureLinks past = links;
    past.mNodeLinks.back() = links.GetLinkCount();
    CHECK(ValidateFractureLinks(past, mesh.GetTetCount(), mesh.GetNodeCount()).HasError());
    CHECK(FractureTopology(mesh, past, none).HasError());
    past = links;
    past.mLinkFaces.back().mCorners[2] = 4;
    CHECK(ValidateFractureLinks(past, mesh.GetTetCount(), mesh.GetNodeCount()).HasError());
    // Not ascending: refused by the check.
    FractureLinks unsorted = links;
    const int node = links.mLinkNodes.front();
    const int first = links.mNodeGroupOffsets[static_cast<std::size_t>(node)];
    const int count = links.mNodeGroupOffsets[static_cast<std::size_t>(node) + 1] - first;
    REQUIRE(count >= 2);
    std::swap(unsorted.mNodeGroups[static_cast<std::size_t>(first)], unsorted.mNodeGroups[static_cast<std::size_t>(first) + 1]);
    CHECK(ValidateFractureLinks(unsorted, mesh.GetTetCount(), mesh.GetNodeCount()).HasError());
    // In range and ascending but not this mesh's: a node shared by groups 0 and 1 is said to touch the last
    // groups instead, so a link through it finds its groups missing.
    FractureLinks foreign = links;
    REQUIRE(links.mNodeGroups[static_cast<std::size_t>(first)] < links.GetGroupCount() - count);
    for (int entry = 0; entry < count; ++entry)
        foreign.mNodeGroups[static_cast<std::size_t>(first + entry)] = links.GetGroupCount() - count + entry;
    REQUIRE(ValidateFractureLinks(foreign, mesh.GetTetCount(), mesh.GetNodeCount()).IsValid());
    const Result<FractureConnectivity> refused = FractureTopology(mesh, foreign, none);
    REQUIRE(refused.HasError());
    CHECK(refused.GetError().mMessage.find("not this mesh's") != std::string::npos);
}

TEST_CASE("GroupPrincipalStress and OpenCracks refuse inputs that do not fit the links, and break nothing", "[fem]")
{
    const TetMesh mesh = Grid(2, 1, 1);
    const FractureLinks links = BuildFractureLinks(mesh);
    const std::vector<TetElementRest> rest = TetRestData(mesh);
    // Tension along x, far above the strength: every link would open.
    const std::vector<Mat3> stress(rest.size(), Vec3(1.0e9, 0.0, 0.0).asDiagonal());
    std::vector<PrincipalStress> principal(static_cast<std::size_t>(links.GetGroupCount()));
    REQUIRE(GroupPrincipalStress(links, stress, rest, principal).IsValid());
    std::vector<PrincipalStress> short_out(principal.size() - 1);
    CHECK(GroupPrincipalStress(links, stress, rest, short_out).HasError());
    CHECK(GroupPrincipalStress(links, std::span(stress).first(stress.size() - 1), std::span(rest).first(rest.size() - 1), principal).HasError());

    const std::vector<Vec3>& positions = mesh.GetRestPositions();
    std::vector<std::uint8_t> broken(static_cast<std::size_t>(links.GetLinkCount()), 0);
    // Too few stresses, too few flags, a node out of range: refused, nothing broken.
    CHECK(OpenCracks(links, std::span(principal).first(principal.size() - 1), mesh.GetTets(), positions, 1.0e6,
                     EFractureMode::CrackPlane, broken).HasError());
    CHECK(OpenCracks(links, principal, mesh.GetTets(), positions, 1.0e6, EFractureMode::CrackPlane,
                     std::span(broken).first(broken.size() - 1)).HasError());
    std::vector<TetIndices> elements = mesh.GetTets();
    elements.back()[3] = static_cast<int>(positions.size());
    const Result<int> out_of_range = OpenCracks(links, principal, elements, positions, 1.0e6, EFractureMode::CrackPlane, broken);
    REQUIRE(out_of_range.HasError());
    CHECK(out_of_range.GetError().mCode == EError::OutOfRange);
    CHECK(std::all_of(broken.begin(), broken.end(), [](std::uint8_t inFlag) { return inFlag == 0; }));
    // The same inputs that fit break the link.
    const Result<int> opened = OpenCracks(links, principal, mesh.GetTets(), positions, 1.0e6, EFractureMode::CrackPlane, broken);
    REQUIRE(opened.IsValid());
    CHECK(opened.Get() == links.GetLinkCount());
}

TEST_CASE("BarycentricSearch refuses nodes out of range, an element out of range never wins", "[fem]")
{
    const TetMesh mesh = Grid(1, 1, 1);
    std::vector<TetIndices> elements = mesh.GetTets();
    REQUIRE(BarycentricSearch::Create(elements, mesh.GetRestPositions()).IsValid());
    elements[0][1] = -1;
    CHECK(BarycentricSearch::Create(elements, mesh.GetRestPositions()).GetError().mCode == EError::OutOfRange);

    const BarycentricSearch search = BarycentricSearch::Create(mesh.GetTets(), mesh.GetRestPositions()).Get();
    const Vec3 centre(0.5, 0.5, 0.5);
    CHECK(std::isnan(search.Weights(mesh.GetTetCount(), centre)[0]));
    CHECK(std::isnan(search.Weights(-1, centre)[0]));
    const std::vector<int> outside{-1, mesh.GetTetCount(), 1 << 30};
    CHECK(search.FindBest(outside, centre).mElement == -1);
    const std::vector<int> mixed{mesh.GetTetCount(), 0};
    CHECK(search.FindBest(mixed, centre).mElement == 0);
}
