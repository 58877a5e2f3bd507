// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "TwoZoneBox.h"

#include <crumple/ffd/FfdDeformer.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <limits>
#include <random>
#include <vector>

using namespace crumple;
using namespace crumple::ffd;

TEST_CASE("Vertex groups hand over every vertex once, each group with the exact box of its current positions",
          "[ffd]")
{
    // Two zones and a loose rear (TwoZoneBox), dented at random points so cells have moved by different amounts.
    const Vec3 half(2.0, 0.9, 0.7);
    FfdDeformer deformer = test::TwoZoneBox(half, {40, 18, 14}, {8, 6, 5}, {6, 5, 5}, 0.8);
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int dent = 0; dent < 4; ++dent)
    {
        // sequenced, last argument first (common::DrawVec3)
        const double z = half.z() * (2.0 * unit(random) - 1.0), x = half.x() - 1.2 * unit(random);
        const PointDisplacement push{Vec3(x, half.y(), z), Vec3(0.0, -0.2 * unit(random), 0.05)};
        REQUIRE(deformer.ApplyDent(std::span<const PointDisplacement>(&push, 1)));
    }
    // Each group's box against its vertices' current positions; inMovedAtLeast..inMovedAtMost groups' boxes
    // differ from their rest boxes.
    const auto check = [&](int inMovedAtLeast, int inMovedAtMost)
    {
        const std::vector<Vec3>& positions = deformer.GetCurrentPositions();
        for (const Vec3& along : {Vec3(-1.0, 0.0, 0.0), Vec3(0.3, 0.9, -0.2).normalized()})
        {
            std::vector<int> seen(positions.size(), 0);
            int groups = 0, unbounded = 0, moved_groups = 0, outside = 0, loose_moved = 0, not_tight = 0;
            deformer.ForEachVertexGroup(
                along,
                [&](const VertexGroup& inGroup)
                {
                    ++groups;
                    unbounded += inGroup.mBounded ? 0 : 1;
                    Vec3 low = Vec3::Constant(std::numeric_limits<double>::infinity()), high = -low;
                    Vec3 rest_low = low, rest_high = high;
                    for (std::uint32_t v : inGroup.mVertices)
                    {
                        ++seen[v];
                        if (!inGroup.mBounded)
                        {
                            loose_moved +=
                                positions[v] == deformer.GetRestMesh().mPositions[v] ? 0 : 1; // never moved
                            continue;
                        }
                        // Distance from the box, which must not exceed the bound.
                        const Vec3 nearest = positions[v].cwiseMax(inGroup.mLow).cwiseMin(inGroup.mHigh);
                        outside += (positions[v] - nearest).norm() <= inGroup.mMoved ? 0 : 1;
                        low = low.cwiseMin(positions[v]);
                        high = high.cwiseMax(positions[v]);
                        rest_low = rest_low.cwiseMin(deformer.GetRestMesh().mPositions[v]);
                        rest_high = rest_high.cwiseMax(deformer.GetRestMesh().mPositions[v]);
                    }
                    if (!inGroup.mBounded)
                        return;
                    // intent: the box is the positions' own (exact: a scan's skip tests need no widening for
                    // a move)
                    not_tight +=
                        low == inGroup.mLow && high == inGroup.mHigh && inGroup.mMoved == 0.0 ? 0 : 1;
                    moved_groups += low == rest_low && high == rest_high ? 0 : 1;
                });
            CHECK(std::all_of(seen.begin(), seen.end(), [](int inCount) { return inCount == 1; }));
            CHECK(outside == 0);
            CHECK(loose_moved == 0);
            CHECK(not_tight == 0);
            CHECK(unbounded == 1); // the rear 0.2 m
            // the two lattices hold 5 x 3 x 2 and 3 x 2 x 2 cells, each with vertices, and the rear
            CHECK(groups == 43);
            CHECK(moved_groups >= inMovedAtLeast);
            CHECK(moved_groups <= inMovedAtMost);
        }
    };
    check(11, 42); // the dents moved some cells: their boxes follow, not the rest box
    // A repaired car (a full recompute) has its rest boxes back; a loaded state its dents' boxes again.
    std::vector<std::vector<Vec3>> controls;
    for (const FfdLattice& zone : deformer.GetZones())
        controls.push_back(zone.GetControlDisplacements());
    deformer.Reset();
    check(0, 0);
    REQUIRE(deformer.SetControlDisplacements(controls));
    check(11, 42);
}
