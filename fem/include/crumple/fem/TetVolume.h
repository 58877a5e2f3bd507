// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Math.h>

namespace crumple::fem
{

/// Signed volume of the tetrahedron (p0, p1, p2, p3): det[p1 - p0, p2 - p0, p3 - p0] / 6.
/// Positive when p3 lies on the side of triangle (p0, p1, p2) that its right-handed normal
/// (p1 - p0) x (p2 - p0) points to: the orientation every TetMesh element must have.
/// @param[in] inP0, inP1, inP2, inP3  corner positions (m)
/// @return signed volume (m^3)
CRUMPLE_API double TetVolume(const Vec3& inP0, const Vec3& inP1, const Vec3& inP2, const Vec3& inP3);

} // namespace crumple::fem
