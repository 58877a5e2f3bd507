// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "SplitAtFeet.h"
#include "SeamTwins.h"
#include "SplitTriangle.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>

namespace crumple::ffd
{

namespace
{

// A far corner closer to the long edge than this fraction of its length makes a degenerate triangle.
constexpr double cDegenerate = 1e-9;

// Where a picked triangle's long edge is split: the foot of its far corner, as a fraction along the edge from
// its end of lower seam twin (the same end on every side of a seam, so every side gets the same point bit for
// bit).
struct FootSplit
{
    std::uint32_t mFrom = 0; ///< the end the fraction counts from (its seam twin of lowest index)
    double mFraction = 0.0;  ///< in (0, 1)
    Vec3 mPoint = Vec3::Zero();
    double mUrgency = 0.0; ///< the selector's, of the triangle whose foot it is
};

// The corner k (0..2) of a triangle facing its longest edge, and that edge's squared length; -1 for a
// triangle without a positive edge.
std::pair<int, double> LongestEdgeCorner(const std::array<Vec3, 3>& inCorners)
{
    int corner = -1;
    double longest = 0.0;
    for (int k = 0; k < 3; ++k)
    {
        const double length2 = (inCorners[(k + 2) % 3] - inCorners[(k + 1) % 3]).squaredNorm();
        if (length2 > longest)
        {
            longest = length2;
            corner = k;
        }
    }
    return {corner, longest};
}

} // namespace

Result<RefinedMesh> SplitAtFeet(const TriangleMesh& inMesh, const FootSelector& inSelect, const char* inName)
{
    if (Status valid = ValidateTriangleMesh(inMesh); !valid)
        return valid.GetError();
    const std::vector<std::uint32_t> twin = SeamTwins(inMesh.mPositions);
    const std::vector<Vec3>& rest = inMesh.mPositions;

    // intent: the split point of each long edge, keyed by its ends' seam twins, the first triangle picked in
    // triangle order deciding
    std::unordered_map<std::uint64_t, FootSplit> splits;
    for (const auto& triangle : inMesh.mTriangles)
    {
        const std::array<Vec3, 3> corners = {rest[triangle[0]], rest[triangle[1]], rest[triangle[2]]};
        const auto [corner, longest] = LongestEdgeCorner(corners);
        if (corner < 0)
            continue;
        const std::uint32_t a = triangle[(corner + 1) % 3], b = triangle[(corner + 2) % 3];
        if (twin[a] == twin[b])
            continue;
        const std::uint64_t key = UndirectedEdgeKey(twin[a], twin[b]);
        const std::uint32_t from = std::min(twin[a], twin[b]), to = std::max(twin[a], twin[b]);
        const Vec3 edge = rest[to] - rest[from];
        const double fraction = (corners[corner] - rest[from]).dot(edge) / edge.squaredNorm();
        // the largest angle faces the longest edge with both other corners acute: its foot is inside
        if (!(fraction > 0.0 && fraction < 1.0))
            continue;
        const Vec3 foot = rest[from] + fraction * edge;
        // A far corner on the edge to round-off is a degenerate triangle: it shows nothing, and its pieces
        // would be as degenerate, with their orientation left to round-off.
        const double height2 = (corners[corner] - foot).squaredNorm();
        if (height2 <= cDegenerate * cDegenerate * edge.squaredNorm())
            continue;
        const double length = std::sqrt(longest);
        const std::optional<double> urgency =
            inSelect(FootOfLongestEdge{corners, corner, length, fraction, std::sqrt(height2)});
        if (!urgency)
            continue;
        // intent: an edge two picked triangles share is split at the foot of the more urgent, the first in
        // triangle order among equals
        if (const auto claimed = splits.find(key); claimed != splits.end())
        {
            if (!(*urgency > claimed->second.mUrgency))
                continue;
            splits.erase(claimed);
        }
        splits.emplace(key, FootSplit{from, fraction, foot, *urgency});
    }

    RefinedMesh refined;
    refined.mMesh.mPositions = inMesh.mPositions;
    if (splits.empty())
    {
        refined.mMesh.mTriangles = inMesh.mTriangles;
        return refined;
    }
    std::vector<Vec3>& positions = refined.mMesh.mPositions;
    // intent: one added vertex per edge by index (a seam's sides by position get one each)
    std::unordered_map<std::uint64_t, std::uint32_t> added;
    std::vector<std::array<std::uint32_t, 3>>& triangles = refined.mMesh.mTriangles;
    triangles.reserve(inMesh.mTriangles.size() + 4 * splits.size());
    // intent: look an edge up only when both its ends (by twin) end a split edge: most triangles touch none
    std::vector<std::uint8_t> on_split(inMesh.mPositions.size(), 0);
    for (const auto& [key, split] : splits)
    {
        on_split[static_cast<std::uint32_t>(key)] = 1;
        on_split[static_cast<std::uint32_t>(key >> 32)] = 1;
    }
    for (const auto& triangle : inMesh.mTriangles)
    {
        std::array<std::uint32_t, 3> cut = {cNoSplit, cNoSplit, cNoSplit};
        for (int k = 0; k < 3; ++k)
        {
            const std::uint32_t a = triangle[k], b = triangle[(k + 1) % 3];
            if (on_split[twin[a]] == 0 || on_split[twin[b]] == 0)
                continue;
            const auto split = splits.find(UndirectedEdgeKey(twin[a], twin[b]));
            if (split == splits.end())
                continue;
            const auto [it, is_new] =
                added.try_emplace(UndirectedEdgeKey(a, b), static_cast<std::uint32_t>(positions.size()));
            if (is_new)
            {
                if (positions.size() >= 0xFFFFFFFEu)
                    return MakeError(EError::OutOfRange,
                                     std::string(inName) +
                                         ": the split mesh would have more than 2^32 - 2 vertices");
                const std::uint32_t low = std::min(a, b), high = std::max(a, b);
                const double fraction = twin[low] == split->second.mFrom ? split->second.mFraction
                                                                         : 1.0 - split->second.mFraction;
                positions.push_back(split->second.mPoint);
                refined.mSplitParents.push_back({low, high});
                refined.mSplitFractions.push_back(fraction);
            }
            cut[k] = it->second;
        }
        SplitTriangle(triangle, cut, positions, triangles);
    }
    return refined;
}

} // namespace crumple::ffd
