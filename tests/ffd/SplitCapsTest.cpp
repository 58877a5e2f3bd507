// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// SplitCaps: a cap on a crease, which no flip may remove, is split at its foot; the surface keeps its shape
// exactly and stays closed, a seam's sides keep their own vertices, and a pole's pocket that turned the cap
// over turns none of its pieces.
#include "BoxMesh.h"
#include "MeshChecks.h"

#include <crumple/ffd/FlipFlatEdges.h>
#include <crumple/ffd/SplitCaps.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <random>
#include <set>

using namespace crumple;
using namespace crumple::ffd;
using namespace crumple::ffd::test;

namespace
{

constexpr double cCapAngle = 150.0 * std::numbers::pi / 180.0;

// A car's front lip as the Toy Car's exporter cut it: the flat top of the bumper (z = 0, normal +z) ends at a
// crease along y (x = 0), where a bevel leans forward and down to the bumper's front. The bevel is one cap,
// 15 cm long and 4 mm deep, its far corner 3 mm below the top: a 174-degree corner.
//   0 (0, -0.075, 0), 1 (0, 0.075, 0): the crease;  2 (0.004, 0, -0.003): the cap's far corner;
//   3 (-0.1, 0, 0): the top behind
TriangleMesh Lip()
{
    TriangleMesh mesh;
    mesh.mPositions = {Vec3(0.0, -0.075, 0.0), Vec3(0.0, 0.075, 0.0), Vec3(0.004, 0.0, -0.003),
                       Vec3(-0.1, 0.0, 0.0)};
    mesh.mTriangles = {{0, 1, 3}, {1, 0, 2}};
    return mesh;
}

// Every added vertex lies where its parents and fraction say, and on the segment between them.
void CheckAddedVertices(const RefinedMesh& inRefined)
{
    const std::vector<Vec3>& p = inRefined.mMesh.mPositions;
    REQUIRE(inRefined.mSplitFractions.size() == inRefined.mSplitParents.size());
    const std::size_t first = p.size() - inRefined.mSplitParents.size();
    for (std::size_t k = 0; k < inRefined.mSplitParents.size(); ++k)
    {
        const auto [a, b] = inRefined.mSplitParents[k];
        const double f = inRefined.mSplitFractions[k];
        CHECK(f > 0.0);
        CHECK(f < 1.0);
        const Vec3 expected = (1.0 - f) * p[a] + f * p[b];
        CHECK((p[first + k] - expected).norm() <= 1e-15 * (1.0 + p[a].norm() + p[b].norm()));
        CHECK((p[first + k] - p[a]).cross(p[b] - p[a]).norm() <= 1e-15 * (p[b] - p[a]).squaredNorm());
    }
}

} // namespace

TEST_CASE("SplitCaps: a cap on a crease, which no flip may remove, becomes two right triangles", "[ffd]")
{
    const TriangleMesh lip = Lip();
    // the premises: the cap turns over in a pole's pocket that folds nothing (its far corner ends up behind
    // the crease), and no flip takes it out (the crease is 3 mm deep, over a millimetre's deviation)
    CHECK(TurnedOver(lip, Pocket(lip)) == 1);
    TriangleMesh flipped = lip;
    REQUIRE(FlipNearlyFlatEdges(flipped, 0.001, true, cCapAngle).Get() == 0);

    Result<RefinedMesh> split = SplitCaps(lip, cCapAngle);
    REQUIRE(split);
    const RefinedMesh& r = split.Get();
    // intent: one vertex at the cap's foot (0, 0, 0) on the crease, the cap and the top each cut there
    REQUIRE(r.mSplitParents.size() == 1);
    CHECK(r.mMesh.mPositions.back() == Vec3(0.0, 0.0, 0.0));
    CHECK(r.mSplitParents[0] == std::array<std::uint32_t, 2>{0, 1});
    CHECK(r.mSplitFractions[0] == Approx(0.5).epsilon(1e-15));
    CHECK(r.mMesh.mTriangles.size() == lip.mTriangles.size() + 2);
    CheckAddedVertices(r);
    CHECK(TotalArea(r.mMesh) == Approx(TotalArea(lip)).epsilon(1e-14));
    CHECK(CornerAngleRange(r.mMesh).mLargest < cCapAngle);
    CHECK(TurnedOver(r.mMesh, Pocket(r.mMesh)) == 0);
    // every piece lies in its triangle's plane, facing the same way
    const Vec3 top = AreaVector(lip, lip.mTriangles[0]).normalized(),
               bevel = AreaVector(lip, lip.mTriangles[1]).normalized();
    for (const auto& t : r.mMesh.mTriangles)
    {
        const Vec3 normal = AreaVector(r.mMesh, t).normalized();
        CHECK(std::max(normal.dot(top), normal.dot(bevel)) > 1.0 - 1e-12);
    }
}

