// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/plugin/DamageMaterial.h>

#include <crumple/ffd/TriangleMesh.h>

#include <cmath>
#include <string>

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
    // intent: a zone's own A, B and G (the sides', the rear's), checked only when the material has them
    const auto zone = [](bool inHas, const char* inName, double inA, double inB, double inG) -> Status
    {
        if (!inHas)
            return Status::Ok();
        const std::string field = std::string("DamageMaterial.m") + inName + "Crush";
        if (!(inA >= 0.0 && inA <= 1.0e12))
            return MakeError(EError::InvalidArgument, field + "A must be in [0, 1e12] N/m");
        if (!(inB > 0.0 && inB <= 1.0e12))
            return MakeError(EError::InvalidArgument, field + "B must be in (0, 1e12] N/m^2");
        if (!(inG >= 0.0 && inG <= 1.0e12))
            return MakeError(EError::InvalidArgument, field + "G must be in [0, 1e12] J/m");
        return Status::Ok();
    };
    if (Status side = zone(material.mHasSideStiffness, "Side", material.mSideCrushA, material.mSideCrushB,
                           material.mSideCrushG);
        !side)
        return side;
    if (Status rear = zone(material.mHasRearStiffness, "Rear", material.mRearCrushA, material.mRearCrushB,
                           material.mRearCrushG);
        !rear)
        return rear;
    if (!(std::isfinite(material.mMinCrushWidth) && material.mMinCrushWidth > 0.0))
        return MakeError(EError::InvalidArgument, "DamageMaterial.mMinCrushWidth must be finite and > 0 m");
    if (!(material.mCrushedLengthFraction >= 0.0 && material.mCrushedLengthFraction < 1.0))
        return MakeError(EError::InvalidArgument, "DamageMaterial.mCrushedLengthFraction must be in [0, 1)");
    if (!(material.mCrushZoneFraction > 0.0 && material.mCrushZoneFraction <= 0.5))
        return MakeError(EError::InvalidArgument, "DamageMaterial.mCrushZoneFraction must be in (0, 0.5]");
    return Status::Ok();
}

} // namespace crumple::plugin
