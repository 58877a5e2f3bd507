// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/ffd/VertexRange.h>

namespace crumple::ffd
{

std::vector<VertexRange> VertexRangesFromFlags(std::span<const std::uint8_t> inChanged)
{
    std::vector<VertexRange> ranges;
    const auto count = static_cast<std::uint32_t>(inChanged.size());
    for (std::uint32_t v = 0; v < count;)
    {
        if (inChanged[v] == 0)
        {
            ++v;
            continue;
        }
        // Extend the run of changed vertices.
        const std::uint32_t begin = v;
        while (v < count && inChanged[v] != 0)
            ++v;
        ranges.push_back({begin, v});
    }
    return ranges;
}

} // namespace crumple::ffd
