// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace crumple::ffd
{

/// How many triangles have each directed edge that touches a seam, by the positions of its ends: a flip by
/// index must not make an edge that a seam's other side already has (the two sides would then face each
/// other, a fold). An edge between two vertices without a twin exists by position only as itself, so the
/// index map answers for it.
class PositionEdges
{
public:
    /// inSeam[v]: 1 when v shares its position with another vertex
    PositionEdges(const std::vector<std::array<std::uint32_t, 3>>& inTriangles, const std::vector<std::uint32_t>& inTwins,
                  std::vector<std::uint8_t> inSeam)
        : mTwins(inTwins), mSeam(std::move(inSeam)), mOut(inTwins.size())
    {
        for (const std::array<std::uint32_t, 3>& t : inTriangles)
            for (int k = 0; k < 3; ++k)
                Add(t[k], t[(k + 1) % 3]);
    }

    /// Whether a triangle has the edge by position; false for an edge that touches no seam (ask by index)
    bool Has(std::uint32_t inFrom, std::uint32_t inTo) const
    {
        if (!(mSeam[inFrom] | mSeam[inTo]))
            return false;
        for (const Entry& e : mOut[mTwins[inFrom]])
            if (e.mTo == mTwins[inTo])
                return true;
        return false;
    }

    void Add(std::uint32_t inFrom, std::uint32_t inTo)
    {
        if (!(mSeam[inFrom] | mSeam[inTo]))
            return;
        std::vector<Entry>& out = mOut[mTwins[inFrom]];
        for (Entry& e : out)
            if (e.mTo == mTwins[inTo])
            {
                ++e.mCount;
                return;
            }
        out.push_back({mTwins[inTo], 1});
    }

    void Remove(std::uint32_t inFrom, std::uint32_t inTo)
    {
        if (!(mSeam[inFrom] | mSeam[inTo]))
            return;
        std::vector<Entry>& out = mOut[mTwins[inFrom]];
        for (std::size_t i = 0; i < out.size(); ++i)
            if (out[i].mTo == mTwins[inTo])
            {
                if (--out[i].mCount == 0)
                {
                    out[i] = out.back();
                    out.pop_back();
                }
                return;
            }
    }

private:
    struct Entry
    {
        std::uint32_t mTo;
        std::uint32_t mCount;
    };
    const std::vector<std::uint32_t>& mTwins;
    std::vector<std::uint8_t> mSeam;
    std::vector<std::vector<Entry>> mOut; ///< Per start vertex's twin, its outgoing edges by their ends' twins
};

} // namespace crumple::ffd
