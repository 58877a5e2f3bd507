// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Result.h>
#include <crumple/fem/HexStaticData.h>

#include <Eigen/Core>

namespace crumple::fem
{

/// Quasi-static displacements U = K^-1 F with the fixed nodes held at zero: the forces on fixed nodes are
/// ignored (taken by the supports), their displacements are 0.
/// @param[in] inData    from HexStaticPrecompute
/// @param[in] inForces  3 #nodes nodal forces (N), entry 3 n + a = node n along axis a, body frame
/// @return 3 #nodes displacements (m), same layout; EError::InvalidArgument for an empty inData or a wrong
///         length, EError::NonFinite for a NaN or Inf force or displacements that overflow
CRUMPLE_API Result<Eigen::VectorXd> HexStaticSolve(const HexStaticData& inData, const Eigen::VectorXd& inForces);

/// The same with prescribed displacements of the fixed nodes: U_f = K_ff^-1 (F_f - K_fb U_b), U_b given.
/// @param[in] inData                from HexStaticPrecompute
/// @param[in] inForces              3 #nodes nodal forces (N); entries of fixed nodes are ignored
/// @param[in] inFixedDisplacements  3 #nodes displacements (m); only the entries of fixed nodes are used, but
///                                  all must be finite
/// @return 3 #nodes displacements (m): the prescribed ones at fixed nodes, the solved ones elsewhere
CRUMPLE_API Result<Eigen::VectorXd> HexStaticSolve(const HexStaticData& inData, const Eigen::VectorXd& inForces,
                                       const Eigen::VectorXd& inFixedDisplacements);

} // namespace crumple::fem
