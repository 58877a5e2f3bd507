// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Result.h>
#include <crumple/fem/HexMaterial.h>
#include <crumple/fem/HexMesh.h>

#include <Eigen/Core>

namespace crumple::fem
{

/// 24 by 24 element stiffness (N/m); dof 3 c + a is corner c (HexMesh corner order) along axis a (x, y, z).
using HexElementStiffnessMatrix = Eigen::Matrix<double, 24, 24>;

/// Linear-elastic stiffness of one trilinear hexahedron, K_e = integral of B^T D B over the element, by 2 x 2 x 2
/// Gauss quadrature through the isoparametric Jacobian (so any convex, non-inverted brick, not only boxes), in
/// the formulation of inMaterial (EHexFormulation; incompatible modes are condensed statically). The result is
/// exactly symmetric, positive semi-definite, and its null space is the 6 rigid-body motions.
/// @param[in] inCorners   8 by 3 corner positions (m), HexMesh corner order
/// @param[in] inMaterial  isotropic material (E, nu, formulation)
/// @return K_e (N/m), or EError::NonFinite / EError::DegenerateGeometry for non-finite corners or an element
///         failing cHexMinJacobianRatio (inverted, flat or twisted)
CRUMPLE_API Result<HexElementStiffnessMatrix> HexElementStiffness(const HexCornerMatrix& inCorners, const HexMaterial& inMaterial);

} // namespace crumple::fem
