// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include "OutgoingEdges.h"

#include <array>
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
        : mTwins(inTwins), mSeam(std::move(inSeam)), mCounts(inTwins.size())
    {
        for (const std::array<std::uint32_t, 3>& t : inTriangles)
            for (int k = 0; k < 3; ++k)
                Add(t[k], t[(k + 1) % 3]);
    }

    /// Whether a triangle has the edge by position; false for an edge that touches no seam (ask by index)
    bool Has(std::uint32_t inFrom, std::uint32_t inTo) const
    {
        return OnSeam(inFrom, inTo) && mCounts.Find(mTwins[inFrom], mTwins[inTo]) != nullptr;
    }

    void Add(std::uint32_t inFrom, std::uint32_t inTo)
    {
        if (!OnSeam(inFrom, inTo))
            return;
        if (std::uint32_t* count = mCounts.Find(mTwins[inFrom], mTwins[inTo]))
            ++*count;
        else
            mCounts.Insert(mTwins[inFrom], mTwins[inTo], 1);
    }

    void Remove(std::uint32_t inFrom, std::uint32_t inTo)
    {
        if (!OnSeam(inFrom, inTo))
            return;
        if (std::uint32_t* count = mCounts.Find(mTwins[inFrom], mTwins[inTo]); count != nullptr && --*count == 0)
            mCounts.Erase(mTwins[inFrom], mTwins[inTo]);
    }

private:
    bool OnSeam(std::uint32_t inFrom, std::uint32_t inTo) const { return (mSeam[inFrom] | mSeam[inTo]) != 0; }

    const std::vector<std::uint32_t>& mTwins;
    std::vector<std::uint8_t> mSeam;
    OutgoingEdges<std::uint32_t> mCounts; ///< Keyed by the ends' twins
};

} // namespace crumple::ffd
