// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/fem/IsotropicMaterialMatrix.h>

namespace crumple::fem
{

/// Stress from strain through a 6x6 material matrix: the symmetric strain tensor is written in Voigt form
/// with engineering shear (exx, eyy, ezz, 2 exy, 2 eyz, 2 ezx), multiplied by C, and written back as a
/// tensor.
/// @param[in] inMaterialMatrix  C (Pa), 6 by 6
/// @param[in] inStrain          symmetric strain tensor (dimensionless, or 1/s for a strain rate), 3 by 3;
///                              only its symmetric part is used
/// @return stress (Pa; Pa s for a strain rate), 3 by 3 symmetric
CRUMPLE_API Mat3 MaterialStress(const Matrix6& inMaterialMatrix, const Mat3& inStrain);

} // namespace crumple::fem
