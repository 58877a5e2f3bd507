// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/ffd/BoundingBox.h>
#include <crumple/ffd/InterpolateWideImpact.h>
#include <crumple/plugin/CampbellCrush.h>
#include <crumple/plugin/DeformableObject.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace crumple::plugin
{

std::array<int, 3> ControlCountForSpacing(const Vec3& inSize, double inSpacing)
{
    // A mesh far larger than a car (or in the wrong unit) must not allocate gigabytes of controls: past
    // cMaxControls the spacing widens by 25 % steps until the lattice fits (2^18 controls are 6 MB).
    constexpr double cMaxControls = 262144.0;
    constexpr double cMaxCells = ffd::FfdLatticeSettings::cMaxControlsPerAxis - 3;
    std::array<int, 3> count{};
    // A non-finite size (a mesh whose extent overflows) would never fit: the coarsest lattice, which
    // FfdDeformer::Create then refuses with its own message about the box.
    if (!IsFinite(inSize) || !(inSpacing > 0.0))
        return {4, 4, 4};
    for (double spacing = inSpacing;; spacing *= 1.25)
    {
        double total = 1.0;
        for (int axis = 0; axis < 3; ++axis)
        {
            // Clamp in double first, so that a huge ratio cannot overflow the cast.
            const double cells = std::clamp(std::ceil(inSize[axis] / spacing), 1.0, cMaxCells);
            count[static_cast<std::size_t>(axis)] = static_cast<int>(cells) + 3;
            total *= cells + 3.0;
        }
        if (total <= cMaxControls)
            return count;
    }
}

ffd::FfdZoneSettings FitZoneToMesh(const ffd::TriangleMesh& inMesh, const std::array<int, 3>& inControlCount,
                                   double inMaxTotalDeformation, double inSpacing)
{
    const ffd::AlignedBox bounds = ffd::BoundingBox(inMesh.mPositions);
    const Vec3 lo = bounds.mMin, hi = bounds.mMax;
    // The margin keeps surface vertices strictly inside, where the spline is defined.
    const Vec3 margin = 0.01 * (hi - lo) + Vec3::Constant(1.0e-3);
    ffd::FfdZoneSettings zone;
    zone.mLattice.mOrigin = lo - margin;
    zone.mLattice.mSize = (hi - lo) + 2.0 * margin;
    const bool from_spacing = inControlCount == std::array<int, 3>{0, 0, 0};
    zone.mLattice.mControlCount = from_spacing ? ControlCountForSpacing(zone.mLattice.mSize, inSpacing) : inControlCount;
    zone.mMaxTotalDeformation = inMaxTotalDeformation;
    return zone;
}

Result<DeformableObject> DeformableObject::Create(const DeformableObjectSettings& inSettings)
{
    const DamageMaterial& material = inSettings.mMaterial;
    if (Status valid = ValidateDamageMaterial(material); !valid)
        return valid.GetError();
    if (!(IsFinite(inSettings.mUpAxis) && std::abs(inSettings.mUpAxis.norm() - 1.0) <= 1.0e-3))
        return MakeError(EError::InvalidArgument, "DeformableObjectSettings.mUpAxis must be a unit vector");

    // intent: the forward axis matters only to a material with the rear's stiffness; others keep any value
    if (material.mHasRearStiffness &&
        !(IsFinite(inSettings.mForwardAxis) && std::abs(inSettings.mForwardAxis.norm() - 1.0) <= 1.0e-3 &&
          std::abs(inSettings.mForwardAxis.dot(inSettings.mUpAxis)) <= 1.0e-3))
        return MakeError(EError::InvalidArgument,
                         "DeformableObjectSettings.mForwardAxis must be a unit vector across mUpAxis (the "
                         "material has the rear's stiffness)");
    if (!(std::isfinite(inSettings.mFittedControlSpacing) && inSettings.mFittedControlSpacing > 0.0))
        return MakeError(EError::InvalidArgument, "DeformableObjectSettings.mFittedControlSpacing must be finite and > 0 m");

    ffd::FfdDeformerSettings deformer_settings = inSettings.mDeformer;
    if (deformer_settings.mZones.empty())
    {
        if (Status mesh = ffd::ValidateTriangleMesh(inSettings.mMesh); !mesh)
            return mesh.GetError();
        // intent: a short body needs a finer lattice than the given spacing to keep its occupant cell
        double spacing = inSettings.mFittedControlSpacing;
        if (inSettings.mFitSpacingToOccupantCell &&
            inSettings.mFittedControlCount == std::array<int, 3>{0, 0, 0})
        {
            const BodyLength length = MeasureBodyLength(inSettings.mMesh.mPositions, inSettings.mUpAxis);
            spacing = std::min(spacing, OccupantCellMaxSpacing(material, length.mMax - length.mMin));
        }
        deformer_settings.mZones.push_back(FitZoneToMesh(inSettings.mMesh, inSettings.mFittedControlCount,
                                                         inSettings.mFittedMaxTotalDeformation, spacing));
    }
    Result<ffd::FfdDeformer> deformer = ffd::FfdDeformer::Create(inSettings.mMesh, deformer_settings);
    if (!deformer)
        return deformer.GetError();
    // The up axis as given (within 1e-3 of unit): a recording keeps it bit for bit, and the crush only
    // takes its direction.
    CrushBody body = MeasureCrushBody(deformer.Get(), inSettings.mUpAxis);
    body.mForward = inSettings.mForwardAxis;
    return DeformableObject(material, inSettings.mInterpolateWideImpacts, inSettings.mUpAxis, std::move(body), std::move(deformer).Get());
}

std::vector<ffd::PointDisplacement> DeformableObject::DentFor(const Collision& inCollision, ECollisionSide inSide,
                                                              int* outClamped) const
{
    std::vector<ffd::PointDisplacement> dent;
    int clamped = 0;
    const bool side_a = inSide == ECollisionSide::A;

    // One direction for the whole collision: impulse-weighted mean inward normal.
    Vec3 direction = Vec3::Zero();
    double total = 0.0, peak = 0.0;
    for (const CollisionContact& c : inCollision.mContacts)
    {
        direction += c.mImpulse * (side_a ? c.mLocalNormalOnA : Vec3(-c.mLocalNormalOnB));
        total += c.mImpulse;
        peak = std::max(peak, c.mImpulse);
    }
    // intent: impulses near the double range (a hand-made collision) overflow the weighted sum: weigh by each
    // contact's share of the peak instead (the same direction, without the overflow; kept as the fallback so
    // that every collision an engine makes keeps its bits)
    if (!IsFinite(direction) && peak > 0.0)
    {
        direction.setZero();
        for (const CollisionContact& c : inCollision.mContacts)
            direction += (c.mImpulse / peak) * (side_a ? c.mLocalNormalOnA : Vec3(-c.mLocalNormalOnB));
    }
    const double length = direction.norm();
    if (!(length > 0.0) || !(peak > 0.0) || !std::isfinite(length))
        return dent;
    direction /= length;

    // Depth from the collision's impulse beyond the no-damage threshold, shape from each contact's share.
    const double effective = std::max(0.0, total - mMaterial.mImpulseThreshold);
    for (const CollisionContact& c : inCollision.mContacts)
    {
        double depth = mMaterial.mDeformationFactor * effective * (c.mImpulse / peak);
        if (!(depth >= mMaterial.mMinDeformation) || depth <= 0.0)
            continue;
        clamped += depth > mMaterial.mMaxInstantDeformation ? 1 : 0;
        depth = std::min(depth, mMaterial.mMaxInstantDeformation);
        dent.push_back({side_a ? c.mLocalPointOnA : c.mLocalPointOnB, depth * direction});
    }
    if (mInterpolate && dent.size() > 1)
        dent = ffd::InterpolateWideImpact(dent, mDeformer.GetMinSpacing());
    if (outClamped != nullptr)
        *outClamped = clamped;
    return dent;
}

Result<ffd::DentReport> DeformableObject::ApplyCollision(const Collision& inCollision, ECollisionSide inSide)
{
    if (inSide != ECollisionSide::A && inSide != ECollisionSide::B)
        return MakeError(EError::InvalidArgument,
                         "DeformableObject::ApplyCollision: the side is not an ECollisionSide value");
    if (Status valid = ValidateCollision(inCollision); !valid)
        return valid.GetError();
    if (mMaterial.mModel == ECrushModel::Campbell)
    {
        const double energy = inSide == ECollisionSide::A ? inCollision.mCrushEnergyA : inCollision.mCrushEnergyB;
        const std::optional<CrushPlan> plan = PlanCampbellCrush(inCollision, inSide, energy, mMaterial, mUp, mDeformer, &mCrushBody);
        if (!plan)
            return ffd::DentReport{};
        ffd::DentReport report = ApplyCrushPlan(*plan, mMaterial.mMaxInstantDeformation, mDeformer);
        report.mContactsClamped = plan->mClamped ? 1 : 0;
        report.mStackedUp = plan->mStackedUp ? 1 : 0;
        return report;
    }
    int clamped = 0;
    const std::vector<ffd::PointDisplacement> dent = DentFor(inCollision, inSide, &clamped);
    if (dent.empty())
        return ffd::DentReport{};
    // The collision is finite and bounded, so the dent is (ApplyDent checks it again and refuses the whole
    // dent).
    Result<ffd::DentReport> report = mDeformer.ApplyDent(dent, mMaterial.mMaxInstantDeformation);
    if (report)
        report.Get().mContactsClamped = clamped;
    return report;
}

} // namespace crumple::plugin
