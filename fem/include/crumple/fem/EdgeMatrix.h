// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Math.h>

namespace crumple::fem
{

/// The edge matrix of a tetrahedron, columns p1 - p0, p2 - p0, p3 - p0 (Sifakis & Barbic 2012, "FEM
/// simulation of 3D deformable solids", section 4.2). With rest positions it is D_m, with current positions
/// D_s; det(D) = 6 x signed volume.
/// @param[in] inP0, inP1, inP2, inP3  corner positions (m)
/// @return D (m), 3 by 3
CRUMPLE_API Mat3 EdgeMatrix(const Vec3& inP0, const Vec3& inP1, const Vec3& inP2, const Vec3& inP3);

} // namespace crumple::fem
