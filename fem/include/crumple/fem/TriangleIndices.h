// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <array>

namespace crumple::fem
{

/// The three vertex (or node) indices of a triangle. Where an orientation is stated, the right-handed normal
/// (p1 - p0) x (p2 - p0) points out of the enclosed solid (counter-clockwise seen from outside).
using TriangleIndices = std::array<int, 3>;

} // namespace crumple::fem
