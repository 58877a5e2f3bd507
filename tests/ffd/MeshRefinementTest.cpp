// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// RefineLongEdges and FlipFlatEdges: the surface stays the same, the triangles get short and well shaped,
// and a smooth dent that turns a bumper's slivers over leaves the refined triangles of the same face alone.
#include "MeshChecks.h"

#include <crumple/ffd/FlipFlatEdges.h>
#include <crumple/ffd/RefineLongEdges.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <numbers>
#include <utility>

using namespace crumple;
using namespace crumple::ffd;
using namespace crumple::ffd::test;

namespace
{

double LongestEdge(const TriangleMesh& inMesh)
{
    double longest = 0.0;
    for (const auto& t : inMesh.mTriangles)
        for (int k = 0; k < 3; ++k)
            longest = std::max(longest, (inMesh.mPositions[t[k]] - inMesh.mPositions[t[(k + 1) % 3]]).norm());
    return longest;
}

// A closed cube of side 2 m about the origin, two triangles per face, counter-clockwise from outside.
TriangleMesh Cube()
{
    TriangleMesh mesh;
    for (int i = 0; i < 8; ++i)
        mesh.mPositions.emplace_back((i & 1) ? 1.0 : -1.0, (i & 2) ? 1.0 : -1.0, (i & 4) ? 1.0 : -1.0);
    mesh.mTriangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                       {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
    return mesh;
}

// A bumper's flat underside as exporters cut it: a strip 1.3 m wide whose front edge is curved (x from
// 0.06 m at the middle to 0.01 m at the ends, 41 points) and whose straight back edge (x = 0) has only its
// two corners, fanned from the back-left corner into slivers. Normal -z (seen from below).
TriangleMesh BumperUnderside()
{
    TriangleMesh mesh;
    mesh.mPositions.emplace_back(0.0, -0.65, 0.0); // 0: back left
    mesh.mPositions.emplace_back(0.0, 0.65, 0.0);  // 1: back right
    constexpr int cFront = 41;
    for (int i = 0; i < cFront; ++i)
    {
        const double y = -0.65 + 1.3 * i / (cFront - 1);
        mesh.mPositions.emplace_back(0.06 - 0.05 * (y / 0.65) * (y / 0.65), y, 0.0);
    }
    // intent: the fan from the back-left corner over the front edge, then the last triangle to the back right
    for (std::uint32_t i = 2; i + 1 < 2 + cFront; ++i)
        mesh.mTriangles.push_back({0, i + 1, i});
    mesh.mTriangles.push_back({0, 1, 2 + cFront - 1});
    return mesh;
}

} // namespace

TEST_CASE("RefineLongEdges: a closed cube stays closed, flat and of the same area, with no edge over the limit", "[ffd]")
{
    const TriangleMesh cube = Cube();
    Result<RefinedMesh> refined = RefineLongEdges(cube, 0.3);
    REQUIRE(refined);
    const RefinedMesh& r = refined.Get();
    CHECK(r.mMesh.mTriangles.size() > 12 * 16);
    CHECK(LongestEdge(r.mMesh) <= 0.3);
    CHECK(TotalArea(r.mMesh) == Approx(24.0).epsilon(1e-12));
    CHECK(IsClosedManifold(r.mMesh));
    // intent: every piece lies on its cube face and faces out as the face did
    for (const auto& t : r.mMesh.mTriangles)
    {
        const Vec3 n = AreaVector(r.mMesh, t).normalized();
        const Vec3 centre = (r.mMesh.mPositions[t[0]] + r.mMesh.mPositions[t[1]] + r.mMesh.mPositions[t[2]]) / 3.0;
        Eigen::Index axis = 0;
        n.cwiseAbs().maxCoeff(&axis);
        CHECK(std::abs(n[axis]) == Approx(1.0).epsilon(1e-12));
        CHECK(n[axis] * centre[axis] == Approx(1.0).epsilon(1e-12));
    }
    // intent: the input's vertices first, unchanged; each added one exactly its parents' midpoint
    REQUIRE(r.mMesh.mPositions.size() == cube.mPositions.size() + r.mSplitParents.size());
    REQUIRE(r.mSplitFractions.size() == r.mSplitParents.size());
    for (double fraction : r.mSplitFractions)
        CHECK(fraction == 0.5);
    for (std::size_t v = 0; v < cube.mPositions.size(); ++v)
        CHECK(r.mMesh.mPositions[v] == cube.mPositions[v]);
    for (std::size_t k = 0; k < r.mSplitParents.size(); ++k)
    {
        const auto [a, b] = r.mSplitParents[k];
        const std::size_t added = cube.mPositions.size() + k;
        CHECK(a < added);
        CHECK(b < added);
        CHECK(r.mMesh.mPositions[added] == 0.5 * (r.mMesh.mPositions[a] + r.mMesh.mPositions[b]));
    }
    // intent: the same input, the same mesh, bit for bit
    Result<RefinedMesh> again = RefineLongEdges(cube, 0.3);
    REQUIRE(again);
    CHECK(again.Get().mMesh.mPositions == r.mMesh.mPositions);
    CHECK(again.Get().mMesh.mTriangles == r.mMesh.mTriangles);
}

TEST_CASE("RefineLongEdges: the two sides of a texture seam get the same midpoints, so no crack opens", "[ffd]")
{
    // Two triangles sharing the edge (0, 1) by position only: vertices 2 and 3 duplicate 0 and 1.
    TriangleMesh mesh;
    mesh.mPositions = {Vec3(0.0, 0.0, 0.0), Vec3(1.0, 0.3, 0.0), Vec3(0.0, 0.0, 0.0), Vec3(1.0, 0.3, 0.0),
                       Vec3(0.4, 0.9, 0.0), Vec3(0.6, -0.7, 0.0)};
    mesh.mTriangles = {{0, 1, 4}, {3, 2, 5}};
    Result<RefinedMesh> refined = RefineLongEdges(mesh, 0.2);
    REQUIRE(refined);
    const TriangleMesh& r = refined.Get().mMesh;
    // intent: every point on the seam (y = 0.3 x, 0 <= x <= 1) from one side has a bitwise twin from the other
    std::vector<Vec3> left, right;
    auto side = [](const Vec3& inPoint) { return inPoint.y() - 0.3 * inPoint.x(); };
    for (const auto& t : r.mTriangles)
    {
        const Vec3 centre = (r.mPositions[t[0]] + r.mPositions[t[1]] + r.mPositions[t[2]]) / 3.0;
        for (std::uint32_t v : t)
            if (std::abs(side(r.mPositions[v])) < 1e-15)
                (side(centre) > 0.0 ? left : right).push_back(r.mPositions[v]);
    }
    REQUIRE(left.size() > 4);
    REQUIRE(right.size() > 4);
    for (const Vec3& p : left)
        CHECK(std::find(right.begin(), right.end(), p) != right.end());
    CHECK(LongestEdge(r) <= 0.2);
}

TEST_CASE("RefineLongEdges: bad input is refused with a reason", "[ffd]")
{
    const TriangleMesh cube = Cube();
    for (double bad : {0.0, -0.1, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
    {
        Result<RefinedMesh> refined = RefineLongEdges(cube, bad);
        REQUIRE(refined.HasError());
        CHECK(refined.GetError().mMessage.find("longest edge") != std::string::npos);
    }
    CHECK(RefineLongEdges(TriangleMesh{}, 0.1).HasError());
    Result<RefinedMesh> too_many = RefineLongEdges(cube, 0.001, 100'000);
    REQUIRE(too_many.HasError());
    CHECK(too_many.GetError().mMessage.find("100000 triangles") != std::string::npos);
    // intent: a mesh already fine enough comes back as it was
    Result<RefinedMesh> same = RefineLongEdges(cube, 10.0);
    REQUIRE(same);
    CHECK(same.Get().mMesh.mTriangles == cube.mTriangles);
    CHECK(same.Get().mSplitParents.empty());
}

TEST_CASE("FlipFlatEdges: a fan of slivers becomes Delaunay, the face and its outline unchanged", "[ffd]")
{
    const TriangleMesh fan = BumperUnderside();
    TriangleMesh flipped = fan;
    Result<std::size_t> flips = FlipFlatEdges(flipped);
    REQUIRE(flips);
    CHECK(flips.Get() > 10);
    CHECK(flipped.mPositions == fan.mPositions);
    CHECK(flipped.mTriangles.size() == fan.mTriangles.size());
    CHECK(TotalArea(flipped) == Approx(TotalArea(fan)).epsilon(1e-12));
    for (const auto& t : flipped.mTriangles)
        CHECK(AreaVector(flipped, t).z() < 0.0);
    // a Delaunay triangulation has the largest smallest angle of all (the strip is thin: it stays small)
    CHECK(CornerAngleRange(flipped).mSmallest >= CornerAngleRange(fan).mSmallest);
    // intent: no edge left whose two facing angles add up to more than pi (the Delaunay property)
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> opposite;
    for (const auto& t : flipped.mTriangles)
        for (int k = 0; k < 3; ++k)
            opposite[{t[k], t[(k + 1) % 3]}] = t[(k + 2) % 3];
    // intent: named pairs, not structured bindings: a lambda may not capture those before C++20 compilers
    // caught up (clang 14 refuses it)
    for (const auto& entry : opposite)
        if (const auto other = opposite.find({entry.first.second, entry.first.first}); other != opposite.end())
        {
            const std::pair<std::uint32_t, std::uint32_t>& edge = entry.first;
            const std::uint32_t c = entry.second;
            auto angle = [&](std::uint32_t inApex) {
                const Vec3 u = flipped.mPositions[edge.first] - flipped.mPositions[inApex];
                const Vec3 v = flipped.mPositions[edge.second] - flipped.mPositions[inApex];
                return std::atan2(u.cross(v).norm(), u.dot(v));
            };
            CHECK(angle(c) + angle(other->second) <= std::numbers::pi + 1e-9);
        }
}

TEST_CASE("FlipFlatEdges: a fold between two planes is left alone, bad input changes nothing", "[ffd]")
{
    TriangleMesh roof;
    roof.mPositions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, 0.1, 0.3), Vec3(0.5, -0.1, 0.3)};
    roof.mTriangles = {{0, 1, 2}, {1, 0, 3}};
    TriangleMesh copy = roof;
    Result<std::size_t> flips = FlipFlatEdges(copy);
    REQUIRE(flips);
    CHECK(flips.Get() == 0);
    CHECK(copy.mTriangles == roof.mTriangles);
    for (double bad : {0.0, -1.0, 1.5, std::numeric_limits<double>::quiet_NaN()})
    {
        REQUIRE(FlipFlatEdges(copy, bad).HasError());
        CHECK(copy.mTriangles == roof.mTriangles);
    }
}

TEST_CASE("A smooth pocket turns a bumper's slivers over, and none of the Delaunay, refined triangles", "[ffd]")
{
    const TriangleMesh fan = BumperUnderside();
    // the premise: the exported fan folds under a field that folds nothing
    CHECK(TurnedOver(fan, Pocket(fan)) > 0);
    TriangleMesh better = fan;
    REQUIRE(FlipFlatEdges(better));
    Result<RefinedMesh> refined = RefineLongEdges(better, 0.1);
    REQUIRE(refined);
    better = refined.Get().mMesh;
    REQUIRE(FlipFlatEdges(better));
    CHECK(TotalArea(better) == Approx(TotalArea(fan)).epsilon(1e-12));
    CHECK(TurnedOver(better, Pocket(better)) == 0);
}

namespace
{

// The bumper's fan, its vertices raised or lowered by up to inNoise (m) in z, seeded: flat to a fraction of a
// millimetre, as an exported bevel is, so the slivers' unit normals scatter by degrees.
TriangleMesh NoisyBumperUnderside(double inNoise)
{
    TriangleMesh mesh = BumperUnderside();
    std::uint32_t state = 12345u;
    for (Vec3& p : mesh.mPositions)
    {
        state = state * 1664525u + 1013904223u;
        p.z() += inNoise * (2.0 * (state >> 8) / double(1u << 24) - 1.0);
    }
    return mesh;
}

// Distance from inPoint to the triangle (a, b, c), by the closest point on the plane or on an edge.
double PointTriangleDistance(const Vec3& inPoint, const Vec3& inA, const Vec3& inB, const Vec3& inC)
{
    auto segment = [&](const Vec3& inFrom, const Vec3& inTo) {
        const Vec3 d = inTo - inFrom;
        const double t = std::clamp((inPoint - inFrom).dot(d) / d.squaredNorm(), 0.0, 1.0);
        return (inFrom + t * d - inPoint).norm();
    };
    const Vec3 n = (inB - inA).cross(inC - inA);
    const Vec3 projected = inPoint - ((inPoint - inA).dot(n) / n.squaredNorm()) * n;
    // intent: inside when the projection lies on the same side of all three edges
    const bool inside = (inB - inA).cross(projected - inA).dot(n) >= 0.0 && (inC - inB).cross(projected - inB).dot(n) >= 0.0 &&
                        (inA - inC).cross(projected - inC).dot(n) >= 0.0;
    if (inside)
        return (projected - inPoint).norm();
    return std::min({segment(inA, inB), segment(inB, inC), segment(inC, inA)});
}

// The largest distance from points spread over inMesh's triangles to inOther's surface.
double SurfaceDeviation(const TriangleMesh& inMesh, const TriangleMesh& inOther)
{
    double largest = 0.0;
    constexpr int cSteps = 8;
    for (const auto& t : inMesh.mTriangles)
        for (int i = 0; i <= cSteps; ++i)
            for (int j = 0; i + j <= cSteps; ++j)
            {
                const double u = double(i) / cSteps, v = double(j) / cSteps;
                const Vec3 p = (1.0 - u - v) * inMesh.mPositions[t[0]] + u * inMesh.mPositions[t[1]] + v * inMesh.mPositions[t[2]];
                double nearest = std::numeric_limits<double>::infinity();
                for (const auto& o : inOther.mTriangles)
                    nearest = std::min(nearest, PointTriangleDistance(p, inOther.mPositions[o[0]], inOther.mPositions[o[1]],
                                                                      inOther.mPositions[o[2]]));
                largest = std::max(largest, nearest);
            }
    return largest;
}

} // namespace

TEST_CASE("FlipNearlyFlatEdges: on an exactly flat fan it makes FlipFlatEdges' triangles", "[ffd]")
{
    TriangleMesh exact = BumperUnderside(), nearly = BumperUnderside();
    REQUIRE(FlipFlatEdges(exact));
    Result<std::size_t> flips = FlipNearlyFlatEdges(nearly, 0.0);
    REQUIRE(flips);
    CHECK(flips.Get() > 10);
    CHECK(nearly.mTriangles == exact.mTriangles);
}

TEST_CASE("FlipNearlyFlatEdges: a fan flat to 0.2 mm becomes Delaunay within the deviation, and a pocket turns nothing over", "[ffd]")
{
    constexpr double cNoise = 2.0e-4, cTolerance = 1.0e-3;
    const TriangleMesh fan = NoisyBumperUnderside(cNoise);
    // the premise: the slivers' normals scatter too far for FlipFlatEdges, and the pocket turns them over
    TriangleMesh exact = fan;
    REQUIRE(FlipFlatEdges(exact));
    CHECK(TurnedOver(exact, Pocket(exact)) > 0);

    TriangleMesh nearly = fan;
    Result<std::size_t> flips = FlipNearlyFlatEdges(nearly, cTolerance);
    REQUIRE(flips);
    CHECK(flips.Get() > 10);
    CHECK(nearly.mPositions == fan.mPositions);
    CHECK(nearly.mTriangles.size() == fan.mTriangles.size());
    for (const auto& t : nearly.mTriangles)
        CHECK(AreaVector(nearly, t).z() < 0.0);
    CHECK(CornerAngleRange(nearly).mSmallest > CornerAngleRange(fan).mSmallest);
    // intent: Delaunay: no inner edge left whose two facing angles add up to more than pi (every quad of the
    // fan is convex and within the deviation, so every such edge could flip)
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> opposite;
    for (const auto& t : nearly.mTriangles)
        for (int k = 0; k < 3; ++k)
            opposite[{t[k], t[(k + 1) % 3]}] = t[(k + 2) % 3];
    int inner = 0;
    for (const auto& entry : opposite)
        if (const auto other = opposite.find({entry.first.second, entry.first.first}); other != opposite.end())
        {
            const Vec3& a = nearly.mPositions[entry.first.first];
            const Vec3& b = nearly.mPositions[entry.first.second];
            auto angle = [&](std::uint32_t inApex) {
                const Vec3 u = a - nearly.mPositions[inApex], v = b - nearly.mPositions[inApex];
                return std::atan2(u.cross(v).norm(), u.dot(v));
            };
            CHECK(angle(entry.second) + angle(other->second) <= std::numbers::pi + 1e-9);
            ++inner;
        }
    CHECK(inner > 20);
    // intent: the surface moved by no more than the noise allows (each flip is bounded by its slab, and the
    // whole fan lies within cNoise of z = 0), both ways
    CHECK(SurfaceDeviation(nearly, fan) <= 2.0 * cNoise);
    CHECK(SurfaceDeviation(fan, nearly) <= 2.0 * cNoise);
    // intent: refined as crumple-crash does, the pocket turns nothing over
    Result<RefinedMesh> refined = RefineLongEdges(nearly, 0.1);
    REQUIRE(refined);
    TriangleMesh better = refined.Get().mMesh;
    REQUIRE(FlipNearlyFlatEdges(better, cTolerance));
    CHECK(TurnedOver(better, Pocket(better)) == 0);
}

TEST_CASE("FlipNearlyFlatEdges: a ridge flips only when its height is within the deviation", "[ffd]")
{
    // A tent: the edge (0, 1) along x at z = 0 and the edge between the two far corners 0.3 m above it.
    TriangleMesh tent;
    tent.mPositions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, 0.1, 0.3), Vec3(0.5, -0.1, 0.3)};
    tent.mTriangles = {{0, 1, 2}, {1, 0, 3}};
    TriangleMesh below = tent, above = tent;
    Result<std::size_t> none = FlipNearlyFlatEdges(below, 0.29);
    REQUIRE(none);
    CHECK(none.Get() == 0);
    CHECK(below.mTriangles == tent.mTriangles);
    Result<std::size_t> one = FlipNearlyFlatEdges(above, 0.31);
    REQUIRE(one);
    CHECK(one.Get() == 1);
    // intent: (a, b, c) = (0, 1, 2) and (b, a, d) = (1, 0, 3) become (c, d, b) and (d, c, a)
    CHECK(above.mTriangles == std::vector<std::array<std::uint32_t, 3>>{{2, 3, 1}, {3, 2, 0}});
}

