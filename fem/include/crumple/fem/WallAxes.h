// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Math.h>

#include <array>

namespace crumple::fem
{

/// The axes of a wall-like box: {width axis u, height axis v, thickness axis t} as indices 0 (x), 1 (y), 2
/// (z). The wall plane is spanned by the two largest extents, the longer of them being the width; the
/// smallest extent is the thickness. Ties go to the lower axis index first, so a cube gives {x, y, z}.
/// @param[in] inSize  extent along x, y, z (m)
CRUMPLE_API std::array<int, 3> WallAxes(const Vec3& inSize);

} // namespace crumple::fem
