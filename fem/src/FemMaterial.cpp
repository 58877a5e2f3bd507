// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/FemMaterial.h>

#include <cmath>
#include <sstream>

namespace crumple::fem
{

namespace
{

// "FemMaterialSettings.mX = v unit: reason", the message of every refusal.
Error FieldError(EError inCode, const char* inField, double inValue, const char* inUnit, const char* inReason)
{
    std::ostringstream message;
    message << "FemMaterialSettings." << inField << " = " << inValue << (inUnit[0] != 0 ? " " : "") << inUnit
            << ": " << inReason;
    return MakeError(inCode, message.str());
}

} // namespace

Result<FemMaterial> FemMaterial::Create(const FemMaterialSettings& inSettings)
{
    // Every number must be finite before any range check can mean anything.
    const struct
    {
        const char* mName;
        double mValue;
        const char* mUnit;
    } fields[] = {{"mYoungsModulus", inSettings.mYoungsModulus, "Pa"},
                  {"mPoissonRatio", inSettings.mPoissonRatio, ""},
                  {"mDensity", inSettings.mDensity, "kg/m^3"},
                  {"mMassDamping", inSettings.mMassDamping, "1/s"},
                  {"mStiffnessDamping", inSettings.mStiffnessDamping, "s"}};
    for (const auto& field : fields)
        if (!std::isfinite(field.mValue))
            return FieldError(EError::NonFinite, field.mName, field.mValue, field.mUnit, "must be finite");

    // Physical ranges.
    if (!(inSettings.mYoungsModulus > 0.0))
        return FieldError(EError::InvalidArgument, "mYoungsModulus", inSettings.mYoungsModulus, "Pa",
                          "must be > 0");
    if (!(inSettings.mYoungsModulus <= FemMaterialSettings::cMaxYoungsModulus))
        return FieldError(EError::OutOfRange, "mYoungsModulus", inSettings.mYoungsModulus, "Pa", "must be at most 1e15");
    if (!(inSettings.mPoissonRatio > -1.0 &&
          inSettings.mPoissonRatio <= FemMaterialSettings::cMaxPoissonRatio))
        return FieldError(EError::InvalidArgument, "mPoissonRatio", inSettings.mPoissonRatio, "",
                          "must lie in (-1, 0.495]; 0.5 (incompressible) makes lambda infinite");
    if (!(inSettings.mDensity > 0.0))
        return FieldError(EError::InvalidArgument, "mDensity", inSettings.mDensity, "kg/m^3", "must be > 0");
    if (!(inSettings.mDensity >= FemMaterialSettings::cMinDensity && inSettings.mDensity <= FemMaterialSettings::cMaxDensity))
        return FieldError(EError::OutOfRange, "mDensity", inSettings.mDensity, "kg/m^3", "must lie in [1e-6, 1e8]");
    if (!(inSettings.mMassDamping <= FemMaterialSettings::cMaxMassDamping))
        return FieldError(EError::OutOfRange, "mMassDamping", inSettings.mMassDamping, "1/s", "must be at most 1e9");
    if (!(inSettings.mStiffnessDamping <= FemMaterialSettings::cMaxStiffnessDamping))
        return FieldError(EError::OutOfRange, "mStiffnessDamping", inSettings.mStiffnessDamping, "s", "must be at most 1e3");
    if (!(inSettings.mMassDamping >= 0.0))
        return FieldError(EError::InvalidArgument, "mMassDamping", inSettings.mMassDamping, "1/s",
                          "must be >= 0 (negative damping adds energy)");
    if (!(inSettings.mStiffnessDamping >= 0.0))
        return FieldError(EError::InvalidArgument, "mStiffnessDamping", inSettings.mStiffnessDamping, "s",
                          "must be >= 0 (negative damping adds energy)");
    if (inSettings.mModel != EElasticModel::StVenantKirchhoff &&
        inSettings.mModel != EElasticModel::CorotatedLinear)
        return FieldError(EError::InvalidArgument, "mModel", static_cast<double>(inSettings.mModel), "",
                          "is not an EElasticModel");

    // Plasticity and fracture: infinity switches them off, NaN is never accepted.
    if (!(inSettings.mYieldStress > 0.0))
        return FieldError(EError::InvalidArgument, "mYieldStress", inSettings.mYieldStress, "Pa",
                          "must be > 0 (infinity: no plasticity)");
    if (!(inSettings.mCreepRate > 0.0))
        return FieldError(EError::InvalidArgument, "mCreepRate", inSettings.mCreepRate, "1/s",
                          "must be > 0 (infinity: instantaneous plastic flow)");
    if (!(inSettings.mMaxPlasticStrain >= 0.0 && std::isfinite(inSettings.mMaxPlasticStrain)))
        return FieldError(EError::InvalidArgument, "mMaxPlasticStrain", inSettings.mMaxPlasticStrain, "",
                          "must be finite and >= 0");
    if (!(inSettings.mTensileStrength > 0.0))
        return FieldError(EError::InvalidArgument, "mTensileStrength", inSettings.mTensileStrength, "Pa",
                          "must be > 0 (infinity: unbreakable)");
    if (inSettings.mFractureMode != EFractureMode::CrackPlane &&
        inSettings.mFractureMode != EFractureMode::DetachGroup)
        return FieldError(EError::InvalidArgument, "mFractureMode", static_cast<double>(inSettings.mFractureMode),
                          "", "is not an EFractureMode");
    return FemMaterial(inSettings);
}

FemMaterial::FemMaterial(const FemMaterialSettings& inSettings)
    : mSettings(inSettings),
      mMaterialMatrix(IsotropicMaterialMatrix(inSettings.mYoungsModulus, inSettings.mPoissonRatio)),
      mLambda(inSettings.mYoungsModulus * inSettings.mPoissonRatio /
              ((1.0 + inSettings.mPoissonRatio) * (1.0 - 2.0 * inSettings.mPoissonRatio))),
      mShearModulus(inSettings.mYoungsModulus / (2.0 * (1.0 + inSettings.mPoissonRatio)))
{
}

double FemMaterial::GetWaveSpeed() const
{
    return std::sqrt((mLambda + 2.0 * mShearModulus) / mSettings.mDensity);
}

bool FemMaterial::IsPlastic() const
{
    return std::isfinite(mSettings.mYieldStress);
}

bool FemMaterial::IsBreakable() const
{
    return std::isfinite(mSettings.mTensileStrength);
}

} // namespace crumple::fem