TEST_CASE("FlipNearlyFlatEdges: across a seam only when asked, each new triangle from both sides' vertices", "[ffd]")
{
    // A cap (0, 1, 2) 0.1 mm high on a 1 m edge, and across that edge, by position only, the triangle (4, 3, 5):
    // vertices 3 and 4 duplicate 0 and 1, as an exporter splits them at a texture seam.
    TriangleMesh seam;
    seam.mPositions = {Vec3(0, 0, 0),  Vec3(1, 0, 0),    Vec3(0.5, 1e-4, 0), Vec3(0, 0, 0),
                       Vec3(1, 0, 0), Vec3(0.5, -0.6, 0)};
    seam.mTriangles = {{0, 1, 2}, {4, 3, 5}};
    TriangleMesh apart = seam;
    Result<std::size_t> none = FlipNearlyFlatEdges(apart, 1e-3);
    REQUIRE(none);
    CHECK(none.Get() == 0);
    TriangleMesh joined = seam;
    Result<std::size_t> one = FlipNearlyFlatEdges(joined, 1e-3, true);
    REQUIRE(one);
    CHECK(one.Get() == 1);
    // intent: the first slot keeps its side's b = 1 with the cap's apex 2 and the far corner 5; the second its
    // side's a = 3
    CHECK(joined.mTriangles[0] == std::array<std::uint32_t, 3>{2, 5, 1});
    CHECK(joined.mTriangles[1] == std::array<std::uint32_t, 3>{5, 2, 3});
    CHECK(TotalArea(joined) == Approx(TotalArea(seam)).epsilon(1e-12));
    for (const auto& t : joined.mTriangles)
        CHECK(AreaVector(joined, t).z() > 0.0);
}

