// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// samples::RemoveCaps with a bend curvature: the thin triangle of a floor pair that no cap angle catches is
// split until none is left that the bend could turn over, and bad parameters are refused, the mesh unchanged.
#include <RemoveCaps.h>
#include <ThinFloorPair.h>

#include <crumple/ffd/SplitFlipProneTriangles.h>

#include <catch2/catch.hpp>

#include <limits>

using namespace crumple;
using namespace crumple::samples;

using crumple::test::ThinFloorPair;

TEST_CASE("RemoveCaps: with a bend curvature no triangle is left that the bend could turn over", "[racing]")
{
    ffd::TriangleMesh mesh = ThinFloorPair();
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
    ffd::TriangleMesh caps_only = ThinFloorPair();
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
        ffd::TriangleMesh mesh = ThinFloorPair();
        std::vector<std::vector<std::uint32_t>> parts;
        const Result<CapRemoval> refused = RemoveCaps(mesh, parts, deviation, curvature);
        REQUIRE_FALSE(refused.IsValid());
        CHECK(refused.GetError().mCode == code);
        CHECK(mesh.mTriangles == ThinFloorPair().mTriangles);
        CHECK(mesh.mPositions == ThinFloorPair().mPositions);
    }
}
