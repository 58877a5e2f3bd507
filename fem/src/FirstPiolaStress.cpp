// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/FirstPiolaStress.h>
#include <crumple/fem/GreenStrain.h>
#include <crumple/fem/MaterialStress.h>

namespace crumple::fem
{

Mat3 FirstPiolaStress(EElasticModel inModel, const Mat3& inF, const Mat3& inRotation,
                      const Matrix6& inMaterialMatrix)
{
    if (inModel == EElasticModel::StVenantKirchhoff)
    {
        // P = F S with the second Piola-Kirchhoff stress S = C:E.
        return inF * MaterialStress(inMaterialMatrix, GreenStrain(inF));
    }

    // Corotated: the strain in the element's rotated frame, stress rotated back.
    const Mat3 unrotated = inRotation.transpose() * inF;
    const Mat3 strain = 0.5 * (unrotated + unrotated.transpose()) - Mat3::Identity();
    return inRotation * MaterialStress(inMaterialMatrix, strain);
}

} // namespace crumple::fem