TEST_CASE("FlipNearlyFlatEdges: bad input changes nothing", "[ffd]")
{
    TriangleMesh fan = NoisyBumperUnderside(2.0e-4);
    const TriangleMesh copy = fan;
    for (double bad : {-1e-3, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
    {
        Result<std::size_t> flips = FlipNearlyFlatEdges(fan, bad);
        REQUIRE(flips.HasError());
        CHECK(flips.GetError().mMessage.find("deviation") != std::string::npos);
        CHECK(fan.mTriangles == copy.mTriangles);
    }
    TriangleMesh broken = copy;
    broken.mTriangles.push_back({0, 1, 999});
    const TriangleMesh broken_copy = broken;
    REQUIRE(FlipNearlyFlatEdges(broken, 1e-3).HasError());
    CHECK(broken.mTriangles == broken_copy.mTriangles);
}

TEST_CASE("FlipNearlyFlatEdges: a closed mesh stays closed, a seam's other side is never doubled", "[ffd]")
{
    SECTION("a re-cut cube, its faces raised or lowered by up to 0.1 mm")
    {
        Result<RefinedMesh> refined = RefineLongEdges(Cube(), 0.3);
        REQUIRE(refined);
        TriangleMesh cube = refined.Get().mMesh;
        std::uint32_t state = 777u;
        for (Vec3& p : cube.mPositions)
        {
            // intent: each vertex leaves the planes of the faces it lies on by up to 0.1 mm, along their normals
            state = state * 1664525u + 1013904223u;
            const double noise = 1.0e-4 * (2.0 * (state >> 8) / double(1u << 24) - 1.0);
            for (int axis = 0; axis < 3; ++axis)
                if (std::abs(std::abs(p[axis]) - 1.0) < 1e-12)
                    p[axis] += noise;
        }
        REQUIRE(IsClosedManifold(cube));
        TriangleMesh flipped = cube;
        Result<std::size_t> flips = FlipNearlyFlatEdges(flipped, 1.0e-3);
        REQUIRE(flips);
        CHECK(flips.Get() > 0);
        CHECK(IsClosedManifold(flipped));
        CHECK(TotalArea(flipped) == Approx(TotalArea(cube)).epsilon(1e-6));
        CHECK(CornerAngleRange(flipped).mSmallest >= CornerAngleRange(cube).mSmallest);
        // intent: no flip crossed a cube edge (0.1 mm noise against a 90-degree crease)
        CHECK(SurfaceDeviation(flipped, cube) <= 2.0e-4);
    }

    SECTION("a thin closed tetrahedron with a vertex split at a seam, flipped by index")
    {
        // Found by a review: the faces (a, b, c) and (b, a, d) are a nearly flat pair whose flip to cd makes the
        // two faces the other side of the seam has by position, reversed: two sheets doubled on each other.
        TriangleMesh tet;
        tet.mPositions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, 0.1, 5e-4), Vec3(0.5, -0.1, 5e-4), Vec3(0.5, 0.1, 5e-4)};
        tet.mTriangles = {{1, 0, 2}, {0, 1, 3}, {3, 1, 4}, {4, 0, 3}};
        for (bool across : {false, true})
        {
            TriangleMesh copy = tet;
            REQUIRE(FlipNearlyFlatEdges(copy, 1.0e-3, across));
            INFO("across seams " << across);
            CHECK(copy.mTriangles == tet.mTriangles);
        }
        TriangleMesh flat = tet;
        REQUIRE(FlipFlatEdges(flat, 0.9));
        CHECK(flat.mTriangles == tet.mTriangles);
    }
}

