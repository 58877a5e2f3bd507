// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/PlasticFlow.h>

#include <algorithm>
#include <cmath>

namespace crumple::fem
{

double EquivalentPlasticStrain(const Mat3& inPlasticStrain)
{
    return std::sqrt(2.0 / 3.0 * inPlasticStrain.squaredNorm());
}

Mat3 PlasticFlow(const Mat3& inTotalStrain, const Mat3& inPlasticStrain, double inShearModulus,
                 const FemMaterialSettings& inMaterial, double inDeltaTime)
{
    // Deviatoric elastic strain and the von Mises stress of an isotropic material (s = 2 mu e').
    const Mat3 elastic = inTotalStrain - inPlasticStrain;
    const Mat3 deviatoric = elastic - (elastic.trace() / 3.0) * Mat3::Identity();
    const double von_mises = 2.0 * inShearModulus * std::sqrt(1.5 * deviatoric.squaredNorm());
    if (!(von_mises > inMaterial.mYieldStress))
        return inPlasticStrain;

    // Radial return of the excess, at the creep rate (an infinite rate makes the fraction exactly 1).
    const double fraction = std::min(1.0, inMaterial.mCreepRate * inDeltaTime);
    Mat3 plastic = inPlasticStrain + fraction * (1.0 - inMaterial.mYieldStress / von_mises) * deviatoric;
    plastic = 0.5 * (plastic + plastic.transpose());

    // Cap: beyond it the material hardens completely (stays elastic).
    const double equivalent = EquivalentPlasticStrain(plastic);
    if (equivalent > inMaterial.mMaxPlasticStrain)
        plastic *= inMaterial.mMaxPlasticStrain / equivalent;
    return plastic;
}

} // namespace crumple::fem
