// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/SurfaceVolume.h>
#include <crumple/fem/TetBoundary.h>
#include <crumple/fem/TetGrid.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <map>

using namespace crumple;
using namespace crumple::fem;

namespace
{

// How often each directed edge (a, b) occurs in the triangles.
std::map<std::pair<int, int>, int> DirectedEdges(const std::vector<TriangleIndices>& inTriangles)
{
    std::map<std::pair<int, int>, int> use;
    for (const TriangleIndices& triangle : inTriangles)
        for (int corner = 0; corner < 3; ++corner)
            ++use[{triangle[corner], triangle[(corner + 1) % 3]}];
    return use;
}

// Sorted node triples, sorted: the boundary as a multiset of faces, ignoring order and winding.
std::vector<std::array<int, 3>> SortedFaces(const std::vector<TriangleIndices>& inTriangles)
{
    std::vector<std::array<int, 3>> faces;
    for (TriangleIndices triangle : inTriangles)
    {
        std::sort(triangle.begin(), triangle.end());
        faces.push_back(triangle);
    }
    std::sort(faces.begin(), faces.end());
    return faces;
}

// Boundary of a box: the count, closed with consistent outward winding, on the box faces, enclosing its
// volume.
void CheckBox(const TetGridSettings& inSettings)
{
    const TetMesh mesh = TetGrid(inSettings).Get();
    const std::vector<TriangleIndices> boundary = TetBoundary(mesh.GetTets());
    const auto& n = inSettings.mCellCount;
    CHECK(boundary.size() == static_cast<std::size_t>(4 * (n[0] * n[1] + n[1] * n[2] + n[2] * n[0])));

    // Closed and consistently wound: each directed edge once, and its reverse once.
    const std::map<std::pair<int, int>, int> edges = DirectedEdges(boundary);
    for (const auto& [edge, count] : edges)
    {
        CHECK(count == 1);
        CHECK(edges.count({edge.second, edge.first}) == 1);
    }

    // Every triangle lies in one face plane of the box.
    const Vec3 lo = inSettings.mOrigin;
    const Vec3 hi = inSettings.mOrigin + inSettings.mSize;
    const std::vector<Vec3>& x = mesh.GetRestPositions();
    for (const TriangleIndices& triangle : boundary)
    {
        bool on_face = false;
        for (int axis = 0; axis < 3; ++axis)
            for (double plane : {lo[axis], hi[axis]})
                on_face = on_face || (x[triangle[0]][axis] == plane && x[triangle[1]][axis] == plane &&
                                      x[triangle[2]][axis] == plane);
        CHECK(on_face);
    }

    // Outward: the divergence theorem gives the box volume.
    CHECK(SurfaceVolume(x, boundary) == Approx(inSettings.mSize.prod()).epsilon(1e-12));

    // Deterministic.
    CHECK(TetBoundary(mesh.GetTets()) == boundary);
}

} // namespace

TEST_CASE("TetBoundary of a box is its closed, outward surface, two triangles per cell face", "[fem]")
{
    for (const ECubeSplit split : {ECubeSplit::Five, ECubeSplit::Six})
        for (const std::array<int, 3> count : {std::array<int, 3>{1, 1, 1}, {3, 2, 2}, {4, 1, 3}, {2, 5, 1}})
        {
            TetGridSettings settings;
            settings.mOrigin = Vec3(-0.3, 1.25, 0.7);
            settings.mSize = Vec3(0.8, 0.35, 1.9);
            settings.mCellCount = count;
            settings.mSplit = split;
            INFO("split " << static_cast<int>(split) << ", cells " << count[0] << " x " << count[1] << " x "
                          << count[2]);
            CheckBox(settings);
        }
}

TEST_CASE("TetBoundary of one tetrahedron lists its faces in the documented order", "[fem]")
{
    const std::vector<TetIndices> tets = {{7, 3, 9, 4}};
    const std::vector<TriangleIndices> expected = {{3, 9, 4}, {7, 4, 9}, {7, 3, 4}, {7, 9, 3}};
    CHECK(TetBoundary(tets) == expected);
    CHECK(TetBoundary(std::span<const TetIndices>()).empty());

    // Two elements sharing a face: that face disappears, the other six stay in element order.
    const std::vector<TetIndices> pair = {{0, 1, 2, 3}, {0, 2, 1, 4}};
    const std::vector<TriangleIndices> pair_expected = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3},
                                                        {2, 1, 4}, {0, 4, 1}, {0, 2, 4}};
    CHECK(TetBoundary(pair) == pair_expected);
}

TEST_CASE("TetBoundary shows the crack faces when an element corner is remapped to a copied node", "[fem]")
{
    // One five-tet cube: element 0 is the central tetrahedron, all its faces interior.
    TetGridSettings settings;
    settings.mSplit = ECubeSplit::Five;
    const TetMesh mesh = TetGrid(settings).Get();
    std::vector<Vec3> positions = mesh.GetRestPositions();
    std::vector<TetIndices> tets = mesh.GetTets();
    const std::vector<TriangleIndices> before = TetBoundary(tets);
    REQUIRE(before.size() == 12);

    // Copy the central element's corner 0 and point only that element to the copy.
    const int original = tets[0][0];
    const int copy = static_cast<int>(positions.size());
    positions.push_back(positions[original]);
    tets[0][0] = copy;
    const std::vector<TriangleIndices> after = TetBoundary(tets);

    // Expected: the old boundary, plus the three faces of element 0 through the corner on both sides of the
    // crack (the neighbours' faces with the original node, element 0's with the copy).
    std::vector<TriangleIndices> expected = before;
    for (int face = 0; face < 4; ++face)
    {
        if (face == 0)
            continue; // the face opposite corner 0 does not contain it and stays interior
        TriangleIndices with_original{}, with_copy{};
        int count = 0;
        for (int corner = 0; corner < 4; ++corner)
            if (corner != face)
            {
                with_original[count] = corner == 0 ? original : tets[0][corner];
                with_copy[count] = tets[0][corner];
                ++count;
            }
        expected.push_back(with_original);
        expected.push_back(with_copy);
    }
    CHECK(after.size() == 18);
    CHECK(SortedFaces(after) == SortedFaces(expected));

    // Still closed (every directed edge balanced by its reverse) and enclosing the same cube: the crack faces
    // cancel in pairs.
    const std::map<std::pair<int, int>, int> edges = DirectedEdges(after);
    for (const auto& [edge, count] : edges)
    {
        const auto reverse = edges.find({edge.second, edge.first});
        REQUIRE(reverse != edges.end());
        CHECK(reverse->second == count);
    }
    CHECK(SurfaceVolume(positions, after) == Approx(1.0).epsilon(1e-12));
    // The central element alone: its three crack faces plus its still-shared fourth face enclose a third of
    // the cube.
    std::vector<TriangleIndices> central;
    for (const TriangleIndices& triangle : after)
        if (std::find(triangle.begin(), triangle.end(), copy) != triangle.end())
            central.push_back(triangle);
    REQUIRE(central.size() == 3);
    central.push_back({tets[0][1], tets[0][2], tets[0][3]});
    CHECK(SurfaceVolume(positions, central) == Approx(1.0 / 3.0).epsilon(1e-12));
}
