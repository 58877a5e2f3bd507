// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "BoxMesh.h"
#include "BruteForceProbe.h"
#include "DrawVec3.h"
#include "Slivers.h"
#include "TwoZoneBox.h"

#include <crumple/ffd/FfdDeformer.h>
#include <crumple/plugin/DeformableObjectSettings.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>

using namespace crumple;
using namespace crumple::ffd;

namespace
{

const Vec3 cHalf(2.0, 0.9, 0.7);

// A random probe: a unit direction, axes across it, and a rectangle somewhere over the body (from a sliver
// to wider than the body).
SurfaceProbe RandomProbe(std::mt19937_64& ioRandom)
{
    std::normal_distribution<double> normal;
    std::uniform_real_distribution<double> centre(-1.2, 1.2), width(0.01, 2.5);
    SurfaceProbe probe;
    probe.mDirection = common::DrawVec3([&] { return normal(ioRandom); }).normalized();
    // Half of the probes along a body axis, as crushes mostly are.
    if (ioRandom() % 2 == 0)
        probe.mDirection = Vec3::Unit(static_cast<Eigen::Index>(ioRandom() % 3)) * (ioRandom() % 2 == 0 ? 1.0 : -1.0);
    Eigen::Index least = 0;
    probe.mDirection.cwiseAbs().minCoeff(&least);
    probe.mSide = probe.mDirection.cross(Vec3::Unit(least)).normalized();
    probe.mThird = probe.mDirection.cross(probe.mSide);
    const double s = centre(ioRandom), t = centre(ioRandom), ws = width(ioRandom), wt = width(ioRandom);
    probe.mSideMin = s - 0.5 * ws;
    probe.mSideMax = s + 0.5 * ws;
    probe.mThirdMin = t - 0.5 * wt;
    probe.mThirdMax = t + 0.5 * wt;
    return probe;
}

void CheckSameAsBruteForce(const FfdDeformer& inDeformer, std::mt19937_64& ioRandom, int inProbes, int& ioHits)
{
    for (int i = 0; i < inProbes; ++i)
    {
        const SurfaceProbe probe = RandomProbe(ioRandom);
        const SurfaceProbeResult indexed = inDeformer.ProbeSurface(probe);
        const SurfaceProbeResult reference = common::BruteForceProbe(inDeformer, probe);
        INFO("probe " << i << ": front " << indexed.mFront << " vs " << reference.mFront << ", moved " << indexed.mMoved
                      << " vs " << reference.mMoved);
        // Bit for bit: the same tests on the same values, only fewer of them.
        REQUIRE(indexed.mFront == reference.mFront);
        REQUIRE(indexed.mVertexInside == reference.mVertexInside);
        REQUIRE(indexed.mMoved == reference.mMoved);
        ioHits += std::isfinite(reference.mFront) ? 1 : 0;
    }
}

// One zone over the box from inOrigin of inSize (m), with inControls controls and up to 1 m of deformation.
FfdDeformer OneZoneDeformer(TriangleMesh inMesh, const Vec3& inOrigin, const Vec3& inSize,
                            const std::array<int, 3>& inControls)
{
    FfdDeformerSettings settings;
    FfdZoneSettings zone;
    zone.mLattice.mOrigin = inOrigin;
    zone.mLattice.mSize = inSize;
    zone.mLattice.mControlCount = inControls;
    zone.mMaxTotalDeformation = 1.0;
    settings.mZones = {zone};
    return FfdDeformer::Create(std::move(inMesh), settings).Get();
}

} // namespace

