// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/ffd/FfdDeformer.h>
#include <crumple/plugin/CampbellCrush.h>
#include <crumple/plugin/Collision.h>
#include <crumple/plugin/DeformableObjectSettings.h>

#include <vector>

namespace crumple::plugin
{

/// A deformable object: material plus an FFD deformer over its render mesh.
class CRUMPLE_API DeformableObject
{
public:
    /// Validates the material and builds the deformer (fitting a zone when none is given).
    static Result<DeformableObject> Create(const DeformableObjectSettings& inSettings);

    /// The dent a collision asks of this object (D4MD section 6.2), in the body frame:
    /// every contact moves along one direction, the impulse-weighted mean of the inward normals (so one
    /// collision dents consistently), by depth_i = factor * J * (j_i / j_max), where J is the collision's
    /// total impulse: the dent's depth follows the impulse of the impact, its shape the way the impulse was
    /// distributed, and neither depends on how many points the engine reported. Depths below the minimum
    /// are dropped, above the instantaneous maximum clamped. Wide contact sets are then interpolated.
    /// @param[out] outClamped  when not null, the number of contacts whose depth was clamped to the maximum
    std::vector<ffd::PointDisplacement> DentFor(const Collision& inCollision, ECollisionSide inSide,
                                                int* outClamped = nullptr) const;

    /// The dent of a collision. ECrushModel::ImpulseFactor: DentFor, then ApplyDent with the instantaneous
    /// maximum as the step bound, so that no vertex (not only no contact point) moves further than
    /// mMaxInstantDeformation in one collision. ECrushModel::Campbell: the collision's crush energy for this
    /// side (Collision::mCrushEnergyA/B) crushes the footprint (PlanCampbellCrush, ApplyCrushPlan); a depth
    /// cut to the instantaneous maximum counts as one clamped contact.
    /// A collision that ValidateCollision refuses (a hand-made one with a NaN, say) returns its error and
    /// changes nothing; every collision a DamageWorld dispatches passes.
    Result<ffd::DentReport> ApplyCollision(const Collision& inCollision, ECollisionSide inSide);

    const DamageMaterial& GetMaterial() const { return mMaterial; }
    bool GetInterpolateWideImpacts() const { return mInterpolate; }
    /// The body's up direction (body frame, unit)
    const Vec3& GetUpAxis() const { return mUp; }
    /// What a Campbell crush plan measures of the body once (MeasureCrushBody): its length, where the
    /// occupant cell lies, and its large triangles
    const CrushBody& GetCrushBody() const { return mCrushBody; }
    /// Whether the object's lattice keeps its occupant cell apart from its crush zones (FitOccupantCell): a
    /// lost cell (OccupantCellFit::IsLost) lets a crush along the body move the whole body; a finer lattice
    /// (mFittedControlSpacing, or zones of that spacing along the length) keeps it
    OccupantCellFit GetOccupantCellFit() const
    {
        return FitOccupantCell(mMaterial, mCrushBody.mLength, mDeformer);
    }
    const ffd::FfdDeformer& GetDeformer() const { return mDeformer; }
    ffd::FfdDeformer& GetDeformer() { return mDeformer; }

private:
    DeformableObject(const DamageMaterial& inMaterial, bool inInterpolate, const Vec3& inUp, CrushBody inCrushBody,
                     ffd::FfdDeformer inDeformer)
        : mMaterial(inMaterial), mInterpolate(inInterpolate), mUp(inUp), mCrushBody(std::move(inCrushBody)), mDeformer(std::move(inDeformer)) {}

    DamageMaterial mMaterial;
    bool mInterpolate = true;
    Vec3 mUp = Vec3::UnitZ();
    CrushBody mCrushBody;
    ffd::FfdDeformer mDeformer;
};

} // namespace crumple::plugin
