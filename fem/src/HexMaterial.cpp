// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "HexFormat.h"

#include <crumple/base/Math.h>
#include <crumple/fem/FemMaterialSettings.h>
#include <crumple/fem/HexMaterial.h>

namespace crumple::fem
{

Result<HexMaterial> HexMaterial::Create(const HexMaterialSettings& inSettings)
{
    // Finite first, then the ranges in which D is positive definite.
    if (!IsFinite(inSettings.mYoungsModulus) || !IsFinite(inSettings.mPoissonRatio))
        return MakeError(EError::NonFinite, "HexMaterialSettings: mYoungsModulus = " +
                                                HexFormat(inSettings.mYoungsModulus) + " Pa and mPoissonRatio = " +
                                                HexFormat(inSettings.mPoissonRatio) + " must be finite");
    if (!(inSettings.mYoungsModulus > 0.0))
        return MakeError(EError::InvalidArgument, "HexMaterialSettings.mYoungsModulus = " +
                                                      HexFormat(inSettings.mYoungsModulus) + " Pa must be > 0");
    // intent: the elasticity matrix's largest entry, about 33 E at the highest Poisson ratio, stays finite
    if (!(inSettings.mYoungsModulus <= FemMaterialSettings::cMaxYoungsModulus))
        return MakeError(EError::OutOfRange, "HexMaterialSettings.mYoungsModulus = " + HexFormat(inSettings.mYoungsModulus) +
                                                 " Pa must be at most 1e15 (FemMaterialSettings::cMaxYoungsModulus)");
    if (!(inSettings.mPoissonRatio > -1.0 && inSettings.mPoissonRatio < 0.5))
        return MakeError(EError::InvalidArgument, "HexMaterialSettings.mPoissonRatio = " +
                                                      HexFormat(inSettings.mPoissonRatio) +
                                                      " must lie in (-1, 0.5): 0.5 is incompressible");
    if (inSettings.mFormulation != EHexFormulation::IncompatibleModes &&
        inSettings.mFormulation != EHexFormulation::FullIntegration)
        return MakeError(EError::InvalidArgument, "HexMaterialSettings.mFormulation is not an EHexFormulation value");
    return HexMaterial(inSettings);
}

HexMaterial::HexMaterial(const HexMaterialSettings& inSettings) : mSettings(inSettings)
{
    // Isotropic Hooke's law with Lame constants lambda and mu; shear rows act on engineering strains.
    const double e = inSettings.mYoungsModulus;
    const double nu = inSettings.mPoissonRatio;
    const double lambda = e * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
    const double mu = e / (2.0 * (1.0 + nu));
    mElasticity.setZero();
    for (int i = 0; i < 3; ++i)
    {
        for (int j = 0; j < 3; ++j)
            mElasticity(i, j) = lambda;
        mElasticity(i, i) = lambda + 2.0 * mu;
        mElasticity(3 + i, 3 + i) = mu;
    }
}

double HexMaterial::GetShearModulus() const
{
    return mSettings.mYoungsModulus / (2.0 * (1.0 + mSettings.mPoissonRatio));
}

} // namespace crumple::fem
