// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Math.h>

#include <array>

namespace crumple::fem
{

/// Elastic forces on the four corners of a linear tetrahedron from its first Piola-Kirchhoff stress:
/// H = -V0 P D_m^-T, f1, f2, f3 = the columns of H, f0 = -(f1 + f2 + f3) (Sifakis & Barbic 2012, eq. 4.9).
/// This is the paper's "for each face, force equals stress times the face normal, distributed over the
/// face's nodes" written with rest-area normals: each node gets a third of P times the area-weighted normals
/// of its three faces. The forces sum to zero and exert no net torque when P F^T is symmetric.
/// @param[in] inFirstPiolaStress  P (Pa), 3 by 3
/// @param[in] inRestEdgeInverse   D_m^-1 (1/m), 3 by 3
/// @param[in] inRestVolume        V0 (m^3), > 0
/// @return forces on corners 0..3 (N), world frame
CRUMPLE_API std::array<Vec3, 4> TetNodalForces(const Mat3& inFirstPiolaStress, const Mat3& inRestEdgeInverse,
                                   double inRestVolume);

} // namespace crumple::fem
