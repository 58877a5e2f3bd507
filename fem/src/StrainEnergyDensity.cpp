// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/MaterialStress.h>
#include <crumple/fem/ModelStrain.h>
#include <crumple/fem/StrainEnergyDensity.h>

namespace crumple::fem
{

double StrainEnergyDensity(EElasticModel inModel, const Mat3& inF, const Mat3& inRotation,
                           const Matrix6& inMaterialMatrix, const Mat3& inPlasticStrain)
{
    // psi = sigma : e / 2 with the elastic strain e and sigma = C:e (the double contraction equals the Voigt
    // product).
    const Mat3 elastic = ModelStrain(inModel, inF, inRotation) - inPlasticStrain;
    return 0.5 * MaterialStress(inMaterialMatrix, elastic).cwiseProduct(elastic).sum();
}

} // namespace crumple::fem
