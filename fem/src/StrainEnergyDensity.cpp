// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/GreenStrain.h>
#include <crumple/fem/MaterialStress.h>
#include <crumple/fem/StrainEnergyDensity.h>

namespace crumple::fem
{

double StrainEnergyDensity(EElasticModel inModel, const Mat3& inF, const Mat3& inRotation,
                           const Matrix6& inMaterialMatrix)
{
    // The model's strain tensor.
    Mat3 strain;
    if (inModel == EElasticModel::StVenantKirchhoff)
        strain = GreenStrain(inF);
    else
    {
        const Mat3 unrotated = inRotation.transpose() * inF;
        strain = 0.5 * (unrotated + unrotated.transpose()) - Mat3::Identity();
    }

    // psi = sigma : eps / 2 with sigma = C:eps (the tensor double contraction equals the Voigt product).
    return 0.5 * MaterialStress(inMaterialMatrix, strain).cwiseProduct(strain).sum();
}

} // namespace crumple::fem
