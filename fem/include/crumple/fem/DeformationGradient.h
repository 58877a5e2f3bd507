// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Math.h>

namespace crumple::fem
{

/// Deformation gradient of a linear tetrahedron, F = D_s D_m^-1 (constant over the element): it maps rest
/// edge vectors to current ones. F = I at rest, F = R for a rigid rotation R; the same formula applied to
/// velocities gives the rate dF/dt.
/// @param[in] inX0, inX1, inX2, inX3  current corner positions (m), or velocities (m/s) for dF/dt
/// @param[in] inRestEdgeInverse       D_m^-1 (1/m), 3 by 3, from the rest positions
/// @return F (dimensionless; 1/s for velocities), 3 by 3
CRUMPLE_API Mat3 DeformationGradient(const Vec3& inX0, const Vec3& inX1, const Vec3& inX2, const Vec3& inX3,
                         const Mat3& inRestEdgeInverse);

} // namespace crumple::fem
