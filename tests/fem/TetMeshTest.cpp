// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/EdgeMatrix.h>
#include <crumple/fem/TetMesh.h>
#include <crumple/fem/TetVolume.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>

using namespace crumple;
using namespace crumple::fem;

namespace
{

// The unit corner tetrahedron: volume 1/6 with indices (0, 1, 2, 3).
std::vector<Vec3> CornerTet()
{
    return {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
}

} // namespace

TEST_CASE("TetVolume is the signed volume and EdgeMatrix its 6x determinant", "[fem]")
{
    const std::vector<Vec3> p = CornerTet();
    CHECK(TetVolume(p[0], p[1], p[2], p[3]) == Approx(1.0 / 6.0).epsilon(1e-15));
    CHECK(TetVolume(p[0], p[2], p[1], p[3]) == Approx(-1.0 / 6.0).epsilon(1e-15));
    CHECK(EdgeMatrix(p[0], p[1], p[2], p[3]).determinant() == Approx(1.0).epsilon(1e-15));

    // Invariant under a rigid motion, cubic in a scale.
    const Mat3 rotation = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
    const Vec3 shift(4.0, -5.0, 6.0);
    auto moved = [&](const Vec3& inP) { return Vec3(2.0 * (rotation * inP) + shift); };
    CHECK(TetVolume(moved(p[0]), moved(p[1]), moved(p[2]), moved(p[3])) == Approx(8.0 / 6.0).epsilon(1e-13));
}

TEST_CASE("TetMesh keeps a valid mesh as given", "[fem]")
{
    // Two tetrahedra sharing the face (1, 2, 3).
    std::vector<Vec3> positions = CornerTet();
    positions.push_back(Vec3(1, 1, 1));
    Result<TetMesh> mesh = TetMesh::Create(positions, {{0, 1, 2, 3}, {4, 1, 3, 2}});
    REQUIRE(mesh.IsValid());
    CHECK(mesh.Get().GetNodeCount() == 5);
    CHECK(mesh.Get().GetTetCount() == 2);
    CHECK(mesh.Get().GetGroups() == std::vector<int>{0, 1});
    CHECK(mesh.Get().GetRestVolume(0) == Approx(1.0 / 6.0));
    CHECK(mesh.Get().GetRestVolume(1) == Approx(1.0 / 3.0));
    CHECK(mesh.Get().GetTotalVolume() == Approx(0.5));
    CHECK(mesh.Get().GetTets()[1] == TetIndices{4, 1, 3, 2});

    // Explicit group ids are kept.
    Result<TetMesh> grouped = TetMesh::Create(positions, {{0, 1, 2, 3}, {4, 1, 3, 2}}, {7, 7});
    REQUIRE(grouped.IsValid());
    CHECK(grouped.Get().GetGroups() == std::vector<int>{7, 7});
}

TEST_CASE("TetMesh refuses bad input with a clear error", "[fem]")
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    struct Case
    {
        const char* mName;
        std::vector<Vec3> mPositions;
        std::vector<TetIndices> mTets;
        std::vector<int> mGroups;
        EError mCode;
        const char* mNeedle;
    };
    const std::vector<Vec3> p = CornerTet();
    const std::vector<Case> cases = {
        {"inverted",
         p,
         {{0, 2, 1, 3}},
         {},
         EError::DegenerateGeometry,
         "tet 0 (nodes 0, 2, 1, 3) is inverted"},
        {"degenerate",
         {p[0], p[1], p[2], Vec3(0.3, 0.3, 0.0)},
         {{0, 1, 2, 3}},
         {},
         EError::DegenerateGeometry,
         "is degenerate"},
        {"index too large", p, {{0, 1, 2, 4}}, {}, EError::OutOfRange, "names node 4, outside [0, 4)"},
        {"negative index", p, {{0, 1, -1, 3}}, {}, EError::OutOfRange, "names node -1"},
        {"repeated index", p, {{0, 1, 1, 3}}, {}, EError::DegenerateGeometry, "uses a node twice"},
        {"NaN position",
         {p[0], p[1], Vec3(0, nan, 0), p[3]},
         {{0, 1, 2, 3}},
         {},
         EError::NonFinite,
         "node 2 has a non-finite position"},
        {"unused node",
         {p[0], p[1], p[2], p[3], Vec3(5, 5, 5)},
         {{0, 1, 2, 3}},
         {},
         EError::InvalidArgument,
         "node 4 belongs to no tetrahedron"},
        {"too few nodes",
         {p[0], p[1], p[2]},
         {{0, 1, 2, 0}},
         {},
         EError::InvalidArgument,
         "at least 4 nodes"},
        {"no tetrahedron", p, {}, {}, EError::InvalidArgument, "at least 4 nodes and 1 tetrahedron"},
        {"group count", p, {{0, 1, 2, 3}}, {0, 1}, EError::InvalidArgument, "2 group ids for 1 tetrahedra"},
        {"negative group", p, {{0, 1, 2, 3}}, {-3}, EError::InvalidArgument, "group id -3"},
    };
    for (const Case& c : cases)
    {
        INFO(c.mName);
        Result<TetMesh> mesh = TetMesh::Create(c.mPositions, c.mTets, c.mGroups);
        REQUIRE(mesh.HasError());
        CHECK(mesh.GetError().mCode == c.mCode);
        INFO(mesh.GetError().mMessage);
        CHECK(mesh.GetError().mMessage.find(c.mNeedle) != std::string::npos);
    }
}
