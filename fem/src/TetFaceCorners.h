// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <cstdint>

namespace crumple::fem
{

/// Corner slots of the four faces of a positively oriented tetrahedron (x1-x0, x2-x0, x3-x0 right-handed),
/// indexed by the corner each face is opposite to; each face is counter-clockwise seen from outside (its
/// normal points away from the opposite corner). Private to fem (boundary extraction and fracture links).
inline constexpr std::array<std::array<std::uint8_t, 3>, 4> cTetFaceCorners{
    {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}}};

} // namespace crumple::fem
