// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <Eigen/Core>

namespace crumple::ffd
{

/// Makes a dent's control changes one-sided. When every wanted displacement has a non-negative component
/// along their mean direction n (a crush: the impactor pushes the surface in, never out), the component of
/// each control change against n is removed. Cubic B-spline weights are non-negative, so afterwards no
/// point of the lattice moves against n: the surface beside a pushed patch cannot bulge out of the body.
///
/// Why: the direct-manipulation solve meets the points exactly with the minimum-norm correction of the
/// quasi-interpolant, and that correction alternates in sign past the edge of a partial push (a B-spline
/// cannot stop a displacement at a point without a counter-swing). Measured on the steel-barrier crash,
/// whose barrier covers the car's front below its top band: the band 8.7 cm above the contact patch moved
/// 2.8 cm forward, out of the car, in one run and not in a run 0.01 km/h faster.
/// Points whose controls were clipped move further along n than wanted where the removed component was
/// compensating; the dent's point error reports it.
/// @param[in]     inWanted  #points by 3 wanted displacements (m)
/// @param[in,out] ioDelta   #controls by 3 control changes (m), clipped in place
/// @return number of controls clipped (0 when the wanted displacements are not one-sided, or all zero)
CRUMPLE_API int OneSidedControls(const Eigen::MatrixX3d& inWanted, Eigen::MatrixX3d& ioDelta);

} // namespace crumple::ffd
