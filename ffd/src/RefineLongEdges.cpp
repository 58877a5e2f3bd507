// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "SplitTriangle.h"

#include <crumple/ffd/RefineLongEdges.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_map>

namespace crumple::ffd
{

Result<RefinedMesh> RefineLongEdges(const TriangleMesh& inMesh, double inMaxEdge, std::size_t inMaxTriangles)
{
    if (Status valid = ValidateTriangleMesh(inMesh); !valid)
        return valid.GetError();
    if (!std::isfinite(inMaxEdge) || !(inMaxEdge > 0.0))
        return MakeError(EError::InvalidArgument, "RefineLongEdges: the longest edge wanted must be finite and > 0 m, not " +
                                                      std::to_string(inMaxEdge));
    RefinedMesh refined;
    refined.mMesh = inMesh;
    std::vector<Vec3>& positions = refined.mMesh.mPositions;
    std::vector<std::array<std::uint32_t, 3>>& triangles = refined.mMesh.mTriangles;
    const double max_edge2 = inMaxEdge * inMaxEdge;
    std::unordered_map<std::uint64_t, std::uint32_t> midpoints;
    std::vector<std::array<std::uint32_t, 3>> cuts;
    std::vector<std::array<std::uint32_t, 3>> next;
    // intent: each pass at least halves every edge longer than inMaxEdge; the new edges inside a triangle are
    // no longer than its longest, so a mesh of edges up to L needs about log2(L / inMaxEdge) passes
    for (;;)
    {
        midpoints.clear();
        cuts.assign(triangles.size(), {cNoSplit, cNoSplit, cNoSplit});
        for (std::size_t t = 0; t < triangles.size(); ++t)
            for (int k = 0; k < 3; ++k)
            {
                const std::uint32_t a = triangles[t][k], b = triangles[t][(k + 1) % 3];
                if (!((positions[a] - positions[b]).squaredNorm() > max_edge2))
                    continue;
                const auto [it, added] = midpoints.try_emplace(UndirectedEdgeKey(a, b), static_cast<std::uint32_t>(positions.size()));
                if (added)
                {
                    if (positions.size() >= 0xFFFFFFFEu)
                        return MakeError(EError::OutOfRange, "RefineLongEdges: the refined mesh would have more than 2^32 - 2 vertices");
                    // (a + b) / 2 is the same whichever way round: the two sides of a seam get the same point
                    const Vec3 midpoint = 0.5 * (positions[a] + positions[b]);
                    positions.push_back(midpoint);
                    refined.mSplitParents.push_back({std::min(a, b), std::max(a, b)});
                    refined.mSplitFractions.push_back(0.5);
                }
                cuts[t][k] = it->second;
            }
        if (midpoints.empty())
            return refined;
        next.clear();
        next.reserve(triangles.size() * 2);
        for (std::size_t t = 0; t < triangles.size(); ++t)
        {
            SplitTriangle(triangles[t], cuts[t], positions, next);
            if (next.size() > inMaxTriangles)
                return MakeError(EError::OutOfRange, "RefineLongEdges: edges of at most " + std::to_string(inMaxEdge) +
                                                         " m need more than " + std::to_string(inMaxTriangles) +
                                                         " triangles; ask for longer edges or a higher limit");
        }
        triangles.swap(next);
    }
}

} // namespace crumple::ffd
