// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/ffd/DropLooseSlivers.h>

#include <catch2/catch.hpp>

#include <array>
#include <cstdint>
#include <vector>

using namespace crumple;
using namespace crumple::ffd;

namespace
{

using Triangle = std::array<std::uint32_t, 3>;

// A closed tetrahedron: every edge shared by exactly two triangles.
TriangleMesh Tetrahedron()
{
    TriangleMesh mesh;
    mesh.mPositions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
    mesh.mTriangles = {Triangle{0, 2, 1}, Triangle{0, 1, 3}, Triangle{0, 3, 2}, Triangle{1, 2, 3}};
    return mesh;
}

} // namespace

TEST_CASE("DropLooseSlivers removes a zero-area triangle over an edge two others close, and nothing else",
          "[ffd]")
{
    TriangleMesh mesh = Tetrahedron();
    const std::vector<Triangle> closed = mesh.mTriangles;
    // intent: an exporter's sliver over edge 0-1: its midpoint (a new vertex) and the edge's ends
    mesh.mPositions.push_back(Vec3(0.5, 0.0, 0.0));
    mesh.mTriangles.insert(mesh.mTriangles.begin() + 2, Triangle{0, 4, 1});
    // and a triangle with two corners at one vertex over edge 2-3
    mesh.mTriangles.push_back(Triangle{2, 2, 3});
    const std::vector<Vec3> positions = mesh.mPositions;
    Result<std::size_t> removed = DropLooseSlivers(mesh);
    REQUIRE(removed);
    CHECK(removed.Get() == 2u);
    CHECK(mesh.mTriangles == closed); // the others, in their order
    CHECK(mesh.mPositions == positions);
    // A second pass finds nothing.
    CHECK(DropLooseSlivers(mesh).Get() == 0u);
}

TEST_CASE("DropLooseSlivers keeps a sliver the surface needs, a thin real triangle, and sees across seams",
          "[ffd]")
{
    SECTION("a zero-area triangle closing a T-junction stays: without it edge 0-1 would open")
    {
        // (0, 1, 2) above edge 0-1; below it, vertex 3 on the edge splits it: (0, 3, 4) and (3, 1, 4), and
        // the sliver (1, 0, 3) joins edge 0-1 to edges 0-3 and 3-1, each shared with one triangle.
        TriangleMesh mesh;
        mesh.mPositions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, 1, 0), Vec3(0.5, 0, 0), Vec3(0.5, -1, 0)};
        mesh.mTriangles = {Triangle{0, 1, 2}, Triangle{1, 0, 3}, Triangle{0, 3, 4}, Triangle{3, 1, 4}};
        const std::vector<Triangle> before = mesh.mTriangles;
        CHECK(DropLooseSlivers(mesh).Get() == 0u);
        CHECK(mesh.mTriangles == before);
    }
    SECTION("a thin triangle hanging off an edge but above the area ratio stays")
    {
        TriangleMesh mesh = Tetrahedron();
        mesh.mPositions.push_back(Vec3(0.5, 0.0, 1.0e-3)); // 1 mm high on a 1 m edge: 2 A / L^2 = 1e-3
        mesh.mTriangles.push_back(Triangle{0, 4, 1});
        CHECK(DropLooseSlivers(mesh).Get() == 0u);
        CHECK(mesh.mTriangles.size() == 5u);
    }
    SECTION("seams: edges meet across split vertices at the same positions")
    {
        // The T-junction of the first section with the sliver's corners split off at a seam (5, 6 twins of
        // 1, 0): it still closes edge 0-1 and stays; over an edge the surface closes it goes.
        TriangleMesh mesh;
        mesh.mPositions = {Vec3(0, 0, 0),    Vec3(1, 0, 0), Vec3(0.5, 1, 0), Vec3(0.5, 0, 0),
                           Vec3(0.5, -1, 0), Vec3(1, 0, 0), Vec3(0, 0, 0)};
        mesh.mTriangles = {Triangle{0, 1, 2}, Triangle{5, 6, 3}, Triangle{0, 3, 4}, Triangle{3, 1, 4}};
        CHECK(DropLooseSlivers(mesh).Get() == 0u);
        TriangleMesh closed = Tetrahedron();
        closed.mPositions.push_back(Vec3(0, 0, 0));   // 4: a twin of 0
        closed.mPositions.push_back(Vec3(1, 0, 0));   // 5: a twin of 1
        closed.mPositions.push_back(Vec3(0.5, 0, 0)); // 6: on edge 0-1
        closed.mTriangles.push_back(Triangle{4, 6, 5});
        CHECK(DropLooseSlivers(closed).Get() == 1u);
        CHECK(closed.mTriangles == Tetrahedron().mTriangles);
    }
}

TEST_CASE("DropLooseSlivers refuses a mesh ValidateTriangleMesh refuses, changing nothing", "[ffd]")
{
    TriangleMesh mesh = Tetrahedron();
    mesh.mTriangles.push_back(Triangle{0, 1, 9}); // no vertex 9
    const TriangleMesh before = mesh;
    CHECK(DropLooseSlivers(mesh).HasError());
    CHECK(mesh.mTriangles == before.mTriangles);
    CHECK(mesh.mPositions == before.mPositions);
}
