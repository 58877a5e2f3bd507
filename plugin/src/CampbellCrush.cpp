// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/plugin/CampbellCrush.h>

#include "StruckFront.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cmath>
#include <limits>
#include <vector>

namespace crumple::plugin
{

namespace
{

// A contact's point and inward normal in the frame of the side's body.
Vec3 SidePoint(const CollisionContact& inContact, ECollisionSide inSide)
{
    return inSide == ECollisionSide::A ? inContact.mLocalPointOnA : inContact.mLocalPointOnB;
}

Vec3 SideInwardNormal(const CollisionContact& inContact, ECollisionSide inSide)
{
    return inSide == ECollisionSide::A ? inContact.mLocalNormalOnA : Vec3(-inContact.mLocalNormalOnB);
}

// Impulse-weighted mean inward normal; zero when no contact pushes.
Vec3 CrushDirection(const Collision& inCollision, ECollisionSide inSide)
{
    Vec3 direction = Vec3::Zero();
    for (const CollisionContact& c : inCollision.mContacts)
        direction += c.mImpulse * SideInwardNormal(c, inSide);
    const double length = direction.norm();
    return length > 0.0 ? Vec3(direction / length) : Vec3::Zero();
}

// The axis across the crush that measures its width: perpendicular to up and to d. A crush along up (a car
// landing on its roof) has no such axis; any perpendicular to d is taken, the least aligned body axis's.
Vec3 WidthAxis(const Vec3& inDirection, const Vec3& inUp)
{
    const Vec3 across = inUp.cross(inDirection);
    if (across.norm() > 0.1)
        return across.normalized();
    Eigen::Index least = 0;
    inDirection.cwiseAbs().minCoeff(&least);
    return inDirection.cross(Vec3::Unit(least)).normalized();
}

// [lo, hi] widened symmetrically to at least inMinWidth.
void Widen(double& ioLo, double& ioHi, double inMinWidth)
{
    const double missing = inMinWidth - (ioHi - ioLo);
    if (missing > 0.0)
    {
        ioLo -= 0.5 * missing;
        ioHi += 0.5 * missing;
    }
}

// The impactor's footprint on this side: the crush direction, the axes across it and the rectangle the
// pushing contacts span there, widened to inMinWidth (the prism the crush planner probes the surface with).
std::optional<ffd::SurfaceProbe> FootprintOf(const Collision& inCollision, ECollisionSide inSide, const Vec3& inUp,
                                             double inMinWidth)
{
    ffd::SurfaceProbe footprint;
    footprint.mDirection = CrushDirection(inCollision, inSide);
    if (footprint.mDirection.isZero(0.0))
        return std::nullopt;
    footprint.mSide = WidthAxis(footprint.mDirection, inUp);
    footprint.mThird = footprint.mDirection.cross(footprint.mSide);
    constexpr double cInf = std::numeric_limits<double>::infinity();
    footprint.mSideMin = footprint.mThirdMin = cInf;
    footprint.mSideMax = footprint.mThirdMax = -cInf;
    for (const CollisionContact& c : inCollision.mContacts)
    {
        if (!(c.mImpulse > 0.0))
            continue;
        const Vec3 p = SidePoint(c, inSide);
        footprint.mSideMin = std::min(footprint.mSideMin, footprint.mSide.dot(p));
        footprint.mSideMax = std::max(footprint.mSideMax, footprint.mSide.dot(p));
        footprint.mThirdMin = std::min(footprint.mThirdMin, footprint.mThird.dot(p));
        footprint.mThirdMax = std::max(footprint.mThirdMax, footprint.mThird.dot(p));
    }
    Widen(footprint.mSideMin, footprint.mSideMax, inMinWidth);
    Widen(footprint.mThirdMin, footprint.mThirdMax, inMinWidth);
    return footprint;
}

// The controls a of lattice row (b, c) that the plan's field can reach, as an index range (empty: low >
// high). The field is nonzero only where d.p < s0 + f + L and the side and third coordinates lie within the
// footprint widened by f + ramp (CrushPlan::DisplacementAt); a control is at its rest position r(a) = r0 + a e
// moved by at most inMoved, so each of the five bounds holds on an interval of a. A hair on each bound and one
// index of slack on each side absorb the round-off; the field itself decides inside the range.
std::array<int, 2> FieldRangeOnRow(const CrushPlan& inPlan, const ffd::FfdLattice& inZone, int inB, int inC, double inMoved)
{
    const int last = inZone.GetSettings().mControlCount[0] - 1;
    const Vec3 r0 = inZone.RestControlPosition(0, inB, inC);
    const Vec3 e = inZone.RestControlPosition(1, inB, inC) - r0;
    double low = 0.0, high = static_cast<double>(last);
    // u.r(a) < inLimit, widened by the move
    auto below = [&](const Vec3& inU, double inLimit) {
        const double start = inU.dot(r0), slope = inU.dot(e);
        const double limit = inLimit + inMoved + 1.0e-9 * (1.0 + std::abs(inLimit) + std::abs(start));
        if (slope > 0.0)
            high = std::min(high, (limit - start) / slope);
        else if (slope < 0.0)
            low = std::max(low, (limit - start) / slope);
        else if (!(start < limit))
            high = -1.0;
    };
    const double across = inPlan.mFlatLayer + inPlan.mRamp;
    // A column behind the front by F reaches F + max((C - F) / (1 - kappa), h) <= max(L, C + h).
    below(inPlan.mDirection, inPlan.mFront + inPlan.mFlatLayer + std::max(inPlan.mZoneLength, inPlan.mDepth + inPlan.mSpacing));
    below(inPlan.mSide, inPlan.mSideMax + across);
    below(-inPlan.mSide, -(inPlan.mSideMin - across));
    below(inPlan.mThird, inPlan.mThirdMax + across);
    below(-inPlan.mThird, -(inPlan.mThirdMin - across));
    if (!(low <= high)) // empty (ApplyCrushPlan takes finite plans only)
        return {1, 0};
    return {std::max(static_cast<int>(std::floor(low)) - 1, 0), std::min(static_cast<int>(std::ceil(high)) + 1, last)};
}

// The lattice's coarsest control spacing along the unit direction inAlong, over the deformer's zones (m).
double CoarsestSpacingAlong(const ffd::FfdDeformer& inDeformer, const Vec3& inAlong)
{
    double spacing = 0.0;
    for (const ffd::FfdLattice& zone : inDeformer.GetZones())
        spacing = std::max(spacing, (zone.GetSettings().mAxes.transpose() * inAlong).cwiseAbs().cwiseProduct(zone.GetSpacing()).sum());
    return spacing;
}

CrossRect Union(const CrossRect& inA, const CrossRect& inB)
{
    return {std::min(inA.mSideMin, inB.mSideMin), std::max(inA.mSideMax, inB.mSideMax), std::min(inA.mThirdMin, inB.mThirdMin),
            std::max(inA.mThirdMax, inB.mThirdMax)};
}

// Where the impactor's face can meet the body across the plan's direction: the impactor's shape box across
// d, within the body's rest bounding box across d. None when they do not overlap.
std::optional<CrossRect> ImpactorFace(const CrushPlan& inPlan, const ShapeBox& inImpactor, const CrushBody& inBody)
{
    const ShapeBox outline{0.5 * (inBody.mRestMin + inBody.mRestMax), Mat3((0.5 * (inBody.mRestMax - inBody.mRestMin)).asDiagonal()), true};
    const std::array<double, 2> side = inImpactor.ExtentAlong(inPlan.mSide), third = inImpactor.ExtentAlong(inPlan.mThird);
    const std::array<double, 2> body_side = outline.ExtentAlong(inPlan.mSide), body_third = outline.ExtentAlong(inPlan.mThird);
    const CrossRect face{std::max(side[0], body_side[0]), std::min(side[1], body_side[1]), std::max(third[0], body_third[0]),
                         std::min(third[1], body_third[1])};
    if (!(face.mSideMin <= face.mSideMax && face.mThirdMin <= face.mThirdMax))
        return std::nullopt;
    return face;
}

// Calls inVisit(side, third, depth) for each bin of inBins that overlaps inFace: its centre across d (m) and
// its surface's depth behind the front (SurfaceBins).
template <class Visit>
void ForEachFaceBin(const CrossRect& inFace, const SurfaceBins& inBins, Visit&& inVisit)
{
    const double half = 0.5 * inBins.mBin;
    for (int j = 0; j < inBins.mThirdCount; ++j)
    {
        const double third = inBins.mThirdOrigin + j * inBins.mBin;
        if (!(third + half > inFace.mThirdMin && third - half < inFace.mThirdMax))
            continue;
        for (int i = 0; i < inBins.mSideCount; ++i)
        {
            const double side = inBins.mSideOrigin + i * inBins.mBin;
            if (side + half > inFace.mSideMin && side - half < inFace.mSideMax)
                inVisit(side, third,
                        inBins.mDepth[static_cast<std::size_t>(j) * static_cast<std::size_t>(inBins.mSideCount) + static_cast<std::size_t>(i)]);
        }
    }
}

// The footprint of a crush C deep against the impactor's face: the rectangle the contacts span and the
// face's bins whose surface lies less than C behind the front (the impactor, advancing C, reaches them), each
// bin counted whole where it overlaps the face, widened to inMinWidth as the contacts' own footprint is.
CrossRect FootprintAtDepth(const CrossRect& inContacts, const CrossRect& inFace, const SurfaceBins& inBins, double inDepth,
                           double inMinWidth)
{
    CrossRect footprint = inContacts;
    const double half = 0.5 * inBins.mBin;
    ForEachFaceBin(inFace, inBins, [&](double inSide, double inThird, double inBinDepth) {
        if (!(inBinDepth < inDepth))
            return;
        footprint.mSideMin = std::min(footprint.mSideMin, std::max(inSide - half, inFace.mSideMin));
        footprint.mSideMax = std::max(footprint.mSideMax, std::min(inSide + half, inFace.mSideMax));
        footprint.mThirdMin = std::min(footprint.mThirdMin, std::max(inThird - half, inFace.mThirdMin));
        footprint.mThirdMax = std::max(footprint.mThirdMax, std::min(inThird + half, inFace.mThirdMax));
    });
    Widen(footprint.mSideMin, footprint.mSideMax, inMinWidth);
    Widen(footprint.mThirdMin, footprint.mThirdMax, inMinWidth);
    return footprint;
}

// A crush against an impactor whose face reaches past the contacts (a wall before a rounded nose): the
// footprint grows to the surface the face reaches as it advances, and a wider footprint takes the energy at a
// shallower crush. The footprint changes only where C passes the depth t of a bin in the face: between two
// such depths it is fixed, F_j (the bins no deeper than t_j), and its crush h(F_j) falls as j grows. The
// crush is h(F_j) for the first j whose crush does not reach the next bin depth t_(j+1): a fixed point
// C = h(Footprint(C)) where one exists, else the jump across t_j (the bins at t_j then count in the width but
// crush nothing). Found by binary search over the sorted depths, a dozen profile integrals at most. Leaves
// that footprint on ioPlan and returns the crush. inContacts: the contacts' span, not widened.
double ConformToImpactor(CrushPlan& ioPlan, const CrossRect& inContacts, const CrossRect& inFace, const SurfaceBins& inBins,
                         const DamageMaterial& inMaterial, double inPrevious, double inEnergy)
{
    const double min_width = inMaterial.mMinCrushWidth;
    auto depth_over = [&](const CrossRect& inFootprint) {
        ioPlan.mSideMin = inFootprint.mSideMin;
        ioPlan.mSideMax = inFootprint.mSideMax;
        ioPlan.mThirdMin = inFootprint.mThirdMin;
        ioPlan.mThirdMax = inFootprint.mThirdMax;
        ioPlan.mWidth = ioPlan.mSideMax - ioPlan.mSideMin;
        const double absorbed = CampbellCrushEnergy(inMaterial, ioPlan.mWidth, inPrevious);
        const double flat = CampbellCrushDepth(inMaterial, ioPlan.mWidth, absorbed + inEnergy) - inPrevious;
        if (!(flat > 0.0) || ioPlan.mStruckFront.mDepth.empty())
            return flat;
        return ProfileCrushDepth(ioPlan, inMaterial, inPrevious, inEnergy, flat);
    };
    // F_-1: the contacts' own footprint (no bin is reached before the crush begins).
    const double contacts_crush = depth_over(FootprintAtDepth(inContacts, inFace, inBins, 0.0, min_width));
    if (!(contacts_crush > 0.0))
        return contacts_crush;
    // The depths t_j of the face's bins that the contacts' own crush reaches (no larger crush can follow).
    std::vector<double> depths;
    ForEachFaceBin(inFace, inBins, [&](double, double, double inBinDepth) {
        if (inBinDepth < contacts_crush)
            depths.push_back(inBinDepth);
    });
    std::sort(depths.begin(), depths.end());
    depths.erase(std::unique(depths.begin(), depths.end()), depths.end());
    // F_j holds the bins with depth <= t_j: the footprint of any C in (t_j, t_(j+1)].
    auto footprint = [&](std::size_t inJ) {
        return FootprintAtDepth(inContacts, inFace, inBins, std::nextafter(depths[inJ], std::numeric_limits<double>::infinity()), min_width);
    };
    // The first j (-1 .. n-1) with h(F_j) < t_(j+1), t_n = +inf; j = -1 fails when the contacts' crush reaches t_0.
    if (depths.empty() || contacts_crush < depths.front())
        return contacts_crush; // ioPlan still holds F_-1, its last depth_over
    std::size_t low = 0, high = depths.size() - 1; // the answer's j lies in [low, high]
    while (low < high)
    {
        const std::size_t middle = low + (high - low) / 2;
        if (depth_over(footprint(middle)) < depths[middle + 1])
            high = middle;
        else
            low = middle + 1;
    }
    return depth_over(footprint(low));
}

// The occupant cell's limit on a planned crush (CrushPlan): active when the crush runs within 60 degrees of
// the body's length and the material leaves a cell. Where a footprint column stacks up, its compaction goes
// past kappa, so the pocket's walls widen to keep facing out (the k < 2 sqrt(f) rule of PlanCampbellCrush,
// f the column's remaining fraction); the footprint's corners and centre bound the columns (the cell's face
// is a plane, so the room is linear across the footprint).
void LimitByCell(const DamageMaterial& inMaterial, const BodyLength& inLength, const ffd::FfdDeformer& inDeformer, CrushPlan& ioPlan)
{
    const double extent = inLength.mMax - inLength.mMin;
    const double along = inLength.mAxis.dot(ioPlan.mDirection);
    // A coarser lattice than FitOccupantCell allows cannot keep a cell apart from its crush zone, and crushes
    // as without one.
    const OccupantCellFit fit = FitOccupantCell(inMaterial, inLength, inDeformer);
    if (!fit.mHasCell || fit.IsLost() || !(std::abs(along) >= 0.5))
        return;
    ioPlan.mCellActive = true;
    // The struck end is where the oriented axis comes in from; the cell begins a zone's share of the length
    // further along.
    ioPlan.mCellAxis = along > 0.0 ? inLength.mAxis : Vec3(-inLength.mAxis);
    ioPlan.mCellFace = along > 0.0 ? inLength.mMin + inMaterial.mCrushZoneFraction * extent
                                   : -(inLength.mMax - inMaterial.mCrushZoneFraction * extent);
    const std::array<double, 2> sides{ioPlan.mSideMin, ioPlan.mSideMax};
    const std::array<double, 2> thirds{ioPlan.mThirdMin, ioPlan.mThirdMax};
    std::array<Vec3, 5> columns;
    for (std::size_t k = 0; k < 4; ++k)
        columns[k] = ioPlan.mFront * ioPlan.mDirection + sides[k & 1] * ioPlan.mSide + thirds[k >> 1] * ioPlan.mThird;
    columns[4] = ioPlan.mFront * ioPlan.mDirection + 0.5 * (sides[0] + sides[1]) * ioPlan.mSide +
                 0.5 * (thirds[0] + thirds[1]) * ioPlan.mThird;
    for (const Vec3& column : columns)
    {
        const auto [crush, length, front] = ioPlan.ColumnCrush(column);
        if (crush < ioPlan.mDepth - front)
            ioPlan.mStackedUp = true;
        if (crush > 0.0 && length > 0.0)
            ioPlan.mRamp = std::max(ioPlan.mRamp, crush / (2.0 * std::sqrt(std::max(1.0 - crush / length, 0.01))));
    }
}

} // namespace

double OccupantCellMaxSpacing(const DamageMaterial& inMaterial, double inLength)
{
    // A zone must hold the flat layer, the spacing kept clear of the cell and two spacings to compact over.
    constexpr double cMinZoneSpacings = 4.0;
    if (!(inMaterial.mModel == ECrushModel::Campbell && inMaterial.mCrushZoneFraction < 0.5 &&
          inLength > 0.0))
        return std::numeric_limits<double>::infinity();
    return inMaterial.mCrushZoneFraction * inLength / cMinZoneSpacings;
}

OccupantCellFit FitOccupantCell(const DamageMaterial& inMaterial, const BodyLength& inLength,
                                const ffd::FfdDeformer& inDeformer)
{
    OccupantCellFit fit;
    const double extent = inLength.mMax - inLength.mMin;
    fit.mMaxSpacing = OccupantCellMaxSpacing(inMaterial, extent);
    fit.mHasCell = std::isfinite(fit.mMaxSpacing);
    fit.mZoneLength = inMaterial.mCrushZoneFraction * extent;
    fit.mSpacing = CoarsestSpacingAlong(inDeformer, inLength.mAxis);
    return fit;
}

std::array<double, 3> CrushPlan::ColumnCrush(const Vec3& inPoint) const
{
    // A flat front (no grid): every column starts at mFront and takes the whole crush, exactly as planned.
    const double front = mStruckFront.At(mSide.dot(inPoint), mThird.dot(inPoint));
    const double depth = front > 0.0 ? mDepth - front : mDepth;
    if (!(depth > 0.0))
        return {0.0, 0.0, front};
    const double zone = front > 0.0 ? std::max(depth / (1.0 - mKappa), mSpacing) : mZoneLength;
    if (!mCellActive)
        return {depth, zone, front};
    // Along the column (the line through inPoint along d) the length coordinate grows by a . d per metre:
    // the column enters the cell at this depth behind its flat layer, and keeps one spacing clear of it.
    const double enter = mDirection.dot(inPoint) + (mCellFace - mCellAxis.dot(inPoint)) / mCellAxis.dot(mDirection) -
                         mFront - mFlatLayer - front;
    const double room = enter - mSpacing;
    if (zone <= room)
        return {depth, zone, front};
    if (!(room > 0.0))
        return {0.0, 0.0, front};
    const double free = (1.0 - mKappa) * room;
    const double packed = (1.0 - 0.5 * mKappa) * room;
    if (depth <= free)
        return {depth, room, front};
    if (!(packed > free)) // kappa 0: the zone compacts to nothing and no further
        return {free, room, front};
    // Stacked up: C1 + (C2 - C1)(1 - exp(-(C - C1) / (C2 - C1))), slope 1 at C1 and C2 never reached.
    return {free - (packed - free) * std::expm1(-(depth - free) / (packed - free)), room, front};
}

double CrushPlan::DisplacementAt(const Vec3& inPoint) const
{
    const auto [crush, length, front] = ColumnCrush(inPoint);
    if (!(crush > 0.0))
        return 0.0;
    const double delta = front > 0.0 ? mDirection.dot(inPoint) - mFront - mFlatLayer - front
                                     : mDirection.dot(inPoint) - mFront - mFlatLayer;
    if (delta >= length)
        return 0.0;
    const double along = delta <= 0.0 ? 1.0 : 1.0 - delta / length;
    const double side = mSide.dot(inPoint), third = mThird.dot(inPoint);
    // The field is full one flat-layer width past the footprint: the spline blends over two spacings, and
    // the footprint's own edge (a box face's corner contacts) must reach the impactor too.
    const double outside = std::max({mSideMin - side, side - mSideMax, mThirdMin - third, third - mThirdMax, mFlatLayer}) - mFlatLayer;
    if (outside >= mRamp)
        return 0.0;
    const double across = mRamp > 0.0 ? 1.0 - outside / mRamp : 1.0;
    return crush * along * across;
}

double CrushWidth(const Collision& inCollision, ECollisionSide inSide, const Vec3& inUp, double inMinWidth)
{
    const std::optional<ffd::SurfaceProbe> footprint = FootprintOf(inCollision, inSide, inUp, inMinWidth);
    return footprint ? footprint->mSideMax - footprint->mSideMin : inMinWidth;
}

double CampbellCrushDepth(const DamageMaterial& inMaterial, double inWidth, double inEnergy)
{
    if (!ValidateDamageMaterial(inMaterial) || !(std::isfinite(inWidth) && inWidth > 0.0))
        return 0.0;
    const double excess = inEnergy / inWidth - inMaterial.mCrushG;
    if (!(excess > 0.0))
        return 0.0;
    // The positive root of B C^2 / 2 + A C - excess = 0, in the form that does not cancel when B excess << A^2.
    const double a = inMaterial.mCrushA, b = inMaterial.mCrushB;
    const double root = std::sqrt(a * a + 2.0 * b * excess);
    if (!std::isfinite(root))
        return std::numeric_limits<double>::infinity(); // beyond any bound: the caller clamps
    return 2.0 * excess / (a + root);
}

double CampbellCrushEnergy(const DamageMaterial& inMaterial, double inWidth, double inDepth)
{
    if (!(inDepth > 0.0) || !ValidateDamageMaterial(inMaterial) || !(std::isfinite(inWidth) && inWidth > 0.0))
        return 0.0;
    return inWidth * (inMaterial.mCrushA * inDepth + 0.5 * inMaterial.mCrushB * inDepth * inDepth + inMaterial.mCrushG);
}

void ShareCrushEnergy(Collision& ioCollision, const CrushSide& inA, const CrushSide& inB)
{
    const double energy = ioCollision.AbsorbedEnergy();
    auto stiffness = [&](const CrushSide& inSide, ECollisionSide inWhich) {
        // intent: a side whose material is not valid (a direct caller's) crushes nothing, as a rigid one
        if (inSide.mMaterial == nullptr || !ValidateDamageMaterial(*inSide.mMaterial))
            return std::numeric_limits<double>::infinity();
        const double b = inSide.mLength != nullptr
                             ? CrushMaterialAlong(*inSide.mMaterial, CrushDirection(ioCollision, inWhich),
                                                  *inSide.mLength, inSide.mUp, inSide.mForward)
                                   .mCrushB
                             : inSide.mMaterial->mCrushB;
        return b * CrushWidth(ioCollision, inWhich, inSide.mUp, inSide.mMaterial->mMinCrushWidth);
    };
    const double k_a = stiffness(inA, ECollisionSide::A), k_b = stiffness(inB, ECollisionSide::B);
    ioCollision.mCrushEnergyA = 0.0;
    ioCollision.mCrushEnergyB = 0.0;
    if (std::isinf(k_a) && std::isinf(k_b))
        return;
    if (std::isinf(k_b))
        ioCollision.mCrushEnergyA = energy;
    else if (std::isinf(k_a))
        ioCollision.mCrushEnergyB = energy;
    else
    {
        // A's share 1 / (1 + k_a / k_b): no sum of stiffnesses to overflow.
        ioCollision.mCrushEnergyA = energy / (1.0 + k_a / k_b);
        ioCollision.mCrushEnergyB = std::max(energy - ioCollision.mCrushEnergyA, 0.0);
    }
}

DamageMaterial CrushMaterialAlong(const DamageMaterial& inMaterial, const Vec3& inDirection,
                                  const BodyLength& inLength, const Vec3& inUp, const Vec3& inForward)
{
    if (!inMaterial.mHasSideStiffness && !inMaterial.mHasRearStiffness)
        return inMaterial;
    const Vec3 width = inUp.cross(inLength.mAxis);
    const bool across = std::abs(inDirection.dot(width)) > std::abs(inDirection.dot(inLength.mAxis));
    DamageMaterial zone = inMaterial;
    if (inMaterial.mHasSideStiffness && across)
    {
        zone.mCrushA = inMaterial.mSideCrushA;
        zone.mCrushB = inMaterial.mSideCrushB;
        zone.mCrushG = inMaterial.mSideCrushG;
    }
    // intent: a crush into the body along +forward moves the rear forward: a hit from behind
    else if (inMaterial.mHasRearStiffness && !across && inDirection.dot(inForward) > 0.0)
    {
        zone.mCrushA = inMaterial.mRearCrushA;
        zone.mCrushB = inMaterial.mRearCrushB;
        zone.mCrushG = inMaterial.mRearCrushG;
    }
    return zone;
}

std::optional<CrushPlan> PlanCampbellCrush(const Collision& inCollision, ECollisionSide inSide,
                                           double inEnergy, const DamageMaterial& inBodyMaterial,
                                           const Vec3& inUp, const ffd::FfdDeformer& inDeformer,
                                           const CrushBody* inBody)
{
    if (!(inEnergy > 0.0) || !ValidateDamageMaterial(inBodyMaterial))
        return std::nullopt;
    // The contacts' own span, then the footprint: that span widened to the material's minimum width.
    const std::optional<ffd::SurfaceProbe> span = FootprintOf(inCollision, inSide, inUp, 0.0);
    if (!span)
        return std::nullopt;
    std::optional<ffd::SurfaceProbe> footprint = span;
    Widen(footprint->mSideMin, footprint->mSideMax, inBodyMaterial.mMinCrushWidth);
    Widen(footprint->mThirdMin, footprint->mThirdMax, inBodyMaterial.mMinCrushWidth);
    CrushPlan plan;
    plan.mDirection = footprint->mDirection;
    plan.mSide = footprint->mSide;
    plan.mThird = footprint->mThird;
    plan.mSideMin = footprint->mSideMin;
    plan.mSideMax = footprint->mSideMax;
    plan.mThirdMin = footprint->mThirdMin;
    plan.mThirdMax = footprint->mThirdMax;
    plan.mWidth = plan.mSideMax - plan.mSideMin;
    // The layer the spline blends over along the crush.
    const double spacing = CoarsestSpacingAlong(inDeformer, plan.mDirection);

    // The impactor meets the body's foremost surface point in the footprint (a low-poly roof may have no
    // vertex there, only a triangle across it); the crush already there is the deepest earlier inward move
    // of the vertices in the footprint, or of the triangles across it when none is.
    const ffd::SurfaceProbeResult surface = inDeformer.ProbeSurface(*footprint);
    if (!std::isfinite(surface.mFront))
        return std::nullopt;
    std::optional<CrushBody> measured;
    if (inBody == nullptr)
        measured = MeasureCrushBody(inDeformer, inUp);
    const CrushBody& body = inBody != nullptr ? *inBody : *measured;
    // The stiffness this crush meets: the sides' when it runs across the body, the rear's when it pushes the
    // body forward (a hit from behind), when the material has them (CrushMaterialAlong).
    const DamageMaterial material =
        CrushMaterialAlong(inBodyMaterial, plan.mDirection, body.mLength, inUp, body.mForward);
    const double front = surface.mFront;
    // A move shallower than the material's smallest dent (the fade of a neighbouring crush) is no crush: it
    // must not waive the no-damage energy G of an undamaged front.
    double previous = surface.mMoved;
    if (!(previous >= std::max(material.mMinDeformation, 1.0e-9)))
        previous = 0.0;
    plan.mFront = front;
    plan.mPreviousCrush = previous;

    // Campbell's energy balance from the crush already there: the structure has absorbed what that crush
    // took, and this collision's energy takes it further.
    const double absorbed = CampbellCrushEnergy(material, plan.mWidth, previous);
    double depth = CampbellCrushDepth(material, plan.mWidth, absorbed + inEnergy) - previous;
    // The struck surface's shape across the footprint (a rounded nose, a front at an angle to the crush),
    // measured within a slab twice the flat front's depth (and the field's widest reach for it), then the
    // depth its profile needs for the energy; a deeper answer measures again in a deeper slab. A column met
    // only behind the slab holds the slab's depth, which the answer does not reach, so the slab changes
    // nothing but the cost (racing dents are centimetres deep; the surface scan is most of a plan's time).
    plan.mKappa = material.mCrushedLengthFraction;
    plan.mSpacing = spacing;
    plan.mFlatLayer = spacing;
    const double wall_slope = 2.0 * std::sqrt(std::max(material.mCrushedLengthFraction, 0.01));
    const ShapeBox& impactor = inSide == ECollisionSide::A ? inCollision.mShapeOfBOnA : inCollision.mShapeOfAOnB;
    const CrossRect contacts{plan.mSideMin, plan.mSideMax, plan.mThirdMin, plan.mThirdMax};
    const std::optional<CrossRect> face = impactor.mKnown ? ImpactorFace(plan, impactor, body) : std::nullopt;
    const CrossRect touched{span->mSideMin, span->mSideMax, span->mThirdMin, span->mThirdMax}; // not widened
    for (double slab = std::min(material.mMaxInstantDeformation, 2.0 * depth + 2.0 * spacing); depth > 0.0;)
    {
        plan.mRamp = std::max(2.0 * spacing, slab / wall_slope);
        plan.mDepth = slab;
        // Half the pocket walls' slope limit: the columns' shear adds to the walls' where both are.
        SurfaceBins surface_bins;
        plan.mStruckFront = MeasureStruckFront(plan, face ? Union(*face, contacts) : contacts, inDeformer, body.mLargeTriangles,
                                               0.5 * wall_slope, face ? &surface_bins : nullptr);
        const double profiled =
            face ? ConformToImpactor(plan, touched, *face, surface_bins, material, previous, inEnergy)
                 : (plan.mStruckFront.mDepth.empty()
                        ? depth
                        : ProfileCrushDepth(plan, material, previous, inEnergy, depth));
        if (profiled <= slab || slab >= material.mMaxInstantDeformation)
        {
            depth = profiled;
            break;
        }
        slab = std::min(material.mMaxInstantDeformation, 2.0 * profiled);
    }
    if (depth > material.mMaxInstantDeformation)
    {
        depth = material.mMaxInstantDeformation;
        plan.mClamped = true;
    }
    if (!(depth >= material.mMinDeformation) || !(depth > 0.0))
        return std::nullopt;
    plan.mDepth = depth;
    // The lattice cannot compact a layer thinner than a control spacing: a shallow crush fades over one.
    plan.mZoneLength = std::max(depth / (1.0 - material.mCrushedLengthFraction), spacing);
    // The cubic B-spline blends the field over two spacings on either side of a point: with the compaction
    // starting right at the surface, the struck face would fall short of the impactor by about a fifth of
    // a spacing times the compaction slope (2.8 cm at 56 km/h on a 0.15 m lattice). The outermost spacing is
    // therefore pressed flat against the impactor and the compaction starts behind it.
    plan.mFlatLayer = spacing;
    // The pocket's walls: where the compaction (to f of a length) meets the fade's shear k = C / ramp, a surface
    // whose normal makes the angle t with the crush keeps facing out (its normal within 90 degrees of where it
    // was) iff cos^2 t / f - k sin t cos t / f + sin^2 t > 0 for every t, that is iff k < 2 sqrt(f). The walls
    // therefore slope at most 2 sqrt(f) : 1 (1:1 at the default quarter; the 2:1 walls before turned the box
    // car's pocket walls over at 64 km/h), and the fade spans at least two control spacings.
    plan.mRamp =
        std::max(2.0 * spacing, depth / (2.0 * std::sqrt(std::max(material.mCrushedLengthFraction, 0.01))));
    LimitByCell(material, body.mLength, inDeformer, plan);
    return plan;
}

ffd::DentReport ApplyCrushPlan(const CrushPlan& inPlan, double inMaxStep, ffd::FfdDeformer& ioDeformer)
{
    ffd::DentReport total;
    // intent: a plan that is not finite crushes nothing (PlanCampbellCrush makes finite ones; a hand-made one
    // could otherwise empty rows FieldRangeOnRow cannot bound)
    const bool finite = IsFinite(inPlan.mDirection) && IsFinite(inPlan.mSide) && IsFinite(inPlan.mThird) &&
                        std::isfinite(inPlan.mSideMin) && std::isfinite(inPlan.mSideMax) && std::isfinite(inPlan.mThirdMin) &&
                        std::isfinite(inPlan.mThirdMax) && std::isfinite(inPlan.mFront) && std::isfinite(inPlan.mDepth) &&
                        std::isfinite(inPlan.mFlatLayer) && std::isfinite(inPlan.mZoneLength) && std::isfinite(inPlan.mRamp);
    if (!finite)
        return total;
    for (std::size_t z = 0; z < ioDeformer.GetZones().size(); ++z)
    {
        const ffd::FfdLattice& zone = ioDeformer.GetZones()[z];
        const std::array<int, 3>& count = zone.GetSettings().mControlCount;
        const std::vector<Vec3>& displacements = zone.GetControlDisplacements();
        // intent: how far any control has moved, to bound where the field can reach a control
        double moved2 = 0.0;
        for (const Vec3& displacement : displacements)
            moved2 = std::max(moved2, displacement.squaredNorm());
        const double moved = std::sqrt(moved2);
        std::vector<int> controls;
        std::vector<double> magnitudes;
        for (int c = 0; c < count[2]; ++c)
            for (int b = 0; b < count[1]; ++b)
            {
                const std::array<int, 2> range = FieldRangeOnRow(inPlan, zone, b, c, moved);
                for (int a = range[0]; a <= range[1]; ++a)
                {
                    const int index = zone.ControlIndex(a, b, c);
                    const Vec3 position = zone.RestControlPosition(a, b, c) + displacements[static_cast<std::size_t>(index)];
                    const double magnitude = inPlan.DisplacementAt(position);
                    if (magnitude > 0.0)
                    {
                        controls.push_back(index);
                        magnitudes.push_back(magnitude);
                    }
                }
            }
        if (controls.empty())
            continue;
        // ControlIndex runs a fastest, so the indices are already ascending.
        Eigen::MatrixX3d delta(static_cast<Eigen::Index>(controls.size()), 3);
        for (std::size_t k = 0; k < controls.size(); ++k)
            delta.row(static_cast<Eigen::Index>(k)) = (magnitudes[k] * inPlan.mDirection).transpose();
        Result<ffd::DentReport> report = ioDeformer.ApplyControlDelta(static_cast<int>(z), controls, delta, inMaxStep);
        if (!report)
            continue; // finite plan, valid indices: cannot happen
        const ffd::DentReport& r = report.Get();
        total.mControlsChanged += r.mControlsChanged;
        total.mControlsPushed += r.mControlsPushed;
        total.mScale = std::min(total.mScale, r.mScale);
        total.mVerticesMoved += r.mVerticesMoved;
        total.mTrianglesUpdated += r.mTrianglesUpdated;
        total.mNormalsUpdated += r.mNormalsUpdated;
    }
    total.mMaxWanted = inPlan.mDepth;
    return total;
}

} // namespace crumple::plugin