TEST_CASE("FlipNearlyFlatEdges with a cap angle: only caps' long edges flip, the rest keeps its triangles", "[ffd]")
{
    // A flat square of 4 x 4 cells cut along one diagonal each (not Delaunay where the diagonals disagree
    // with a slight shear), with a cap: a vertex 0.1 mm off the middle of one cell's diagonal, fanned in.
    TriangleMesh mesh;
    constexpr int cCells = 4;
    for (int j = 0; j <= cCells; ++j)
        for (int i = 0; i <= cCells; ++i)
            mesh.mPositions.emplace_back(0.1 * i + 0.02 * j, 0.1 * j, 0.0); // sheared: the cut diagonals are not Delaunay
    auto index = [](int inI, int inJ) { return static_cast<std::uint32_t>(inJ * (cCells + 1) + inI); };
    for (int j = 0; j < cCells; ++j)
        for (int i = 0; i < cCells; ++i)
        {
            if (i == 1 && j == 1)
                continue; // the cell with the cap, below
            mesh.mTriangles.push_back({index(i, j), index(i + 1, j), index(i + 1, j + 1)});
            mesh.mTriangles.push_back({index(i, j), index(i + 1, j + 1), index(i, j + 1)});
        }
    // intent: cell (1, 1) split at a point just beside its diagonal: (a, b, c) is a cap with c near ab
    const Vec3 a = mesh.mPositions[index(1, 1)], b = mesh.mPositions[index(2, 2)];
    mesh.mPositions.push_back(0.5 * (a + b) + Vec3(-1e-4, 1e-4, 0.0)); // left of a -> b, inside (a, b, (1, 2))
    const auto c = static_cast<std::uint32_t>(mesh.mPositions.size() - 1);
    mesh.mTriangles.push_back({index(1, 1), index(2, 1), index(2, 2)});
    mesh.mTriangles.push_back({index(1, 1), index(2, 2), c});
    mesh.mTriangles.push_back({c, index(2, 2), index(1, 2)});
    mesh.mTriangles.push_back({index(1, 1), c, index(1, 2)});

    TriangleMesh caps = mesh, all = mesh;
    Result<std::size_t> cap_flips = FlipNearlyFlatEdges(caps, 1.0e-3, false, 150.0 * std::numbers::pi / 180.0);
    Result<std::size_t> all_flips = FlipNearlyFlatEdges(all, 1.0e-3);
    REQUIRE(cap_flips);
    REQUIRE(all_flips);
    CHECK(cap_flips.Get() >= 1);
    CHECK(all_flips.Get() > cap_flips.Get()); // the sheared cells' diagonals flip too without a cap angle
    // intent: no corner of 150 degrees or more is left, and every other cell keeps its two triangles
    for (const auto& t : caps.mTriangles)
        for (int k = 0; k < 3; ++k)
        {
            const Vec3 u = caps.mPositions[t[(k + 1) % 3]] - caps.mPositions[t[k]];
            const Vec3 v = caps.mPositions[t[(k + 2) % 3]] - caps.mPositions[t[k]];
            CHECK(std::atan2(u.cross(v).norm(), u.dot(v)) < 150.0 * std::numbers::pi / 180.0);
        }
    std::size_t kept = 0;
    for (std::size_t t = 0; t + 4 < mesh.mTriangles.size(); ++t)
        kept += caps.mTriangles[t] == mesh.mTriangles[t] ? 1 : 0;
    CHECK(kept >= mesh.mTriangles.size() - 4 - 4); // at most the cap's neighbour cells changed
    CHECK(TotalArea(caps) == Approx(TotalArea(mesh)).epsilon(1e-12));
    for (const auto& t : caps.mTriangles)
        CHECK(AreaVector(caps, t).z() > 0.0);
    for (double bad : {-0.1, 4.0, std::numeric_limits<double>::quiet_NaN()})
    {
        TriangleMesh copy = mesh;
        REQUIRE(FlipNearlyFlatEdges(copy, 1.0e-3, false, bad).HasError());
        CHECK(copy.mTriangles == mesh.mTriangles);
    }
}

