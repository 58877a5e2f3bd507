// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include "OutgoingEdges.h"

#include <cstddef>
#include <cstdint>

namespace crumple::ffd
{

/// Each directed edge's triangle (vertices by their key: index or seam twin), for the flip loop.
class DirectedEdges
{
public:
    static constexpr std::uint32_t cNone = 0xFFFFFFFEu;        ///< No triangle has the edge
    static constexpr std::uint32_t cNonManifold = 0xFFFFFFFFu; ///< Two triangles have it the same way round

    explicit DirectedEdges(std::size_t inVertexCount) : mEdges(inVertexCount) {}

    /// Room for inCount edges from inFrom (its triangles' corners), so that adding them allocates once
    void Reserve(std::uint32_t inFrom, std::size_t inCount) { mEdges.Reserve(inFrom, inCount); }

    /// Records that inTriangle has the edge; a second triangle with it marks it cNonManifold
    void Add(std::uint32_t inFrom, std::uint32_t inTo, std::uint32_t inTriangle)
    {
        if (std::uint32_t* triangle = mEdges.Find(inFrom, inTo))
            *triangle = cNonManifold;
        else
            mEdges.Insert(inFrom, inTo, inTriangle);
    }

    /// The edge's triangle, cNone or cNonManifold
    std::uint32_t Find(std::uint32_t inFrom, std::uint32_t inTo) const
    {
        const std::uint32_t* triangle = mEdges.Find(inFrom, inTo);
        return triangle != nullptr ? *triangle : cNone;
    }

    /// The edge now belongs to inTriangle (whatever it was before)
    void Set(std::uint32_t inFrom, std::uint32_t inTo, std::uint32_t inTriangle)
    {
        if (std::uint32_t* triangle = mEdges.Find(inFrom, inTo))
            *triangle = inTriangle;
        else
            mEdges.Insert(inFrom, inTo, inTriangle);
    }

    void Erase(std::uint32_t inFrom, std::uint32_t inTo) { mEdges.Erase(inFrom, inTo); }

private:
    OutgoingEdges<std::uint32_t> mEdges;
};

} // namespace crumple::ffd
