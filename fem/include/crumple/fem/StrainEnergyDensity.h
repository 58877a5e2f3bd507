// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/fem/EElasticModel.h>
#include <crumple/fem/IsotropicMaterialMatrix.h>

namespace crumple::fem
{

/// Elastic energy per rest volume, psi = eps^T C eps / 2 in Voigt form, with eps the model's strain
/// (GreenStrain(F) for StVenantKirchhoff, sym(R^T F) - I for CorotatedLinear). FirstPiolaStress() is its
/// derivative with respect to F.
/// @param[in] inModel           strain measure
/// @param[in] inF               deformation gradient, 3 by 3
/// @param[in] inRotation        polar rotation of inF (used by CorotatedLinear only), 3 by 3
/// @param[in] inMaterialMatrix  C (Pa), 6 by 6
/// @param[in] inPlasticStrain   eps_p (dimensionless), 3 by 3 symmetric; psi is that of eps - eps_p
/// @return psi (J/m^3), >= 0
CRUMPLE_API double StrainEnergyDensity(EElasticModel inModel, const Mat3& inF, const Mat3& inRotation,
                           const Matrix6& inMaterialMatrix, const Mat3& inPlasticStrain = Mat3::Zero());

} // namespace crumple::fem
