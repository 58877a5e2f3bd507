// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/plugin/DamageMaterial.h>

#include <crumple/ffd/TriangleMesh.h>

#include <cmath>

namespace crumple::plugin
{

Status ValidateDamageMaterial(const DamageMaterial& inMaterial)
{
    const DamageMaterial& material = inMaterial;
    if (!(std::isfinite(material.mDeformationFactor) && material.mDeformationFactor >= 0.0))
        return MakeError(EError::InvalidArgument, "DamageMaterial.mDeformationFactor must be finite and >= 0 m/(N s)");
    if (!(std::isfinite(material.mMinDeformation) && material.mMinDeformation >= 0.0))
        return MakeError(EError::InvalidArgument, "DamageMaterial.mMinDeformation must be finite and >= 0 m");
    // intent: at most what FfdDeformer::ApplyDent takes (ffd::cMaxMeshCoordinate), so a dent the material allows
    // is never refused there
    if (!(std::isfinite(material.mMaxInstantDeformation) && material.mMaxInstantDeformation >= material.mMinDeformation &&
          material.mMaxInstantDeformation <= ffd::cMaxMeshCoordinate))
        return MakeError(EError::InvalidArgument,
                         "DamageMaterial.mMaxInstantDeformation must be finite, >= mMinDeformation and <= 1e6 m");
    if (!(std::isfinite(material.mImpulseThreshold) && material.mImpulseThreshold >= 0.0))
        return MakeError(EError::InvalidArgument, "DamageMaterial.mImpulseThreshold must be finite and >= 0 N s");
    if (material.mModel != ECrushModel::ImpulseFactor && material.mModel != ECrushModel::Campbell)
        return MakeError(EError::InvalidArgument, "DamageMaterial.mModel must be ImpulseFactor or Campbell");
    // Campbell stiffnesses within 1e12 (a car's are about 1e4-1e6): their products cannot overflow.
    if (!(material.mCrushA >= 0.0 && material.mCrushA <= 1.0e12))
        return MakeError(EError::InvalidArgument, "DamageMaterial.mCrushA must be in [0, 1e12] N/m");
    if (!(material.mCrushB > 0.0 && material.mCrushB <= 1.0e12))
        return MakeError(EError::InvalidArgument, "DamageMaterial.mCrushB must be in (0, 1e12] N/m^2");
    if (!(material.mCrushG >= 0.0 && material.mCrushG <= 1.0e12))
        return MakeError(EError::InvalidArgument, "DamageMaterial.mCrushG must be in [0, 1e12] J/m");
    if (material.mHasSideStiffness)
    {
        if (!(material.mSideCrushA >= 0.0 && material.mSideCrushA <= 1.0e12))
            return MakeError(EError::InvalidArgument, "DamageMaterial.mSideCrushA must be in [0, 1e12] N/m");
        if (!(material.mSideCrushB > 0.0 && material.mSideCrushB <= 1.0e12))
            return MakeError(EError::InvalidArgument,
                             "DamageMaterial.mSideCrushB must be in (0, 1e12] N/m^2");
        if (!(material.mSideCrushG >= 0.0 && material.mSideCrushG <= 1.0e12))
            return MakeError(EError::InvalidArgument, "DamageMaterial.mSideCrushG must be in [0, 1e12] J/m");
    }
    if (material.mHasRearStiffness)
    {
        if (!(material.mRearCrushA >= 0.0 && material.mRearCrushA <= 1.0e12))
            return MakeError(EError::InvalidArgument, "DamageMaterial.mRearCrushA must be in [0, 1e12] N/m");
        if (!(material.mRearCrushB > 0.0 && material.mRearCrushB <= 1.0e12))
            return MakeError(EError::InvalidArgument,
                             "DamageMaterial.mRearCrushB must be in (0, 1e12] N/m^2");
        if (!(material.mRearCrushG >= 0.0 && material.mRearCrushG <= 1.0e12))
            return MakeError(EError::InvalidArgument, "DamageMaterial.mRearCrushG must be in [0, 1e12] J/m");
    }
    if (!(std::isfinite(material.mMinCrushWidth) && material.mMinCrushWidth > 0.0))
        return MakeError(EError::InvalidArgument, "DamageMaterial.mMinCrushWidth must be finite and > 0 m");
    if (!(material.mCrushedLengthFraction >= 0.0 && material.mCrushedLengthFraction < 1.0))
        return MakeError(EError::InvalidArgument, "DamageMaterial.mCrushedLengthFraction must be in [0, 1)");
    if (!(material.mCrushZoneFraction > 0.0 && material.mCrushZoneFraction <= 0.5))
        return MakeError(EError::InvalidArgument, "DamageMaterial.mCrushZoneFraction must be in (0, 0.5]");
    return Status::Ok();
}

} // namespace crumple::plugin