TEST_CASE("SplitCaps: a cap off the middle splits at its own foot, and a closed solid stays closed", "[ffd]")
{
    // A tetrahedron whose bottom face (0, 1, 2) is a cap: its far corner 3 mm off the long edge, 0.3 m from
    // its first end (a 172-degree corner).
    TriangleMesh solid;
    solid.mPositions = {Vec3(-0.5, 0.0, 0.0), Vec3(0.5, 0.0, 0.0), Vec3(-0.2, 0.003, 0.0),
                        Vec3(0.0, 0.3, 0.4)};
    solid.mTriangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
    REQUIRE(IsClosedManifold(solid));
    REQUIRE(CornerAngleRange(solid).mLargest > cCapAngle);

    Result<RefinedMesh> split = SplitCaps(solid, cCapAngle);
    REQUIRE(split);
    const RefinedMesh& r = split.Get();
    REQUIRE(r.mSplitParents.size() == 1);
    CHECK(r.mSplitFractions[0] == Approx(0.3).epsilon(1e-12));
    CHECK((r.mMesh.mPositions.back() - Vec3(-0.2, 0.0, 0.0)).norm() < 1e-15);
    CheckAddedVertices(r);
    CHECK(IsClosedManifold(r.mMesh));
    CHECK(TotalArea(r.mMesh) == Approx(TotalArea(solid)).epsilon(1e-14));
    CHECK(CornerAngleRange(r.mMesh).mLargest < cCapAngle);

    SECTION("the same input gives the same mesh; a mesh without caps comes back as it was")
    {
        Result<RefinedMesh> again = SplitCaps(solid, cCapAngle);
        REQUIRE(again);
        CHECK(again.Get().mMesh.mPositions == r.mMesh.mPositions);
        CHECK(again.Get().mMesh.mTriangles == r.mMesh.mTriangles);
        Result<RefinedMesh> none = SplitCaps(r.mMesh, cCapAngle);
        REQUIRE(none);
        CHECK(none.Get().mSplitParents.empty());
        CHECK(none.Get().mMesh.mPositions == r.mMesh.mPositions);
        CHECK(none.Get().mMesh.mTriangles == r.mMesh.mTriangles);
    }
}

TEST_CASE("SplitCaps: a seam's other side is split at the same point with a vertex of its own", "[ffd]")
{
    // The lip with the crease a hard edge: the top has its own copies 4 and 5 of the crease's ends.
    TriangleMesh lip = Lip();
    lip.mPositions.push_back(lip.mPositions[0]);
    lip.mPositions.push_back(lip.mPositions[1]);
    lip.mTriangles[0] = {4, 5, 3};
    Result<RefinedMesh> split = SplitCaps(lip, cCapAngle);
    REQUIRE(split);
    const RefinedMesh& r = split.Get();
    REQUIRE(r.mSplitParents.size() == 2);
    CheckAddedVertices(r);
    const std::size_t first = r.mMesh.mPositions.size() - 2;
    CHECK(r.mMesh.mPositions[first] == r.mMesh.mPositions[first + 1]); // bit for bit: the seam stays closed
    // intent: no triangle takes vertices from both sides (a textured mesh keeps each side's coordinates)
    const std::set<std::uint32_t> bevel = {0, 1, 2}, top = {3, 4, 5};
    for (const auto& t : r.mMesh.mTriangles)
    {
        int on_bevel = 0, on_top = 0;
        for (std::uint32_t v : t)
        {
            const std::uint32_t parent = v < first ? v : r.mSplitParents[v - first][0];
            on_bevel += bevel.count(parent) ? 1 : 0;
            on_top += top.count(parent) ? 1 : 0;
        }
        CHECK((on_bevel == 3 || on_top == 3));
    }
    CHECK(TurnedOver(r.mMesh, Pocket(r.mMesh)) == 0);
}

TEST_CASE("SplitCaps: bad input is refused with a reason", "[ffd]")
{
    const TriangleMesh lip = Lip();
    for (double bad : {0.0, 1.5, std::numbers::pi + 1e-9, std::numeric_limits<double>::quiet_NaN()})
    {
        Result<RefinedMesh> refused = SplitCaps(lip, bad);
        REQUIRE_FALSE(refused);
        CHECK(refused.GetError().mMessage.find("cap angle") != std::string::npos);
    }
    TriangleMesh broken = lip;
    broken.mTriangles.push_back({0, 1, 99});
    CHECK_FALSE(SplitCaps(broken, cCapAngle));
    TriangleMesh not_finite = lip;
    not_finite.mPositions[3].x() = std::numeric_limits<double>::infinity();
    CHECK_FALSE(SplitCaps(not_finite, cCapAngle));
}

