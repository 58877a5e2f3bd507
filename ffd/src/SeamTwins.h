// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Math.h>

#include <cstdint>
#include <vector>

namespace crumple::ffd
{

/// Each vertex's twin of lowest index at the same position (==, so 0.0 and -0.0 are one), so that the edges
/// on the two sides of a texture seam or a hard edge, where exporters split vertices, are one edge.
/// @param[in] inPositions  #V positions
/// @return #V indices: twin[v] <= v, twin[twin[v]] == twin[v]
std::vector<std::uint32_t> SeamTwins(const std::vector<Vec3>& inPositions);

} // namespace crumple::ffd
