// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "SeamTwins.h"

#include <algorithm>
#include <numeric>

namespace crumple::ffd
{

std::vector<std::uint32_t> SeamTwins(const std::vector<Vec3>& inPositions)
{
    // intent: sort by position, ties by index, so each run of equal positions starts at its lowest index
    std::vector<std::uint32_t> order(inPositions.size());
    std::iota(order.begin(), order.end(), 0u);
    auto less = [&](std::uint32_t inA, std::uint32_t inB) {
        const Vec3& a = inPositions[inA];
        const Vec3& b = inPositions[inB];
        if (a.x() != b.x())
            return a.x() < b.x();
        if (a.y() != b.y())
            return a.y() < b.y();
        if (a.z() != b.z())
            return a.z() < b.z();
        return inA < inB;
    };
    std::sort(order.begin(), order.end(), less);
    std::vector<std::uint32_t> twin(inPositions.size());
    for (std::size_t i = 0; i < order.size(); ++i)
        twin[order[i]] = (i > 0 && inPositions[order[i]] == inPositions[order[i - 1]]) ? twin[order[i - 1]] : order[i];
    return twin;
}

} // namespace crumple::ffd
