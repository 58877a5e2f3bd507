// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/GreenStrain.h>
#include <crumple/fem/ModelStrain.h>

namespace crumple::fem
{

Mat3 ModelStrain(EElasticModel inModel, const Mat3& inF, const Mat3& inRotation)
{
    if (inModel == EElasticModel::StVenantKirchhoff)
        return GreenStrain(inF);
    const Mat3 unrotated = inRotation.transpose() * inF;
    return 0.5 * (unrotated + unrotated.transpose()) - Mat3::Identity();
}

} // namespace crumple::fem
