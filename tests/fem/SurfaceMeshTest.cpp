// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/SurfaceMesh.h>
#include <crumple/fem/SurfaceVolume.h>

#include <catch2/catch.hpp>

#include <limits>

using namespace crumple;
using namespace crumple::fem;

namespace
{

// The outward-wound surface of the box [inLo, inHi]: 8 corners, 12 triangles.
SurfaceMesh Box(const Vec3& inLo, const Vec3& inHi)
{
    SurfaceMesh mesh;
    for (int corner = 0; corner < 8; ++corner)
        mesh.mPositions.emplace_back((corner & 1) ? inHi.x() : inLo.x(), (corner & 2) ? inHi.y() : inLo.y(),
                                     (corner & 4) ? inHi.z() : inLo.z());
    mesh.mTriangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                       {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
    return mesh;
}

} // namespace

TEST_CASE("SurfaceVolume is the enclosed volume, signed by the winding", "[fem]")
{
    const SurfaceMesh box = Box(Vec3(-1.5, 2.0, 0.25), Vec3(0.5, 2.5, 3.25));
    REQUIRE(ValidateClosedSurface(box).IsValid());
    CHECK(SurfaceVolume(box.mPositions, box.mTriangles) == Approx(2.0 * 0.5 * 3.0).epsilon(1e-14));
    SurfaceMesh inside_out = box;
    for (TriangleIndices& triangle : inside_out.mTriangles)
        std::swap(triangle[1], triangle[2]);
    CHECK(SurfaceVolume(inside_out.mPositions, inside_out.mTriangles) == Approx(-3.0).epsilon(1e-14));
}

TEST_CASE("ValidateClosedSurface refuses open, degenerate and invalid surfaces with a useful message",
          "[fem]")
{
    const SurfaceMesh box = Box(Vec3::Zero(), Vec3::Ones());

    // One face (two triangles) missing: its four sides are open edges.
    SurfaceMesh open = box;
    open.mTriangles.resize(10);
    Status status = ValidateClosedSurface(open);
    REQUIRE(status.HasError());
    CHECK(status.GetError().mCode == EError::DegenerateGeometry);
    CHECK(status.GetError().mMessage.find("not closed: 4 of 17 edges") != std::string::npos);
    CHECK(status.GetError().mMessage.find("used by 1 triangle") != std::string::npos);

    // A third triangle on an edge: non-manifold.
    SurfaceMesh fin = box;
    fin.mPositions.emplace_back(0.5, 0.5, 2.0);
    fin.mTriangles.push_back({4, 5, 8});
    fin.mTriangles.push_back({5, 4, 8});
    status = ValidateClosedSurface(fin);
    REQUIRE(status.HasError());
    CHECK(status.GetError().mMessage.find("edge from (0, 0, 1) to (1, 0, 1) m, used by 4 triangles") !=
          std::string::npos);

    SurfaceMesh nan = box;
    nan.mPositions[3].x() = std::numeric_limits<double>::quiet_NaN();
    CHECK(ValidateClosedSurface(nan).GetError().mCode == EError::NonFinite);
    SurfaceMesh out_of_range = box;
    out_of_range.mTriangles[7][2] = 8;
    CHECK(ValidateClosedSurface(out_of_range).GetError().mCode == EError::OutOfRange);
    SurfaceMesh repeated = box;
    repeated.mTriangles[7] = {3, 6, 3};
    CHECK(ValidateClosedSurface(repeated).GetError().mCode == EError::DegenerateGeometry);
    CHECK(ValidateClosedSurface(SurfaceMesh{box.mPositions, {}}).GetError().mCode == EError::InvalidArgument);
}
