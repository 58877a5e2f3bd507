// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <cstdint>
#include <span>
#include <vector>

namespace crumple::ffd
{

/// A half-open range [mBegin, mEnd) of vertex indices whose position or normal changed: what a game
/// re-uploads to its vertex buffer.
struct CRUMPLE_API VertexRange
{
    std::uint32_t mBegin = 0; ///< First changed vertex
    std::uint32_t mEnd = 0;   ///< One past the last changed vertex

    bool operator==(const VertexRange&) const = default;
};

/// Turns a flag per vertex (non-zero = changed) into ascending, disjoint, non-adjacent ranges.
CRUMPLE_API std::vector<VertexRange> VertexRangesFromFlags(std::span<const std::uint8_t> inChanged);

} // namespace crumple::ffd
