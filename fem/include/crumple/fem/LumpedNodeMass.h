// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>
#include <crumple/base/Result.h>

#include <crumple/fem/TetElementRest.h>
#include <crumple/fem/TetMesh.h>

#include <span>

#include <vector>

namespace crumple::fem
{

/// Lumped (diagonal) node masses: each element gives a quarter of its mass rho V0 to each of its corners, the
/// row-sum lumping of the linear tetrahedron's consistent mass matrix. The masses sum to rho x total volume.
/// @param[in] inMesh     the mesh
/// @param[in] inDensity  rho (kg/m^3), finite and > 0
/// @return #N node masses (kg), each > 0 for a valid mesh; refused for a density that is not finite and > 0
CRUMPLE_API Result<std::vector<double>> LumpedNodeMass(const TetMesh& inMesh, double inDensity);

/// The same for a connectivity that differs from a mesh's (after fracture duplicated nodes).
/// @param[in] inElementNodes  #T element -> node indices, each < inNodeCount
/// @param[in] inRest          #T element rest data (rest volumes)
/// @param[in] inNodeCount     #N
/// @param[in] inDensity       rho (kg/m^3), finite and > 0
/// @return #N node masses (kg); refused, with the element named, when inRest's size differs from
/// inElementNodes', a node index is outside [0, inNodeCount), or a rest volume or the density is not finite
/// and > 0
CRUMPLE_API Result<std::vector<double>> LumpedNodeMass(std::span<const TetIndices> inElementNodes,
                                                       std::span<const TetElementRest> inRest, int inNodeCount,
                                                       double inDensity);

} // namespace crumple::fem
