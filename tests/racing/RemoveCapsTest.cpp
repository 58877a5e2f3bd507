// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// samples::RemoveCaps with a bend curvature: the thin triangle of a floor pair that no cap angle catches is
// split until none is left that the bend could turn over, and bad parameters are refused, the mesh unchanged.
#include <RemoveCaps.h>

#include <crumple/ffd/SplitFlipProneTriangles.h>

#include <catch2/catch.hpp>

#include <limits>

using namespace crumple;
using namespace crumple::samples;

namespace
{

// A long edge from (0, 0) to (0, 0.56), a thin triangle behind it (a 149.5 degree corner, bend limit 2.0 /m)
// and a well-shaped one in front (tests/ffd/SplitFlipProneTrianglesTest.cpp's floor).
ffd::TriangleMesh Floor()
{
    ffd::TriangleMesh mesh;
    mesh.mPositions = {Vec3(0.0, 0.0, 0.0), Vec3(0.0, 0.56, 0.0), Vec3(-0.05, 0.448, 0.0),
                       Vec3(0.4, 0.28, 0.0)};
    mesh.mTriangles = {{0, 1, 2}, {1, 0, 3}};
    return mesh;
}

} // namespace

TEST_CASE("RemoveCaps: with a bend curvature no triangle is left that the bend could turn over", "[racing]")
{
    ffd::TriangleMesh mesh = Floor();
    std::vector<std::vector<std::uint32_t>> parts;
    const Result<CapRemoval> removed = RemoveCaps(mesh, parts, 0.001, 10.0);
    REQUIRE(removed.IsValid());
    CHECK(removed.Get().mSplitVertices == 0); // no cap: the largest corner is under 150 degrees
    CHECK(removed.Get().mFlipProneVertices > 0);
    // Converged: one more pass finds nothing to split.
    const Result<ffd::RefinedMesh> again = ffd::SplitFlipProneTriangles(mesh, 10.0);
    REQUIRE(again.IsValid());
    CHECK(again.Get().mSplitParents.empty());

    // Without a curvature only caps go: the floor keeps its two triangles.
    ffd::TriangleMesh caps_only = Floor();
    const Result<CapRemoval> kept = RemoveCaps(caps_only, parts, 0.001);
    REQUIRE(kept.IsValid());
    CHECK(caps_only.mTriangles.size() == 2);
}

TEST_CASE("RemoveCaps: a negative or non-finite deviation or curvature is refused, the mesh unchanged",
          "[racing]")
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (const auto& [deviation, curvature, code] :
         {std::tuple{-0.001, 10.0, EError::InvalidArgument}, std::tuple{nan, 10.0, EError::NonFinite},
          std::tuple{0.001, -1.0, EError::InvalidArgument}, std::tuple{0.001, nan, EError::NonFinite},
          std::tuple{0.001, std::numeric_limits<double>::infinity(), EError::NonFinite}})
    {
        ffd::TriangleMesh mesh = Floor();
        std::vector<std::vector<std::uint32_t>> parts;
        const Result<CapRemoval> refused = RemoveCaps(mesh, parts, deviation, curvature);
        REQUIRE_FALSE(refused.IsValid());
        CHECK(refused.GetError().mCode == code);
        CHECK(mesh.mTriangles == Floor().mTriangles);
        CHECK(mesh.mPositions == Floor().mPositions);
    }
}
