// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "ZonePoints.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace crumple::ffd
{

std::size_t ZonePointSet::KeyHash::operator()(const Key& inKey) const
{
    // Large odd multipliers spread neighbouring buckets (Teschner et al. 2003, spatial hashing).
    const auto x = static_cast<std::uint64_t>(inKey[0]), y = static_cast<std::uint64_t>(inKey[1]),
               z = static_cast<std::uint64_t>(inKey[2]);
    return static_cast<std::size_t>((x * 73856093u) ^ (y * 19349663u) ^ (z * 83492791u));
}

ZonePointSet::Key ZonePointSet::BucketOf(const Vec3& inLattice) const
{
    // intent: clamped so that a tiny merge distance cannot overflow the conversion; points beyond the clamp share
    // a bucket, which costs time and changes no answer (the distance itself is checked)
    Key key;
    for (int axis = 0; axis < 3; ++axis)
        key[axis] = static_cast<std::int64_t>(std::clamp(std::floor(inLattice[axis] / mMergeDistance), -1.0e18, 1.0e18));
    return key;
}

bool ZonePointSet::Add(const Vec3& inLattice, const Vec3& inDisplacement)
{
    // intent: a merge distance of 0 merges nothing (the scan's strict "closer than")
    if (!(mMergeDistance > 0.0))
    {
        mPoints.push_back({inLattice, inDisplacement, 1});
        return false;
    }
    // A point closer than the distance lies in one of the 27 buckets around this one; the scan took the first
    // added, which is the smallest index among them.
    const Key key = BucketOf(inLattice);
    std::size_t first = mPoints.size();
    for (std::int64_t dx = -1; dx <= 1; ++dx)
        for (std::int64_t dy = -1; dy <= 1; ++dy)
            for (std::int64_t dz = -1; dz <= 1; ++dz)
            {
                const auto bucket = mBuckets.find({key[0] + dx, key[1] + dy, key[2] + dz});
                if (bucket == mBuckets.end())
                    continue;
                for (std::size_t index : bucket->second)
                    if (index < first && (mPoints[index].mLattice - inLattice).cwiseAbs().maxCoeff() < mMergeDistance)
                    {
                        first = index;
                        break; // ascending: the rest of this bucket comes later
                    }
            }
    if (first < mPoints.size())
    {
        // Running mean (a sum of two displacements near the double range would overflow).
        ZonePoint& near = mPoints[first];
        ++near.mMergedCount;
        near.mDisplacement += (inDisplacement - near.mDisplacement) / near.mMergedCount;
        return true;
    }
    mBuckets[key].push_back(mPoints.size());
    mPoints.push_back({inLattice, inDisplacement, 1});
    return false;
}

int ThinZonePoints(std::vector<ZonePoint>& ioPoints)
{
    int merged = 0;
    for (double bin = 0.25; ioPoints.size() > cMaxZonePoints; bin *= 2.0)
    {
        // Bins in the order of their first point (std::map: no dependence on a hash's iteration order).
        std::map<std::array<std::int64_t, 3>, std::size_t> slot_of_bin;
        std::vector<ZonePoint> thinned;
        for (const ZonePoint& point : ioPoints)
        {
            const std::array<std::int64_t, 3> bin_key{static_cast<std::int64_t>(std::floor(point.mLattice.x() / bin)),
                                                      static_cast<std::int64_t>(std::floor(point.mLattice.y() / bin)),
                                                      static_cast<std::int64_t>(std::floor(point.mLattice.z() / bin))};
            const auto [slot, inserted] = slot_of_bin.try_emplace(bin_key, thinned.size());
            if (inserted)
            {
                thinned.push_back(point);
                continue;
            }
            // Weighted running means of position and displacement.
            ZonePoint& into = thinned[slot->second];
            const int total = into.mMergedCount + point.mMergedCount;
            const double share = static_cast<double>(point.mMergedCount) / total;
            into.mLattice += share * (point.mLattice - into.mLattice);
            into.mDisplacement += share * (point.mDisplacement - into.mDisplacement);
            into.mMergedCount = total;
        }
        merged += static_cast<int>(ioPoints.size() - thinned.size());
        ioPoints = std::move(thinned);
    }
    return merged;
}

} // namespace crumple::ffd
