// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// The constrained points of a dent: near-coincident ones merge as a scan over the earlier points would
// merge them, and a dent of thousands of points (a long collision window's contacts) is merged down to a
// bounded number per zone instead of a solve that grows with their square (8,000 points took 35 s).
#include "BoxMesh.h"

#include <crumple/ffd/FfdDeformer.h>
#include <crumple/plugin/DeformableObjectSettings.h>

#include <catch2/catch.hpp>

#include <random>

using namespace crumple;
using namespace crumple::ffd;

namespace
{

const Vec3 cHalf(2.0, 0.9, 0.7);

FfdDeformer MakeBoxDeformer(double inMergeDistance)
{
    TriangleMesh mesh = common::MakeBoxMesh(cHalf, {40, 18, 14});
    FfdDeformerSettings settings;
    settings.mZones.push_back(plugin::FitZoneToMesh(mesh, {8, 6, 6}, 0.5));
    settings.mMergeDistance = inMergeDistance;
    return FfdDeformer::Create(std::move(mesh), settings).Get();
}

// inCount points on the front face (x = +2) within inHalfWidth of its centre, pushed back by inDepth.
std::vector<PointDisplacement> FrontPoints(int inCount, double inHalfWidth, double inDepth, std::uint32_t inSeed)
{
    std::mt19937 random(inSeed);
    std::uniform_real_distribution<double> across(-inHalfWidth, inHalfWidth);
    std::vector<PointDisplacement> points;
    for (int i = 0; i < inCount; ++i)
    {
        const double z = across(random),
                     y = across(random); // sequenced, last argument first (common::DrawVec3)
        points.push_back({Vec3(2.0, y, z), Vec3(-inDepth, 0.0, 0.0)});
    }
    return points;
}

} // namespace

TEST_CASE("Dent points merge into the first earlier point closer than the merge distance, as a scan finds it", "[ffd]")
{
    for (double merge : {0.0, 0.1, 0.5, 0.9})
    {
        FfdDeformer deformer = MakeBoxDeformer(merge);
        const FfdLattice& zone = deformer.GetZones()[0];
        const std::vector<PointDisplacement> points = FrontPoints(700, 0.6, 0.01, 7);
        // The reference: each point against every earlier kept point, in order (the rest lattice coordinate of
        // an undented deformer is the lattice coordinate itself).
        std::vector<Vec3> kept;
        int merged = 0;
        for (const PointDisplacement& point : points)
        {
            const Vec3 u = zone.LatticeCoordinate(point.mPoint);
            bool near = false;
            for (const Vec3& k : kept)
                near = near || (k - u).cwiseAbs().maxCoeff() < merge;
            if (near)
                ++merged;
            else
                kept.push_back(u);
        }
        const Result<DentReport> report = deformer.ApplyDent(points);
        REQUIRE(report);
        INFO("merge distance " << merge << " cells: " << kept.size() << " kept by the scan");
        CHECK(report.Get().mPointsMerged == merged);
        CHECK(report.Get().mPointsApplied == static_cast<int>(kept.size()));
    }
}

TEST_CASE("A dent of 8,000 points is merged to at most 1,024 per zone and still moves the face as asked", "[ffd]")
{
    FfdDeformer deformer = MakeBoxDeformer(0.0); // no merging of near points: every point reaches the solve
    const double depth = 0.02;
    const std::vector<PointDisplacement> points = FrontPoints(8000, 0.5, depth, 11);
    const Result<DentReport> report = deformer.ApplyDent(points);
    REQUIRE(report);
    INFO("applied " << report.Get().mPointsApplied << ", merged " << report.Get().mPointsMerged << ", largest point error "
                    << report.Get().mMaxPointError << " m");
    CHECK(report.Get().mPointsApplied <= 1024);
    CHECK(report.Get().mPointsApplied + report.Get().mPointsMerged == 8000);
    // A uniform push is a uniform shift of the controls that reach the points (the weights sum to one), so the
    // merged points are met exactly, up to the solve's rank tolerance.
    CHECK(report.Get().mMaxPointError <= 1.0e-3 * depth);
    // The vertices of the face's middle moved back by the depth.
    const std::vector<Vec3>& rest = deformer.GetRestMesh().mPositions;
    const std::vector<Vec3>& now = deformer.GetPositions();
    int middle = 0;
    for (std::size_t v = 0; v < rest.size(); ++v)
        if (rest[v].x() > 1.999 && std::abs(rest[v].y()) < 0.3 && std::abs(rest[v].z()) < 0.3)
        {
            ++middle;
            CHECK(std::abs((now[v] - rest[v]).x() + depth) <= 1.0e-3 * depth);
        }
    CHECK(middle > 10);
}
