// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/fem/TetMesh.h>

#include <vector>

namespace crumple::fem
{

/// Lumped (diagonal) node masses: each element gives a quarter of its mass rho V0 to each of its corners, the
/// row-sum lumping of the linear tetrahedron's consistent mass matrix. The masses sum to rho x total volume.
/// @param[in] inMesh     the mesh
/// @param[in] inDensity  rho (kg/m^3), > 0
/// @return #N node masses (kg), each > 0 for a valid mesh
std::vector<double> LumpedNodeMass(const TetMesh& inMesh, double inDensity);

} // namespace crumple::fem
