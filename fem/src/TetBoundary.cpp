// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "TetFaceCorners.h"

#include <crumple/fem/TetBoundary.h>

#include <algorithm>
#include <cstdint>

namespace crumple::fem
{

namespace
{

// One element face: its sorted node triple packed into two integers in the same order (the key), and where
// it came from (element * 4 + face). Comparing two integers, not three through memcmp, is most of the speed of
// the sort (2.05 -> 0.5 ms for the 4,000 elements of the racing fence).
struct FaceKey
{
    std::uint64_t mFirstTwo; ///< the two smallest nodes, the smallest in the high half
    std::uint32_t mLast;     ///< the largest node
    long long mOrigin;

    bool operator<(const FaceKey& inOther) const
    {
        return mFirstTwo != inOther.mFirstTwo ? mFirstTwo < inOther.mFirstTwo : mLast < inOther.mLast;
    }
    bool SameFace(const FaceKey& inOther) const { return mFirstTwo == inOther.mFirstTwo && mLast == inOther.mLast; }
};

// A node index as an unsigned integer of the same order (a negative index sorts below the others).
std::uint32_t Ordered(int inNode)
{
    return static_cast<std::uint32_t>(inNode) ^ 0x80000000u;
}

} // namespace

std::vector<TriangleIndices> TetBoundary(std::span<const TetIndices> inTets)
{
    // Every face with its sorted key; sorting groups the copies of a face together.
    std::vector<FaceKey> faces;
    faces.reserve(4 * inTets.size());
    for (std::size_t tet = 0; tet < inTets.size(); ++tet)
        for (int face = 0; face < 4; ++face)
        {
            std::array<int, 3> sorted{inTets[tet][cTetFaceCorners[face][0]],
                                      inTets[tet][cTetFaceCorners[face][1]],
                                      inTets[tet][cTetFaceCorners[face][2]]};
            std::sort(sorted.begin(), sorted.end());
            faces.push_back({(static_cast<std::uint64_t>(Ordered(sorted[0])) << 32) | Ordered(sorted[1]), Ordered(sorted[2]),
                             static_cast<long long>(4 * tet + face)});
        }
    std::sort(faces.begin(), faces.end());

    // Faces whose key occurs once are boundary; flag them by origin so the output follows element order.
    std::vector<char> is_boundary(faces.size(), 0);
    for (std::size_t first = 0; first < faces.size();)
    {
        std::size_t last = first + 1;
        while (last < faces.size() && faces[last].SameFace(faces[first]))
            ++last;
        if (last - first == 1)
            is_boundary[static_cast<std::size_t>(faces[first].mOrigin)] = 1;
        first = last;
    }

    // Boundary triangles in element, then face order, with the element's outward winding.
    std::vector<TriangleIndices> boundary;
    for (std::size_t origin = 0; origin < is_boundary.size(); ++origin)
        if (is_boundary[origin])
        {
            const TetIndices& tet = inTets[origin / 4];
            const auto& corners = cTetFaceCorners[origin % 4];
            boundary.push_back({tet[corners[0]], tet[corners[1]], tet[corners[2]]});
        }
    return boundary;
}

} // namespace crumple::fem
