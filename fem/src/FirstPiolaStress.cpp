// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/FirstPiolaStress.h>
#include <crumple/fem/MaterialStress.h>
#include <crumple/fem/ModelStrain.h>

namespace crumple::fem
{

Mat3 FirstPiolaStress(EElasticModel inModel, const Mat3& inF, const Mat3& inRotation,
                      const Matrix6& inMaterialMatrix, const Mat3& inPlasticStrain)
{
    // Stress of the elastic strain, in the model's frame: P = F S (S = C:(E - eps_p)) or P = R C:(eps - eps_p).
    const Mat3 stress = MaterialStress(inMaterialMatrix, ModelStrain(inModel, inF, inRotation) - inPlasticStrain);
    return (inModel == EElasticModel::StVenantKirchhoff ? inF : inRotation) * stress;
}

} // namespace crumple::fem
