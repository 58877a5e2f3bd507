// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Math.h>

namespace crumple::fem
{

/// A 6x6 matrix in Voigt notation.
using Matrix6 = Eigen::Matrix<double, 6, 6>;
/// A symmetric tensor in Voigt notation (xx, yy, zz, xy, yz, zx).
using Vector6 = Eigen::Matrix<double, 6, 1>;

/// The isotropic linear-elastic material matrix C with sigma = C eps in Voigt notation: stresses
/// (sxx, syy, szz, sxy, syz, szx) and strains (exx, eyy, ezz, 2 exy, 2 eyz, 2 ezx) (engineering shear).
///   C = E / ((1 + nu)(1 - 2 nu)) * [[1-nu, nu, nu, 0, 0, 0], [nu, 1-nu, nu, ...], [nu, nu, 1-nu, ...],
///        [0, 0, 0, (1 - 2 nu)/2, 0, 0], ...]
/// (the paper's "6x6 material stiffness matrix", section IV.A; Mueller et al., Real time physics class notes
/// 2008).
/// @param[in] inYoungsModulus  E (Pa), > 0
/// @param[in] inPoissonRatio   nu, in (-1, 0.5)
/// @return C (Pa), 6 by 6, symmetric positive definite for valid inputs
CRUMPLE_API Matrix6 IsotropicMaterialMatrix(double inYoungsModulus, double inPoissonRatio);

} // namespace crumple::fem
