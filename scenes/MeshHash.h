// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Math.h>

#include <cstdint>
#include <vector>

namespace crumple::common
{

/// FNV-1a hash of the bytes of a vector of Vec3, to compare and print meshes (a replay's check line).
std::uint64_t HashPositions(const std::vector<Vec3>& inPositions);

} // namespace crumple::common
