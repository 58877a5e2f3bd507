// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Result.h>
#include <crumple/fem/HexMaterial.h>
#include <crumple/fem/HexMesh.h>

#include <Eigen/SparseCore>

namespace crumple::fem
{

/// Global stiffness of a hexahedral mesh: the sum of the element stiffnesses (HexElementStiffness) scattered to
/// 3 dofs per node, dof 3 n + a = node n along axis a (x, y, z). No boundary conditions: the matrix is singular
/// with the 6 rigid-body motions (per connected part) as null space. Exactly symmetric; both triangles stored.
/// Summation runs in element order, so the result is bitwise reproducible. Memory: 81 entries per row for an
/// interior node of a structured mesh (12 bytes each); time linear in the element count, measured 22 us per
/// element with incompatible modes (13 of them in the element kernel) and 15 us with full integration
/// (Release, x86-64, one thread, 20 x 20 x 5 cells).
/// @param[in] inMesh      the mesh
/// @param[in] inMaterial  the material of every element
/// @return 3 #nodes by 3 #nodes compressed column matrix (N/m), or the first element's error
///         (EError::DegenerateGeometry, with its index)
CRUMPLE_API Result<Eigen::SparseMatrix<double>> HexStiffness(const HexMesh& inMesh, const HexMaterial& inMaterial);

} // namespace crumple::fem
