// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Math.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace crumple::ffd
{

/// A constrained point of a dent after zone assignment and merging.
struct ZonePoint
{
    Vec3 mLattice;        ///< Rest lattice coordinate (cells)
    Vec3 mDisplacement;   ///< Wanted displacement (m), averaged over the points merged into it
    int mMergedCount = 1; ///< How many of the dent's points it stands for
};

/// The constrained points of one zone, each new point merged into the first earlier one (in the order they
/// were added) closer than the merge distance in lattice cells (max norm), its displacement averaged in.
/// A grid of buckets one merge distance wide finds that point among the 27 buckets around the new one, so a
/// dent of n points costs O(n) instead of a scan of every earlier point (O(n^2): 16,000 contacts of a long
/// collision window took seconds). The result is the scan's, point for point.
class ZonePointSet
{
public:
    explicit ZonePointSet(double inMergeDistance) : mMergeDistance(inMergeDistance) {}

    /// Adds a point; returns true when it was merged into an earlier one.
    bool Add(const Vec3& inLattice, const Vec3& inDisplacement);
    /// The points, in the order they were first added
    std::vector<ZonePoint>& GetPoints() { return mPoints; }

private:
    using Key = std::array<std::int64_t, 3>;
    struct KeyHash
    {
        std::size_t operator()(const Key& inKey) const;
    };
    Key BucketOf(const Vec3& inLattice) const;

    double mMergeDistance;
    std::vector<ZonePoint> mPoints;
    std::unordered_map<Key, std::vector<std::size_t>, KeyHash> mBuckets; // point indices, ascending
};

/// Most constrained points one zone solves in one dent. The direct-manipulation solve costs O(points^2 +
/// points rank^2) (DirectManipulation.h): measured on a 24 x 24 x 6 lattice over a flat 4 x 2 m sheet, 512
/// points took 56 ms, 1,024 130 ms, 2,048 256 ms and 4,096 4.7 s.
constexpr std::size_t cMaxZonePoints = 1024;

/// Merges ioPoints on a grid of lattice bins, 1/4 cell wide and doubled until at most cMaxZonePoints are
/// left (a cubic B-spline cannot follow detail finer than its cells): each bin's points become one at their
/// mean lattice coordinate with their mean displacement, weighted by how many points each stands for, in the
/// order of each bin's first point. Nothing changes when there are no more than cMaxZonePoints. Returns how
/// many points were merged away.
int ThinZonePoints(std::vector<ZonePoint>& ioPoints);

} // namespace crumple::ffd
