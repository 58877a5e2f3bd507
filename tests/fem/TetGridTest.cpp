// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/LumpedNodeMass.h>
#include <crumple/fem/TetGrid.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <limits>
#include <map>
#include <numeric>

using namespace crumple;
using namespace crumple::fem;

namespace
{

// How many elements use each triangular face (sorted node triple).
std::map<std::array<int, 3>, int> FaceUse(const TetMesh& inMesh)
{
    std::map<std::array<int, 3>, int> use;
    for (const TetIndices& tet : inMesh.GetTets())
        for (int skip = 0; skip < 4; ++skip)
        {
            std::array<int, 3> face{};
            int count = 0;
            for (int corner = 0; corner < 4; ++corner)
                if (corner != skip)
                    face[count++] = tet[corner];
            std::sort(face.begin(), face.end());
            ++use[face];
        }
    return use;
}

// Checks counts, orientation, volume and conformity of a grid mesh.
void CheckGrid(const TetGridSettings& inSettings, int inPerCell)
{
    Result<TetMesh> result = TetGrid(inSettings);
    REQUIRE(result.IsValid());
    const TetMesh& mesh = result.Get();
    const auto& n = inSettings.mCellCount;
    const int cells = n[0] * n[1] * n[2];
    CHECK(mesh.GetNodeCount() == (n[0] + 1) * (n[1] + 1) * (n[2] + 1));
    CHECK(mesh.GetTetCount() == inPerCell * cells);

    // Positive volumes summing to the box; each cell's elements are consecutive and carry its group id.
    const double box = inSettings.mSize.prod();
    const double cell = box / cells;
    for (int tet = 0; tet < mesh.GetTetCount(); ++tet)
    {
        CHECK(mesh.GetRestVolume(tet) > 0.0);
        CHECK(mesh.GetGroups()[tet] == tet / inPerCell);
    }
    CHECK(mesh.GetTotalVolume() == Approx(box).epsilon(1e-12));

    // Five-tet cells: one central element of a third of the cell, four corner ones of a sixth.
    if (inPerCell == 5)
        for (int tet = 0; tet < mesh.GetTetCount(); ++tet)
            CHECK(mesh.GetRestVolume(tet) == Approx(tet % 5 == 0 ? cell / 3.0 : cell / 6.0).epsilon(1e-12));

    // Conforming: every face is used once (boundary) or twice (interior), and the boundary has two triangles
    // per cell face on the box surface.
    int boundary = 0;
    for (const auto& [face, count] : FaceUse(mesh))
    {
        CHECK((count == 1 || count == 2));
        boundary += count == 1 ? 1 : 0;
    }
    CHECK(boundary == 4 * (n[0] * n[1] + n[1] * n[2] + n[2] * n[0]));
}

} // namespace

TEST_CASE("TetGrid cuts cells into five conforming tetrahedra", "[fem]")
{
    for (const std::array<int, 3> count : {std::array<int, 3>{1, 1, 1}, {3, 2, 2}, {4, 1, 3}})
    {
        TetGridSettings settings;
        settings.mOrigin = Vec3(-1.0, 2.0, 0.5);
        settings.mSize = Vec3(0.4, 0.2, 0.3);
        settings.mCellCount = count;
        CheckGrid(settings, 5);
    }

    // The central element of every cell sits on the nodes of even global parity i + j + k.
    TetGridSettings settings;
    settings.mCellCount = {3, 2, 2};
    const TetMesh mesh = TetGrid(settings).Get();
    for (int tet = 0; tet < mesh.GetTetCount(); tet += 5)
        for (int node : mesh.GetTets()[tet])
        {
            const int i = node % 4, j = (node / 4) % 3, k = node / 12;
            CHECK((i + j + k) % 2 == 0);
        }
}

TEST_CASE("TetGrid six-tet split conforms as well", "[fem]")
{
    TetGridSettings settings;
    settings.mSize = Vec3(1.0, 0.1, 0.1);
    settings.mCellCount = {5, 2, 3};
    settings.mSplit = ECubeSplit::Six;
    CheckGrid(settings, 6);
}

TEST_CASE("TetGrid refuses a box without extent or cells", "[fem]")
{
    TetGridSettings zero_size;
    zero_size.mSize = Vec3(1.0, 0.0, 1.0);
    TetGridSettings no_cells;
    no_cells.mCellCount = {2, 0, 2};
    TetGridSettings nan_origin;
    nan_origin.mOrigin.x() = std::numeric_limits<double>::quiet_NaN();
    TetGridSettings too_many;
    too_many.mCellCount = {1024, 1024, 1024};
    CHECK(TetGrid(zero_size).GetError().mMessage.find("mSize[1]") != std::string::npos);
    CHECK(TetGrid(no_cells).GetError().mMessage.find("mCellCount[1] = 0") != std::string::npos);
    CHECK(TetGrid(nan_origin).GetError().mCode == EError::NonFinite);
    CHECK(TetGrid(too_many).GetError().mMessage.find("more than") != std::string::npos);
}

TEST_CASE("LumpedNodeMass gives each corner a quarter of every element's mass", "[fem]")
{
    // One unit cube, five tets: the four even corners carry the central element (1/3) and three corner
    // elements (1/6 each): 1/12 + 3/24 = 5/24 of the mass; the four odd corners only their own corner
    // element: 1/24.
    TetGridSettings settings;
    const TetMesh cube = TetGrid(settings).Get();
    const double density = 7850.0;
    const std::vector<double> masses = LumpedNodeMass(cube, density).Get();
    for (int node = 0; node < 8; ++node)
    {
        const int parity = (node & 1) + ((node >> 1) & 1) + ((node >> 2) & 1);
        CHECK(masses[node] == Approx(density * (parity % 2 == 0 ? 5.0 / 24.0 : 1.0 / 24.0)).epsilon(1e-14));
    }

    // A larger grid: the masses add up to rho V.
    settings.mSize = Vec3(1.0, 0.1, 0.1);
    settings.mCellCount = {20, 2, 2};
    const TetMesh beam = TetGrid(settings).Get();
    const std::vector<double> beam_masses = LumpedNodeMass(beam, density).Get();
    CHECK(std::accumulate(beam_masses.begin(), beam_masses.end(), 0.0) ==
          Approx(density * 0.01).epsilon(1e-12));
    CHECK(*std::min_element(beam_masses.begin(), beam_masses.end()) > 0.0);
}
