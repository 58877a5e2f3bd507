// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/fem/EElasticModel.h>
#include <crumple/fem/IsotropicMaterialMatrix.h>

namespace crumple::fem
{

/// First Piola-Kirchhoff stress P of an element (force per rest area), the derivative of the strain energy
/// density with respect to F:
///  - StVenantKirchhoff: P = F C:E, E = GreenStrain(F)
///  - CorotatedLinear:   P = R C:eps, eps = sym(R^T F) - I, R = PolarRotation(F); with the exact polar R this
///    equals 2 mu (F - R) + lambda tr(eps) R, the exact gradient of the corotated energy.
/// With plastic strain eps_p the stress is that of the elastic strain: C:(E - eps_p), C:(eps - eps_p).
/// @param[in] inModel           strain measure
/// @param[in] inF               deformation gradient, 3 by 3
/// @param[in] inRotation        polar rotation of inF (used by CorotatedLinear only), 3 by 3
/// @param[in] inMaterialMatrix  C (Pa), 6 by 6
/// @param[in] inPlasticStrain   eps_p (dimensionless), 3 by 3 symmetric, in the model's frame
/// @return P (Pa), 3 by 3
CRUMPLE_API Mat3 FirstPiolaStress(EElasticModel inModel, const Mat3& inF, const Mat3& inRotation,
                      const Matrix6& inMaterialMatrix, const Mat3& inPlasticStrain = Mat3::Zero());

} // namespace crumple::fem