TEST_CASE("ProbeSurface equals a scan of every vertex and triangle, on fine and coarse meshes, dented or not", "[ffd]")
{
    std::mt19937_64 random(3);
    // {segments per axis, split into two zones with a loose rear}: a fine mesh, and a coarse one whose
    // triangles span many cells (a probe often holds no vertex, only triangles across it), with slivers
    // inside so that its probes stay on their cell-by-cell path (12 vertices and 20 triangles alone would
    // scan everything after a cell or two).
    for (const std::array<int, 3>& segments : {std::array<int, 3>{40, 18, 14}, std::array<int, 3>{2, 1, 1}})
    {
        FfdDeformer deformer =
            test::TwoZoneBox(cHalf, segments, {14, 8, 7}, {14, 8, 7}, 0.6, segments[0] == 2 ? 400 : 0);
        int hits = 0;
        CheckSameAsBruteForce(deformer, random, 300, hits);

        // Dents on the front, the sides and the top, and oblique ones, then probes again.
        std::uniform_real_distribution<double> y(-0.85, 0.85), z(-0.65, 0.65), depth(0.05, 0.4);
        for (int dent = 0; dent < 8; ++dent)
        {
            std::vector<PointDisplacement> points;
            for (int i = 0; i < 3; ++i)
            {
                // Draws sequenced, last argument first (common::DrawVec3).
                if (dent % 4 == 0)
                {
                    const double pz = z(random), py = y(random);
                    points.push_back({Vec3(2.0, py, pz), Vec3(-depth(random), 0.0, 0.0)});
                }
                else if (dent % 4 == 1)
                {
                    const double pz = z(random), px = 0.8 * y(random);
                    points.push_back({Vec3(px, 0.9, pz), Vec3(0.0, -depth(random), 0.0)});
                }
                else if (dent % 4 == 2)
                {
                    const double py = y(random), px = 2.0 * y(random);
                    points.push_back({Vec3(px, py, 0.7), Vec3(0.0, 0.0, -depth(random))});
                }
                else
                {
                    // oblique, and outward along x: moves of either sign in every component
                    const double pz = z(random), py = y(random), d = depth(random);
                    points.push_back({Vec3(2.0, py, pz), Vec3(0.5 * d, -0.6 * d, 0.4 * d)});
                }
            }
            REQUIRE(deformer.ApplyDent(points));
            CheckSameAsBruteForce(deformer, random, 100, hits);
        }
        // The state set whole (a loaded damage state) and taken back (a repaired car): the cells' boxes
        // follow a full recompute as they follow a dent.
        std::vector<std::vector<Vec3>> controls;
        for (const FfdLattice& zone : deformer.GetZones())
            controls.push_back(zone.GetControlDisplacements());
        deformer.Reset();
        CheckSameAsBruteForce(deformer, random, 50, hits);
        REQUIRE(deformer.SetControlDisplacements(controls));
        CheckSameAsBruteForce(deformer, random, 50, hits);
        CHECK(hits > 300); // most probes meet the body: the comparison is not over empty answers
    }
}

TEST_CASE("ProbeSurface finds nothing for a probe that is not finite", "[ffd]")
{
    TriangleMesh mesh = common::MakeBoxMesh(cHalf, {8, 4, 4});
    FfdDeformerSettings settings;
    settings.mZones.push_back(plugin::FitZoneToMesh(mesh, {8, 6, 6}, 0.5));
    const FfdDeformer deformer = FfdDeformer::Create(std::move(mesh), settings).Get();
    SurfaceProbe probe;
    probe.mSideMin = probe.mThirdMin = -1.0;
    probe.mSideMax = probe.mThirdMax = 1.0;
    CHECK(deformer.ProbeSurface(probe).mFront == -2.0); // the rear face, seen along +x
    probe.mSideMax = std::numeric_limits<double>::quiet_NaN();
    CHECK(std::isinf(deformer.ProbeSurface(probe).mFront));
}

