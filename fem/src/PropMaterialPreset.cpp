// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/PropMaterialPreset.h>

#include <limits>
#include <string>

namespace crumple::fem
{

namespace
{

constexpr double cOff = std::numeric_limits<double>::infinity();

// The physical half of a preset; plasticity and fracture off unless set afterwards.
FemMaterialSettings Physical(double inYoungsModulus, double inPoissonRatio, double inDensity,
                             double inMassDamping, double inStiffnessDamping, double inTensileStrength,
                             EFractureMode inMode)
{
    FemMaterialSettings settings;
    settings.mYoungsModulus = inYoungsModulus;
    settings.mPoissonRatio = inPoissonRatio;
    settings.mDensity = inDensity;
    settings.mMassDamping = inMassDamping;
    settings.mStiffnessDamping = inStiffnessDamping;
    settings.mYieldStress = cOff;
    settings.mTensileStrength = inTensileStrength;
    settings.mFractureMode = inMode;
    return settings;
}

// The display half of a preset.
ProceduralEdgeSettings Edges(double inWidth, double inHeight, double inRandomWidth, double inRandomHeight,
                             double inHorizontalFrequency, double inVerticalFrequency,
                             double inHorizontalAmplitude, double inVerticalAmplitude)
{
    ProceduralEdgeSettings settings;
    settings.mAverageSectionWidth = inWidth;
    settings.mAverageSectionHeight = inHeight;
    settings.mRandomSectionWidth = inRandomWidth;
    settings.mRandomSectionHeight = inRandomHeight;
    settings.mHorizontalEdgeFrequency = inHorizontalFrequency;
    settings.mVerticalEdgeFrequency = inVerticalFrequency;
    settings.mHorizontalEdgeAmplitude = inHorizontalAmplitude;
    settings.mVerticalEdgeAmplitude = inVerticalAmplitude;
    settings.mSeed = 0;
    return settings;
}

} // namespace

Result<PropMaterialPreset> MakePropMaterialPreset(EPropMaterial inMaterial)
{
    // Values and their sources are listed in the header.
    PropMaterialPreset preset;
    switch (inMaterial)
    {
    case EPropMaterial::Glass:
        preset.mMaterial = Physical(70.0e9, 0.22, 2500.0, 0.2, 2.0e-6, 50.0e6, EFractureMode::DetachGroup);
        preset.mEdges = Edges(0.2, 0.2, 0.2, 0.2, 5.0, 5.0, 0.01, 0.01);
        return preset;
    case EPropMaterial::Wood:
        preset.mMaterial = Physical(10.0e9, 0.3, 500.0, 0.2, 2.0e-6, 40.0e6, EFractureMode::CrackPlane);
        preset.mEdges = Edges(0.6, 0.1, 0.3, 0.05, 40.0, 0.0, 0.024, 0.0);
        return preset;
    case EPropMaterial::Brick:
        preset.mMaterial = Physical(12.0e9, 0.2, 1900.0, 0.2, 4.0e-6, 1.5e6, EFractureMode::DetachGroup);
        preset.mEdges = Edges(0.215, 0.065, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
        return preset;
    case EPropMaterial::Rubber:
        preset.mMaterial = Physical(5.0e6, 0.49, 1100.0, 1.0, 4.0e-5, 25.0e6, EFractureMode::CrackPlane);
        preset.mEdges = Edges(0.5, 0.5, 0.1, 0.1, 2.0, 2.0, 0.01, 0.01);
        return preset;
    case EPropMaterial::Steel:
        preset.mMaterial = Physical(210.0e9, 0.3, 7850.0, 0.2, 2.0e-6, 360.0e6, EFractureMode::CrackPlane);
        preset.mMaterial.mYieldStress = 235.0e6;
        preset.mMaterial.mCreepRate = cOff;
        preset.mMaterial.mMaxPlasticStrain = 0.25;
        preset.mEdges = Edges(0.5, 0.5, 0.1, 0.1, 2.0, 2.0, 0.005, 0.005);
        return preset;
    }
    return MakeError(EError::InvalidArgument,
                     "MakePropMaterialPreset: " + std::to_string(static_cast<int>(inMaterial)) +
                         " is not an EPropMaterial");
}

} // namespace crumple::fem
