// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "MeshHash.h"

namespace crumple::common
{

std::uint64_t HashPositions(const std::vector<Vec3>& inPositions)
{
    std::uint64_t hash = 1469598103934665603ull;
    const auto* bytes = reinterpret_cast<const unsigned char*>(inPositions.data());
    for (std::size_t i = 0; i < inPositions.size() * sizeof(Vec3); ++i)
        hash = (hash ^ bytes[i]) * 1099511628211ull;
    return hash;
}

} // namespace crumple::common
