// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// SplitFlipProneTriangles against the field that turns a triangle over: a long thin triangle (no cap: its
// largest corner is under 150 degrees) that an in-plane bend of curvature kappa turns over exactly when
// kappa passes its bend limit 2 h / (L^2 s (1 - s)) is split below that limit and left above it; its pieces
// take the same bend without turning, the surface keeps its shape, and bad input changes nothing.
#include "MeshChecks.h"
#include "ThinFloorPair.h"

#include <crumple/ffd/SplitFlipProneTriangles.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

using namespace crumple;
using namespace crumple::ffd;
using namespace crumple::ffd::test;
using crumple::test::cThinFloorBendLimit;
using crumple::test::ThinFloorPair;

namespace
{

// A crush bending the floor in its plane: x moves by kappa / 2 y (0.56 - y), zero at both ends of the edge
// and most in its middle, a parabola of curvature kappa along y.
TriangleMesh Bent(const TriangleMesh& inMesh, double inKappa)
{
    TriangleMesh bent = inMesh;
    for (Vec3& p : bent.mPositions)
        p.x() += 0.5 * inKappa * p.y() * (0.56 - p.y());
    return bent;
}

// SplitFlipProneTriangles until it adds nothing; the number of passes that added vertices.
int SplitUntilDone(TriangleMesh& ioMesh, double inKappa)
{
    int passes = 0;
    for (; passes < 20; ++passes)
    {
        Result<RefinedMesh> split = SplitFlipProneTriangles(ioMesh, inKappa);
        REQUIRE(split.IsValid());
        if (split.Get().mSplitParents.empty())
            break;
        for (std::size_t added = 0; added < split.Get().mSplitParents.size(); ++added)
        {
            // every added vertex lies on its parent edge, where its fraction says: the shape is kept
            const auto [a, b] = split.Get().mSplitParents[added];
            const double t = split.Get().mSplitFractions[added];
            const Vec3 expected = (1.0 - t) * ioMesh.mPositions[a] + t * ioMesh.mPositions[b];
            CHECK((split.Get().mMesh.mPositions[ioMesh.mPositions.size() + added] - expected).norm() <=
                  1.0e-15);
        }
        ioMesh = std::move(split.Get().mMesh);
    }
    return passes;
}

} // namespace

TEST_CASE("SplitFlipProneTriangles: the bend that turns a thin triangle over is the one its limit names",
          "[ffd]")
{
    const TriangleMesh floor = ThinFloorPair();
    // The analytic threshold, checked on the field itself: just above the limit the triangle turns over, just
    // below it does not.
    CHECK(TurnedOver(floor, Bent(floor, 1.01 * cThinFloorBendLimit)) == 1);
    CHECK(TurnedOver(floor, Bent(floor, 0.99 * cThinFloorBendLimit)) == 0);

    // Asked to stand a bend under its limit, nothing is split.
    Result<RefinedMesh> kept = SplitFlipProneTriangles(floor, 0.99 * cThinFloorBendLimit);
    REQUIRE(kept.IsValid());
    CHECK(kept.Get().mSplitParents.empty());
    CHECK(kept.Get().mMesh.mTriangles == floor.mTriangles);

    // Asked to stand three times its limit, it is split (the neighbour on the edge too), and the pieces take
    // that bend, and one of ten times its limit, without turning over.
    for (const double factor : {3.0, 10.0})
    {
        TriangleMesh split = floor;
        const int passes = SplitUntilDone(split, factor * cThinFloorBendLimit);
        INFO("bend " << factor << " x the limit: " << passes << " passes, " << split.mTriangles.size()
                     << " triangles");
        CHECK(passes >= 1);
        CHECK(passes < 20);
        CHECK(split.mTriangles.size() > floor.mTriangles.size() + 1);
        CHECK(TurnedOver(split, Bent(split, factor * cThinFloorBendLimit)) == 0);
        CHECK(TotalArea(split) == Approx(TotalArea(floor)).epsilon(1.0e-12));
    }
}

TEST_CASE("SplitFlipProneTriangles: a bad curvature or mesh is refused", "[ffd]")
{
    const TriangleMesh floor = ThinFloorPair();
    for (const double bad : {0.0, -1.0})
    {
        const Result<RefinedMesh> refused = SplitFlipProneTriangles(floor, bad);
        REQUIRE_FALSE(refused.IsValid());
        CHECK(refused.GetError().mCode == EError::InvalidArgument);
    }
    for (const double bad :
         {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
    {
        const Result<RefinedMesh> refused = SplitFlipProneTriangles(floor, bad);
        REQUIRE_FALSE(refused.IsValid());
        CHECK(refused.GetError().mCode == EError::NonFinite);
    }
    TriangleMesh broken = floor;
    broken.mTriangles.push_back({0, 1, 7});
    CHECK_FALSE(SplitFlipProneTriangles(broken, 10.0).IsValid());
}