TEST_CASE(
    "RefineLongEdges with a bend limit cuts flat panels only, and leaves a curved surface's facets whole",
    "[ffd]")
{
    const double two_degrees = 2.0 * std::numbers::pi / 180.0;
    // A flat square of two triangles: cut down to the limit as without a bend limit (its edges are flat or on
    // its border, where one triangle is alone).
    TriangleMesh square;
    square.mPositions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
    square.mTriangles = {{0, 1, 2}, {0, 2, 3}};
    Result<RefinedMesh> flat = RefineLongEdges(square, 0.3, 4'000'000, two_degrees);
    Result<RefinedMesh> any = RefineLongEdges(square, 0.3);
    REQUIRE(flat);
    REQUIRE(any);
    CHECK(LongestEdge(flat.Get().mMesh) <= 0.3);
    CHECK(flat.Get().mMesh.mTriangles == any.Get().mMesh.mTriangles);
    CHECK(TotalArea(flat.Get().mMesh) == Approx(1.0).epsilon(1e-12));

    // A cube: every triangle has a box edge, bent 90 degrees: nothing is cut, so no vertex lands on a facet
    // off the surface it stands for.
    const TriangleMesh cube = Cube();
    Result<RefinedMesh> kept = RefineLongEdges(cube, 0.3, 4'000'000, two_degrees);
    REQUIRE(kept);
    CHECK(kept.Get().mSplitParents.empty());
    CHECK(kept.Get().mMesh.mTriangles == cube.mTriangles);

    // A half cylinder of 12 facets (15 degrees apart), 2 m long: its long edges along the axis are bent and
    // stay whole; without a bend limit they are cut.
    TriangleMesh tube;
    for (int i = 0; i <= 12; ++i)
    {
        const double angle = std::numbers::pi * i / 12.0;
        tube.mPositions.emplace_back(std::cos(angle), std::sin(angle), 0.0);
        tube.mPositions.emplace_back(std::cos(angle), std::sin(angle), 2.0);
    }
    for (std::uint32_t i = 0; i < 12; ++i)
    {
        tube.mTriangles.push_back({2 * i, 2 * i + 2, 2 * i + 1});
        tube.mTriangles.push_back({2 * i + 1, 2 * i + 2, 2 * i + 3});
    }
    Result<RefinedMesh> tube_kept = RefineLongEdges(tube, 0.3, 4'000'000, two_degrees);
    Result<RefinedMesh> tube_cut = RefineLongEdges(tube, 0.3);
    REQUIRE(tube_kept);
    REQUIRE(tube_cut);
    CHECK(tube_kept.Get().mSplitParents.empty());
    CHECK(LongestEdge(tube_cut.Get().mMesh) <= 0.3);

    // A flat strip of 60 triangles, every edge long, ends at a fold bent 90 degrees: the fold's long edge is
    // kept whole, so the strip's last triangle is, and through their shared long edges every triangle before
    // it, back to the first in the mesh's order (a keep found late travels against the order). Unfolded, the
    // same strip is cut down to the limit.
    TriangleMesh strip;
    constexpr std::uint32_t cColumns = 30;
    for (std::uint32_t i = 0; i <= cColumns; ++i)
    {
        strip.mPositions.emplace_back(double(i), 0.0, 0.0); // 2 i: bottom
        strip.mPositions.emplace_back(double(i), 1.0, 0.0); // 2 i + 1: top
    }
    for (std::uint32_t i = 0; i < cColumns; ++i)
    {
        strip.mTriangles.push_back({2 * i, 2 * i + 2, 2 * i + 1});
        strip.mTriangles.push_back({2 * i + 1, 2 * i + 2, 2 * i + 3});
    }
    Result<RefinedMesh> unfolded = RefineLongEdges(strip, 0.6, 4'000'000, two_degrees);
    REQUIRE(unfolded);
    CHECK(LongestEdge(unfolded.Get().mMesh) <= 0.6);
    strip.mPositions.emplace_back(double(cColumns) + 0.5, 0.5, 1.0); // the fold's apex, above the last column
    const auto apex = static_cast<std::uint32_t>(strip.mPositions.size() - 1);
    strip.mTriangles.push_back({2 * cColumns + 1, 2 * cColumns, apex});
    Result<RefinedMesh> folded = RefineLongEdges(strip, 0.6, 4'000'000, two_degrees);
    REQUIRE(folded);
    CHECK(folded.Get().mSplitParents.empty());
    CHECK(folded.Get().mMesh.mTriangles == strip.mTriangles);

    // Refused: a bend outside [0, pi].
    CHECK_FALSE(RefineLongEdges(square, 0.3, 4'000'000, -0.1));
    CHECK_FALSE(RefineLongEdges(square, 0.3, 4'000'000, 4.0));
    CHECK_FALSE(RefineLongEdges(square, 0.3, 4'000'000, std::numeric_limits<double>::quiet_NaN()));
}
