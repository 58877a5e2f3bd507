// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Result.h>
#include <crumple/fem/HexCompliance.h>

#include <Eigen/Core>

namespace crumple::fem
{

/// An instant quasi-static dent: U_out = C F_load, one dense matrix-vector product (9 #output #load
/// multiply-adds). Measured (Release, x86-64, one thread): 40 x 4 x 4 cantilever, 25 tip nodes onto all 1025
/// nodes 0.06 ms (HexStaticSolve 0.41 ms); 20 x 20 x 5 plate, 441 top nodes onto the same 441 0.25 ms
/// (HexStaticSolve 3.4 ms), onto all 2646 nodes 4.0 ms (no gain). Equals HexStaticSolve on the output nodes
/// for forces on the load nodes only, to rounding (1e-14 relative in the tests).
/// @param[in] inCompliance  from HexCompliancePrecompute or LoadHexCompliance
/// @param[in] inLoadForces  3 #load forces (N), entry 3 l + a = mLoadNodes[l] along axis a, body frame
/// @return 3 #output displacements (m), entry 3 o + b = mOutputNodes[o] along axis b; EError::InvalidArgument
///         for a wrong length or an inconsistent inCompliance, EError::NonFinite for a NaN or Inf force or
///         displacements that are not finite (a non-finite compliance entry, or an overflow)
CRUMPLE_API Result<Eigen::VectorXd> HexComplianceSolve(const HexCompliance& inCompliance, const Eigen::VectorXd& inLoadForces);

} // namespace crumple::fem