namespace
{

// Caps as SplitCaps takes them: a corner of at least the cap angle, the far corner off the long edge by more
// than 1e-9 of its length (closer is a degenerate triangle, which it leaves).
int CountCaps(const TriangleMesh& inMesh)
{
    int caps = 0;
    for (const auto& t : inMesh.mTriangles)
    {
        TriangleMesh one;
        one.mPositions = {inMesh.mPositions[t[0]], inMesh.mPositions[t[1]], inMesh.mPositions[t[2]]};
        one.mTriangles = {{0, 1, 2}};
        double longest = 0.0;
        for (int k = 0; k < 3; ++k)
            longest = std::max(longest, (one.mPositions[(k + 1) % 3] - one.mPositions[k]).norm());
        const double height = 2.0 * AreaVector(one, one.mTriangles[0]).norm() / longest;
        caps += height > 1e-9 * longest && CornerAngleRange(one).mLargest >= cCapAngle ? 1 : 0;
    }
    return caps;
}

// Every directed edge's reverse is there, by position: a surface closed across its seams.
bool IsClosedByPosition(const TriangleMesh& inMesh)
{
    auto key = [&](std::uint32_t inA, std::uint32_t inB)
    {
        const Vec3& a = inMesh.mPositions[inA];
        const Vec3& b = inMesh.mPositions[inB];
        return std::array<double, 6>{a.x(), a.y(), a.z(), b.x(), b.y(), b.z()};
    };
    std::map<std::array<double, 6>, int> directed;
    for (const auto& t : inMesh.mTriangles)
        for (int k = 0; k < 3; ++k)
            ++directed[key(t[k], t[(k + 1) % 3])];
    for (const auto& t : inMesh.mTriangles)
        for (int k = 0; k < 3; ++k)
            if (directed[key(t[(k + 1) % 3], t[k])] != directed[key(t[k], t[(k + 1) % 3])])
                return false;
    return true;
}

} // namespace

TEST_CASE("SplitCaps stress: random boxes full of caps and seams stay valid, closed and of the same area, "
          "and lose every cap",
          "[ffd]")
{
    // A subdivided box whose grid vertices are pulled, at random, onto the line through two of their
    // neighbours (caps of exactly 180 degrees, degenerate), or to within a millimetre of it (caps), at every
    // scale from a millimetre to ten kilometres; one face's vertices split from the rest (a seam).
    std::mt19937_64 random(2026);
    for (int trial = 0; trial < 24; ++trial)
    {
        const double scale = std::pow(10.0, -3.0 + 7.0 * (trial % 8) / 7.0);
        TriangleMesh mesh = common::MakeBoxMesh(Vec3(2.0, 0.9, 0.7) * scale, {9, 5, 4});
        std::uniform_int_distribution<std::size_t> pick(0, mesh.mTriangles.size() - 1);
        std::uniform_real_distribution<double> offset(-1e-3, 1e-3), along(0.2, 0.8);
        for (int pull = 0; pull < 40; ++pull)
        {
            const auto& t = mesh.mTriangles[pick(random)];
            const Vec3 a = mesh.mPositions[t[1]], b = mesh.mPositions[t[2]];
            const Vec3 on_line = a + along(random) * (b - a);
            // intent: the same plane (the box's faces are flat), so the surface stays a box
            Vec3 moved = on_line + (pull % 2 == 0 ? 0.0 : offset(random) * scale) * (b - a).normalized();
            const Vec3 before = mesh.mPositions[t[0]];
            for (int axis = 0; axis < 3; ++axis)
                if (std::abs(std::abs(before[axis]) - std::abs(mesh.mPositions[t[1]][axis])) == 0.0 &&
                    std::abs(std::abs(before[axis]) - std::abs(mesh.mPositions[t[2]][axis])) == 0.0)
                    moved[axis] = before[axis];
            mesh.mPositions[t[0]] = moved;
        }
        if (trial % 3 == 0)
        {
            // intent: the +x face's triangles take their own copies of their vertices (a hard edge)
            std::map<std::uint32_t, std::uint32_t> copy;
            for (auto& t : mesh.mTriangles)
            {
                const Vec3 centre =
                    (mesh.mPositions[t[0]] + mesh.mPositions[t[1]] + mesh.mPositions[t[2]]) / 3.0;
                if (!(centre.x() > 1.999 * scale))
                    continue;
                for (std::uint32_t& v : t)
                {
                    const auto [it, added] =
                        copy.try_emplace(v, static_cast<std::uint32_t>(mesh.mPositions.size()));
                    if (added)
                        mesh.mPositions.push_back(mesh.mPositions[v]);
                    v = it->second;
                }
            }
        }
        INFO("trial " << trial << ", scale " << scale << " m, " << CountCaps(mesh) << " caps");
        REQUIRE(IsClosedByPosition(mesh));
        REQUIRE(CountCaps(mesh) > 0); // the premise
        const double area = TotalArea(mesh);
        TriangleMesh cut = mesh;
        int rounds = 0;
        for (; rounds < 16; ++rounds)
        {
            Result<RefinedMesh> split = SplitCaps(cut, cCapAngle);
            REQUIRE(split);
            CheckAddedVertices(split.Get());
            if (split.Get().mSplitParents.empty())
                break;
            cut = split.Get().mMesh;
            REQUIRE(ValidateTriangleMesh(cut));
            REQUIRE(FlipNearlyFlatEdges(cut, 1e-3 * scale, true, cCapAngle));
        }
        INFO(rounds << " rounds, " << CountCaps(cut) << " caps left");
        CHECK(ValidateTriangleMesh(cut));
        CHECK(TotalArea(cut) == Approx(area).epsilon(1e-9));
        CHECK(IsClosedByPosition(cut));
        CHECK(CountCaps(cut) == 0); // measured: 2-11 caps each, none left after 1-5 rounds
    }
}
