// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/ffd/RefineLongEdges.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_map>

namespace crumple::ffd
{

namespace
{

using Triangle = std::array<std::uint32_t, 3>;

// An undirected edge as one key: both triangles that share it find the same midpoint.
std::uint64_t EdgeKey(std::uint32_t inA, std::uint32_t inB)
{
    const std::uint64_t low = std::min(inA, inB), high = std::max(inA, inB);
    return (high << 32) | low;
}

// The triangle (v0, v1, v2) cut at the midpoints m[k] of its split edges k = (v[k], v[k+1]) (cNone where
// not split), each piece counter-clockwise as the triangle was.
constexpr std::uint32_t cNone = 0xFFFFFFFFu;

void SplitTriangle(const Triangle& inTriangle, const std::array<std::uint32_t, 3>& inMid, const std::vector<Vec3>& inPositions,
                   std::vector<Triangle>& ioOut)
{
    const int split = (inMid[0] != cNone) + (inMid[1] != cNone) + (inMid[2] != cNone);
    if (split == 0)
    {
        ioOut.push_back(inTriangle);
        return;
    }
    if (split == 3)
    {
        const auto& [v0, v1, v2] = inTriangle;
        const auto& [m0, m1, m2] = inMid;
        ioOut.push_back({v0, m0, m2});
        ioOut.push_back({m0, v1, m1});
        ioOut.push_back({m2, m1, v2});
        ioOut.push_back({m0, m1, m2});
        return;
    }
    // intent: rotate so that edge 0 is split and, with two split, edge 2 is the one that is not
    int r = 0;
    if (split == 1)
        r = inMid[0] != cNone ? 0 : (inMid[1] != cNone ? 1 : 2);
    else
        r = inMid[2] == cNone ? 0 : (inMid[0] == cNone ? 1 : 2);
    const std::uint32_t v0 = inTriangle[r], v1 = inTriangle[(r + 1) % 3], v2 = inTriangle[(r + 2) % 3];
    const std::uint32_t m0 = inMid[r], m1 = inMid[(r + 1) % 3];
    if (split == 1)
    {
        ioOut.push_back({v0, m0, v2});
        ioOut.push_back({m0, v1, v2});
        return;
    }
    // intent: the corner at v1, then the quad (v0, m0, m1, v2) along its shorter diagonal
    ioOut.push_back({m0, v1, m1});
    const double v0_m1 = (inPositions[v0] - inPositions[m1]).squaredNorm();
    const double m0_v2 = (inPositions[m0] - inPositions[v2]).squaredNorm();
    if (v0_m1 <= m0_v2)
    {
        ioOut.push_back({v0, m0, m1});
        ioOut.push_back({v0, m1, v2});
    }
    else
    {
        ioOut.push_back({v0, m0, v2});
        ioOut.push_back({m0, m1, v2});
    }
}

} // namespace

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
    std::vector<Triangle>& triangles = refined.mMesh.mTriangles;
    const double max_edge2 = inMaxEdge * inMaxEdge;
    std::unordered_map<std::uint64_t, std::uint32_t> midpoints;
    std::vector<std::array<std::uint32_t, 3>> cuts;
    std::vector<Triangle> next;
    // intent: each pass at least halves every edge longer than inMaxEdge; the new edges inside a triangle are
    // no longer than its longest, so a mesh of edges up to L needs about log2(L / inMaxEdge) passes
    for (;;)
    {
        midpoints.clear();
        cuts.assign(triangles.size(), {cNone, cNone, cNone});
        for (std::size_t t = 0; t < triangles.size(); ++t)
            for (int k = 0; k < 3; ++k)
            {
                const std::uint32_t a = triangles[t][k], b = triangles[t][(k + 1) % 3];
                if (!((positions[a] - positions[b]).squaredNorm() > max_edge2))
                    continue;
                const auto [it, added] = midpoints.try_emplace(EdgeKey(a, b), static_cast<std::uint32_t>(positions.size()));
                if (added)
                {
                    if (positions.size() >= 0xFFFFFFFEu)
                        return MakeError(EError::OutOfRange, "RefineLongEdges: the refined mesh would have more than 2^32 - 2 vertices");
                    // (a + b) / 2 is the same whichever way round: the two sides of a seam get the same point
                    const Vec3 midpoint = 0.5 * (positions[a] + positions[b]);
                    positions.push_back(midpoint);
                    refined.mMidpointParents.push_back({std::min(a, b), std::max(a, b)});
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
