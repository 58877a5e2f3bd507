// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Math.h>

#include <array>
#include <cstdint>
#include <vector>

namespace crumple::ffd
{

/// An undirected edge as one key, whichever way round its ends are given: both triangles on an edge (and
/// both sides of a seam, given the ends' twins) find the same entry.
inline std::uint64_t UndirectedEdgeKey(std::uint32_t inA, std::uint32_t inB)
{
    const std::uint64_t low = inA < inB ? inA : inB, high = inA < inB ? inB : inA;
    return (high << 32) | low;
}

/// Marks an edge of SplitTriangle's inMid that is not split.
constexpr std::uint32_t cNoSplit = 0xFFFFFFFFu;

/// Appends the triangle (v0, v1, v2) cut at the points inMid[k] on its edges k = (v[k], v[k+1]) (cNoSplit
/// where not split), each piece counter-clockwise as the triangle was. The points may lie anywhere inside
/// their edges (RefineLongEdges puts them at midpoints, SplitCaps at a cap's foot); a quad left over is cut
/// along its shorter diagonal.
inline void SplitTriangle(const std::array<std::uint32_t, 3>& inTriangle,
                          const std::array<std::uint32_t, 3>& inMid, const std::vector<Vec3>& inPositions,
                          std::vector<std::array<std::uint32_t, 3>>& ioOut)
{
    const int split = (inMid[0] != cNoSplit) + (inMid[1] != cNoSplit) + (inMid[2] != cNoSplit);
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
        r = inMid[0] != cNoSplit ? 0 : (inMid[1] != cNoSplit ? 1 : 2);
    else
        r = inMid[2] == cNoSplit ? 0 : (inMid[0] == cNoSplit ? 1 : 2);
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

} // namespace crumple::ffd
