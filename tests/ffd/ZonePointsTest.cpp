// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// White-box: ZonePointSet merges each point into the first earlier kept point closer than the merge distance
// (max norm, in cells), exactly as the linear scan it replaced, point for point; ThinZonePoints merges what
// is left on coarser bins until it fits and keeps the weighted means.
#include "ZonePoints.h"
#include "DrawVec3.h"

#include <catch2/catch.hpp>

#include <cstring>
#include <random>

using namespace crumple;
using namespace crumple::ffd;

namespace
{

// The scan ZonePointSet replaced (FfdDeformer::ApplyDent before 946e45a).
std::vector<ZonePoint> Scan(const std::vector<std::pair<Vec3, Vec3>>& inPoints, double inMergeDistance)
{
    std::vector<ZonePoint> points;
    for (const auto& point : inPoints)
    {
        // intent: named, not structured bindings: clang 14 refuses to capture those in a lambda
        const Vec3& lattice = point.first;
        const Vec3& displacement = point.second;
        auto near = std::find_if(points.begin(), points.end(), [&](const ZonePoint& p) {
            return (p.mLattice - lattice).cwiseAbs().maxCoeff() < inMergeDistance;
        });
        if (near != points.end())
        {
            ++near->mMergedCount;
            near->mDisplacement += (displacement - near->mDisplacement) / near->mMergedCount;
        }
        else
            points.push_back({lattice, displacement, 1});
    }
    return points;
}

bool SameBytes(const Vec3& inA, const Vec3& inB)
{
    return std::memcmp(inA.data(), inB.data(), sizeof(Vec3)) == 0;
}

} // namespace

TEST_CASE("ZonePointSet merges as the linear scan does, point for point and bit for bit", "[ffd]")
{
    std::mt19937 random(3u);
    // Clustered points (many near-coincident) with distinct displacements, on a lattice of 12 cells per axis.
    std::uniform_real_distribution<double> centre(0.0, 12.0), jitter(-0.3, 0.3), push(-0.05, 0.05);
    std::vector<std::pair<Vec3, Vec3>> input;
    for (int cluster = 0; cluster < 60; ++cluster)
    {
        const Vec3 middle = common::DrawVec3([&] { return centre(random); });
        for (int i = 0; i < 12; ++i)
            input.push_back({middle + common::DrawVec3([&] { return jitter(random); }),
                             common::DrawVec3([&] { return push(random); })});
    }
    for (double merge : {0.0, 0.05, 0.1, 0.35, 0.999})
    {
        ZonePointSet set(merge);
        int merged = 0;
        for (const auto& [lattice, displacement] : input)
            merged += set.Add(lattice, displacement) ? 1 : 0;
        const std::vector<ZonePoint> expected = Scan(input, merge);
        const std::vector<ZonePoint>& got = set.GetPoints();
        INFO("merge distance " << merge << " cells");
        REQUIRE(got.size() == expected.size());
        CHECK(merged == static_cast<int>(input.size() - expected.size()));
        bool same = true;
        for (std::size_t i = 0; i < got.size(); ++i)
            same = same && SameBytes(got[i].mLattice, expected[i].mLattice) &&
                   SameBytes(got[i].mDisplacement, expected[i].mDisplacement) && got[i].mMergedCount == expected[i].mMergedCount;
        CHECK(same);
    }
}

TEST_CASE("ThinZonePoints fits a zone's points under the cap with their weighted means, and leaves fewer alone", "[ffd]")
{
    std::mt19937 random(5u);
    std::uniform_real_distribution<double> coordinate(0.0, 16.0), push(-0.1, 0.0);
    std::vector<ZonePoint> points;
    Vec3 weighted_sum = Vec3::Zero();
    int weight = 0;
    for (int i = 0; i < 5000; ++i)
    {
        const double y = coordinate(random),
                     x = coordinate(random); // sequenced, last argument first (common::DrawVec3)
        const ZonePoint point{Vec3(x, y, 0.5), Vec3(push(random), 0.0, 0.0), 1 + i % 3};
        weighted_sum += point.mMergedCount * point.mDisplacement;
        weight += point.mMergedCount;
        points.push_back(point);
    }
    const std::size_t before = points.size();
    const int merged = ThinZonePoints(points);
    CHECK(points.size() <= cMaxZonePoints);
    CHECK(merged == static_cast<int>(before - points.size()));
    // Every original point is in exactly one merged point: the counts and the weighted displacement add up.
    int total = 0;
    Vec3 sum = Vec3::Zero();
    for (const ZonePoint& point : points)
    {
        total += point.mMergedCount;
        sum += point.mMergedCount * point.mDisplacement;
    }
    CHECK(total == weight);
    CHECK((sum - weighted_sum).norm() <= 1.0e-9 * weighted_sum.norm());

    std::vector<ZonePoint> few(points.begin(), points.begin() + 10);
    const std::vector<ZonePoint> copy = few;
    CHECK(ThinZonePoints(few) == 0);
    CHECK(few.size() == copy.size());
}