TEST_CASE("ProbeSurface bounds a cell by how far its stored positions moved, not by the displacement", "[ffd]")
{
    // Review finding: a displacement of 1e-16 m added to a rest coordinate of 1 rounds to a move of 2.2e-16 m.
    // A cell bound taken from the displacement let the probe skip that vertex behind the front (probe 'moved'
    // 1.39e-16 against the scan's 2.22e-16). Two small triangles across the probe at x = 0.1 and x = 1, and
    // 200 slivers elsewhere so the probe stays in its cell-by-cell path.
    TriangleMesh mesh;
    auto add = [&](const Vec3& inPoint) {
        mesh.mPositions.push_back(inPoint);
        return static_cast<std::uint32_t>(mesh.mPositions.size() - 1);
    };
    const std::uint32_t w = add({0.1, 0.0, 0.0}), a = add({0.1, 0.4, 0.01}), b = add({0.1, -0.4, 0.01});
    const std::uint32_t v = add({1.0, 0.0, 0.0}), c = add({1.0, 0.4, 0.01}), e = add({1.0, -0.4, 0.01});
    mesh.mTriangles = {{w, a, b}, {v, c, e}};
    test::AddSlivers(mesh, Vec3(0.05, 0.45, 0.3), 1.9, 200);
    FfdDeformer deformer =
        OneZoneDeformer(std::move(mesh), Vec3(0.0, -0.5, -0.5), Vec3(2.0, 1.0, 1.0), {8, 4, 4});
    const FfdLattice& lattice = deformer.GetZones()[0];
    std::vector<int> controls;
    for (int k = 0; k < 4; ++k)
        for (int j = 0; j < 4; ++j)
            for (int i = 0; i < 8; ++i)
                controls.push_back(lattice.ControlIndex(i, j, k));
    std::sort(controls.begin(), controls.end());
    Eigen::MatrixX3d delta = Eigen::MatrixX3d::Zero(static_cast<Eigen::Index>(controls.size()), 3);
    for (std::size_t n = 0; n < controls.size(); ++n)
        delta(static_cast<Eigen::Index>(n), 0) = 1.2e-16 / 1.15 * (1.5 - 0.1 * (controls[n] % 8));
    REQUIRE(deformer.ApplyControlDelta(0, controls, delta));
    SurfaceProbe probe;
    probe.mSideMin = probe.mThirdMin = -0.1;
    probe.mSideMax = probe.mThirdMax = 0.1;
    const SurfaceProbeResult indexed = deformer.ProbeSurface(probe);
    const SurfaceProbeResult reference = common::BruteForceProbe(deformer, probe);
    CHECK(indexed.mFront == reference.mFront);
    CHECK(indexed.mVertexInside == reference.mVertexInside);
    CHECK(indexed.mMoved == reference.mMoved);
    CHECK(reference.mMoved > 0.0);
}

TEST_CASE("ProbeSurface finds a triangle whose corner in no zone stayed while the cell's vertices moved away",
          "[ffd]")
{
    // A triangle with two corners in a zone (x = 0.5) and one outside every zone (x = 0, which never moves).
    // The zone's vertices all move +0.3 m along x, so the triangle now spans x from 0 to 0.8: a probe at x in
    // [0.1, 0.2] meets it near its loose corner, which the cell's rest box moved by its vertices' move alone
    // (x from 0.3) would rule out. 200 slivers elsewhere in the zone keep the probe on its cell-by-cell path.
    TriangleMesh mesh;
    auto add = [&](const Vec3& inPoint)
    {
        mesh.mPositions.push_back(inPoint);
        return static_cast<std::uint32_t>(mesh.mPositions.size() - 1);
    };
    const std::uint32_t a = add({0.5, 0.0, 0.0}), b = add({0.5, 1.0, 0.0}), c = add({0.0, 0.5, 0.0});
    mesh.mTriangles = {{a, b, c}};
    test::AddSlivers(mesh, Vec3(0.45, 1.4, 0.4), 0.5, 200);
    FfdDeformer deformer =
        OneZoneDeformer(std::move(mesh), Vec3(0.4, -0.5, -0.5), Vec3(0.6, 2.0, 1.0), {4, 4, 4});
    REQUIRE(deformer.GetVertexZone(c) == -1);
    REQUIRE(deformer.GetVertexZone(a) == 0);
    std::vector<int> controls(static_cast<std::size_t>(deformer.GetZones()[0].GetControlCount()));
    for (std::size_t n = 0; n < controls.size(); ++n)
        controls[n] = static_cast<int>(n);
    Eigen::MatrixX3d delta = Eigen::MatrixX3d::Zero(static_cast<Eigen::Index>(controls.size()), 3);
    delta.col(0).setConstant(0.3);
    REQUIRE(deformer.ApplyControlDelta(0, controls, delta));
    REQUIRE(deformer.GetCurrentPositions()[a].x() > 0.79);

    SurfaceProbe probe;
    probe.mDirection = Vec3::UnitZ();
    probe.mSide = Vec3::UnitX();
    probe.mThird = Vec3::UnitY();
    probe.mSideMin = 0.1;
    probe.mSideMax = 0.2;
    probe.mThirdMin = 0.4;
    probe.mThirdMax = 0.6;
    const SurfaceProbeResult indexed = deformer.ProbeSurface(probe);
    const SurfaceProbeResult reference = common::BruteForceProbe(deformer, probe);
    CHECK(reference.mFront == 0.0); // the triangle is met
    CHECK(indexed.mFront == reference.mFront);
    CHECK(indexed.mVertexInside == reference.mVertexInside);
    CHECK(indexed.mMoved == reference.mMoved);
}
