// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace crumple::ffd
{

/// Each directed edge's triangle, found by scanning its start vertex's few outgoing edges. A flip reads about
/// ten of them and changes six; in a hash map those lookups were most of the flips' time.
class DirectedEdges
{
public:
    static constexpr std::uint32_t cNone = 0xFFFFFFFEu;        ///< No triangle has the edge
    static constexpr std::uint32_t cNonManifold = 0xFFFFFFFFu; ///< Two triangles have it the same way round

    explicit DirectedEdges(std::size_t inVertexCount) : mOut(inVertexCount) {}

    /// Records that inTriangle has the edge; a second triangle with it marks it cNonManifold
    void Add(std::uint32_t inFrom, std::uint32_t inTo, std::uint32_t inTriangle)
    {
        for (Entry& e : mOut[inFrom])
            if (e.mTo == inTo)
            {
                e.mTriangle = cNonManifold;
                return;
            }
        mOut[inFrom].push_back({inTo, inTriangle});
    }

    /// The edge's triangle, cNone or cNonManifold
    std::uint32_t Find(std::uint32_t inFrom, std::uint32_t inTo) const
    {
        for (const Entry& e : mOut[inFrom])
            if (e.mTo == inTo)
                return e.mTriangle;
        return cNone;
    }

    /// The edge now belongs to inTriangle (whatever it was before)
    void Set(std::uint32_t inFrom, std::uint32_t inTo, std::uint32_t inTriangle)
    {
        for (Entry& e : mOut[inFrom])
            if (e.mTo == inTo)
            {
                e.mTriangle = inTriangle;
                return;
            }
        mOut[inFrom].push_back({inTo, inTriangle});
    }

    void Erase(std::uint32_t inFrom, std::uint32_t inTo)
    {
        std::vector<Entry>& out = mOut[inFrom];
        for (std::size_t i = 0; i < out.size(); ++i)
            if (out[i].mTo == inTo)
            {
                out[i] = out.back();
                out.pop_back();
                return;
            }
    }

private:
    struct Entry
    {
        std::uint32_t mTo;
        std::uint32_t mTriangle;
    };
    std::vector<std::vector<Entry>> mOut; ///< Per start vertex (its key), its outgoing edges
};

} // namespace crumple::ffd
