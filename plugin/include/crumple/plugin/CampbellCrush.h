// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/ffd/DentReport.h>
#include <crumple/ffd/FfdDeformer.h>
#include <crumple/plugin/Collision.h>
#include <crumple/plugin/DamageMaterial.h>

#include <array>
#include <optional>
#include <span>
#include <vector>

namespace crumple::plugin
{

/// How far behind a crush's front each column of it meets the body: the struck surface's depth along d,
/// sampled on a square grid across d (bin centres; bilinear between them, the edge bins' values beyond).
/// Values are in [0, S], S the depth of the slab it was measured in (at least the crush depth C): a column
/// that meets nothing within the slab holds S, and crushes nothing. The grid is made
/// Lipschitz (no value exceeds a neighbour's by more than mSlope times their distance), so the crush the
/// columns take, C minus their depth, changes across the footprint no faster than the pocket walls allow.
struct CRUMPLE_API StruckFront
{
    double mSideOrigin = 0.0;  ///< Centre of bin (0, 0) along the plan's mSide (m)
    double mThirdOrigin = 0.0; ///< Centre of bin (0, 0) along the plan's mThird (m)
    double mBin = 0.0;         ///< Bin size (m)
    double mSlope = 1.0;       ///< Largest change of depth per metre across d
    int mSideCount = 0, mThirdCount = 0;
    std::vector<double> mDepth; ///< mSideCount x mThirdCount, side fastest (m); empty: a flat front, depth 0

    /// The depth at inSide, inThird (m): 0 on an empty grid.
    double At(double inSide, double inThird) const;
};

/// Where and how deep a Campbell crush goes, in the struck body's frame.
///
/// The impactor's face is taken flat, normal to the crush direction d (the impulse-weighted inward normal of
/// the contacts), over the footprint: the rectangle the contacts span across d, widened on each side axis to
/// at least the material's minimum crush width. At first touch the face stands at the body's foremost
/// vertex in the footprint (s0 along d); it ends C further in. The crush field moves a point at depth
/// delta = d.x - s0 - f by C g(delta) h along d, f a flat layer of one lattice spacing pressed against the
/// impactor (the spline blends over two spacings, so the struck face would otherwise fall short): g is 1 in
/// front and falls linearly to 0 at the crush zone length L = C / (1 - kappa) (the crushed length is compacted to kappa of itself, kappa the material's
/// mCrushedLengthFraction), and h is 1 on the footprint and one flat layer around it, then fades to 0 over
/// max(2 lattice spacings, C / 2) (pocket walls no steeper than 2:1). So a flat
/// barrier leaves a flat front at its final position (to within kappa L), a pole a pocket as wide as the
/// footprint, and nothing moves outside the footprint's margin or behind the crush zone.
///
/// The impactor's own shape (Collision::mShapeOfBOnA / mShapeOfAOnB, from BodyState::mShapeMin, mShapeMax)
/// widens the footprint beyond the contacts: an engine reports where the bodies touch at first (a rounded
/// nose's tip, the edge of an offset wall), but the impactor's face meets more of the body as it advances. With
/// the shape known the footprint is the contacts' span and every bin of the struck surface (below) within the
/// impactor's box across d, and within the body's rest bounds, that lies less than C behind s0; C is the
/// crush that footprint's width takes the energy at (a fixed point, found by binary search over the bins'
/// depths, where alone the footprint changes). A wall wider than the car
/// therefore crushes the whole front it reaches, an offset wall only its own share, a pole its own width (or
/// the minimum width) however tall. The box is the shape's bounding box: a fence's rails count as a wall.
///
/// A curved or slanted front (a rounded nose, a car hit by a wall at an angle): each column meets the body
/// F behind s0 (mStruckFront), so it crushes by C - F only, over its own zone behind its own surface; the
/// struck surface then ends against the impactor's final face instead of being pushed back whole. The
/// grid's slope limit (half the pocket walls': sqrt(kappa)) keeps the columns' shear fold-free; a front
/// steeper than that conforms only as far as the limit lets it.
///
/// The occupant cell (DamageMaterial::mCrushZoneFraction): when the crush runs within 60 degrees of the
/// body's length, each column of the field (a line along d) stops one control spacing h short of where it
/// enters the cell, so the cell's vertices keep their place (the spline reaches two spacings, and the
/// field's last spacing moves by less than a fifth of (1 - kappa) h). A column with room Z behind the flat
/// layer crushes by C while C <= (1 - kappa) Z; past that its zone stacks up: the column crushes by
/// C1 + (C2 - C1)(1 - exp(-(C - C1) / (C2 - C1))), C1 = (1 - kappa) Z, C2 = (1 - kappa / 2) Z, compacted over
/// Z, so the crush still grows with the energy but never reaches the cell. The lattice's spacing along the
/// length must fit four times in the zone, or no cell is kept. The fold guard keeps controls
/// FfdDeformerSettings::mMinControlSpacing (0.2) of a spacing apart: a zone compacted closer (kappa / 2 below
/// it) has the guard push the rest on, into the cell: 1.9 mm at the default quarter on the tested bodies,
/// 3.3 % of the crush with kappa 0.1 at 40 degrees (CampbellCrushTest's stress case).
struct CRUMPLE_API CrushPlan
{
    Vec3 mDirection = Vec3::UnitX(); ///< d: unit crush direction, into the body
    Vec3 mSide = Vec3::UnitY();      ///< Unit axis across d measuring the width (perpendicular to up and d)
    Vec3 mThird = Vec3::UnitZ();     ///< d x side
    double mSideMin = 0.0, mSideMax = 0.0;   ///< Footprint along mSide (m)
    double mThirdMin = 0.0, mThirdMax = 0.0; ///< Footprint along mThird (m)
    double mFront = 0.0;          ///< s0: foremost vertex of the footprint along d (m)
    double mDepth = 0.0;          ///< C: crush depth this collision adds (m)
    double mFlatLayer = 0.0;      ///< Depth behind s0 pressed flat against the impactor (a control spacing, m)
    double mZoneLength = 0.0;     ///< L: depth behind the flat layer the crush compacts (m)
    double mRamp = 0.0;           ///< Width of the footprint's fade (m)
    double mWidth = 0.0;          ///< w: the crushed width the energy is spread over (m)
    double mPreviousCrush = 0.0;  ///< Crush already in the footprint before this collision (m)
    bool mClamped = false;        ///< The depth was cut to the material's maximum instantaneous deformation
    double mKappa = 0.25;         ///< kappa: the material's mCrushedLengthFraction
    double mSpacing = 0.0;        ///< h: the lattice's coarsest control spacing along d (m)
    bool mCellActive = false;     ///< The crush runs along the body's length and an occupant cell limits it
    Vec3 mCellAxis = Vec3::UnitX(); ///< a: the body's length axis, oriented along the crush (a . d > 0)
    double mCellFace = 0.0;       ///< Where the cell begins along mCellAxis (m)
    bool mStackedUp = false;      ///< Some column of the footprint crushes less than its share: its zone stacked up
    StruckFront mStruckFront;     ///< Where each column meets the body, behind mFront (empty: all at mFront)

    /// The column through inPoint: its crush (m), the length it compacts over behind its flat layer (m), and
    /// how far behind mFront its surface begins (m): mDepth, mZoneLength and 0 on a flat front unless the
    /// occupant cell limits the column.
    std::array<double, 3> ColumnCrush(const Vec3& inPoint) const;
    /// The field's displacement magnitude along mDirection at body point inPoint (m), >= 0.
    double DisplacementAt(const Vec3& inPoint) const;
};

/// The body's length: its longest horizontal extent at rest (across the up axis), where the crush zones at
/// either end and the occupant cell between them lie (DamageMaterial::mCrushZoneFraction).
struct CRUMPLE_API BodyLength
{
    Vec3 mAxis = Vec3::UnitX(); ///< Unit, perpendicular to up
    double mMin = 0.0;          ///< The rest vertices' extent along mAxis (m)
    double mMax = 0.0;
};

/// The longer of the two horizontal extents of inRestPositions (the body axis least aligned with inUp, made
/// perpendicular to it, and up x that axis); ties take the first. An empty span gives an empty extent.
CRUMPLE_API BodyLength MeasureBodyLength(std::span<const Vec3> inRestPositions, const Vec3& inUp);

/// Whether a body's lattice can keep its occupant cell apart from its crush zones (CrushPlan): a crush zone
/// (DamageMaterial::mCrushZoneFraction of the body's length) must hold four of the lattice's control spacings
/// along the length (the flat layer, the spacing kept clear of the cell and two to compact over). Where it
/// cannot, a Campbell crush along the length runs as if the body had no cell, and the spline carries it into
/// the cell and beyond: a 4.2 m box car with 8 controls along its length (0.84 m apart) crushed 0.45 m at the
/// front moves its roof 0.30 m and with 5 controls its rear 0.22 m (crumple-crash, 56 km/h full wall); at the
/// default 0.15 m spacing neither moves.
struct CRUMPLE_API OccupantCellFit
{
    bool mHasCell = false; ///< The material leaves a cell (Campbell's model, mCrushZoneFraction < 0.5) on a
                           ///< body with a length
    double mZoneLength = 0.0; ///< A crush zone's length along the body (m)
    double mSpacing = 0.0;    ///< The lattice's coarsest control spacing along the body's length (m)
    double mMaxSpacing = 0.0; ///< The coarsest spacing that keeps the cell: a quarter of mZoneLength (m)

    /// A cell the lattice is too coarse to keep: crushes along the length can move the whole body
    bool IsLost() const { return mHasCell && !(mSpacing <= mMaxSpacing); }
};

/// The coarsest control spacing along a body of length inLength (m) that keeps its occupant cell with
/// inMaterial (a quarter of a crush zone, OccupantCellFit::mMaxSpacing); infinity when the material leaves no
/// cell (the impulse factor, a crush zone of half the length or more) or the length is not > 0.
CRUMPLE_API double OccupantCellMaxSpacing(const DamageMaterial& inMaterial, double inLength);

/// The occupant cell's fit for a body of length inLength dented by inDeformer's lattice with inMaterial
/// (PlanCampbellCrush keeps a cell exactly when mHasCell and not IsLost(), for crushes within 60 degrees of
/// the length). DeformableObject::GetOccupantCellFit gives an object's.
CRUMPLE_API OccupantCellFit FitOccupantCell(const DamageMaterial& inMaterial, const BodyLength& inLength,
                                            const ffd::FfdDeformer& inDeformer);

/// What a crush plan needs to know of a body that its dents do not change, measured once per body
/// (DeformableObject keeps it): its length, and its triangles with an edge longer than half the lattice's
/// finest control spacing at rest, the only ones that can hold a struck-front bin centre that none of their
/// vertices stands for (StruckFront).
struct CRUMPLE_API CrushBody
{
    BodyLength mLength;
    std::vector<std::uint32_t> mLargeTriangles; ///< Ascending
    Vec3 mRestMin = Vec3::Zero(); ///< The rest mesh's bounding box in the body frame (m): how far across a
    Vec3 mRestMax = Vec3::Zero(); ///< crush an impactor's face can meet the body
    /// The body's forward direction (DeformableObjectSettings::mForwardAxis; MeasureCrushBody leaves +x):
    /// tells its rear from its front (CrushMaterialAlong)
    Vec3 mForward = Vec3::UnitX();
};

/// The material a crush along inDirection (body frame, unit, into the body) meets: inMaterial itself, or a
/// copy whose mCrushA, B and G are the sides' when it has them (DamageMaterial::mHasSideStiffness) and the
/// direction lies nearer the body's width (inUp x inLength.mAxis) than its length, or the rear's when it has
/// them (mHasRearStiffness), the direction lies along the length and pushes the body forward (inDirection .
/// inForward > 0: a hit from behind). PlanCampbellCrush and ShareCrushEnergy crush with it.
CRUMPLE_API DamageMaterial CrushMaterialAlong(const DamageMaterial& inMaterial, const Vec3& inDirection,
                                              const BodyLength& inLength, const Vec3& inUp,
                                              const Vec3& inForward = Vec3::UnitX());

/// Measures inDeformer's rest mesh for PlanCampbellCrush.
CRUMPLE_API CrushBody MeasureCrushBody(const ffd::FfdDeformer& inDeformer, const Vec3& inUp);

/// The width across inUp over which the collision's contacts of side inSide crush, at least inMinWidth (m).
CRUMPLE_API double CrushWidth(const Collision& inCollision, ECollisionSide inSide, const Vec3& inUp, double inMinWidth);

/// Depth C (m) at which a structure of width inWidth has absorbed inEnergy by Campbell's law
/// E / w = A C + B C^2 / 2 + G: 0 while E / w <= G, and 0 for a material ValidateDamageMaterial refuses or a
/// width that is not finite and > 0.
CRUMPLE_API double CampbellCrushDepth(const DamageMaterial& inMaterial, double inWidth, double inEnergy);
/// Energy (J) a structure of width inWidth absorbs to reach crush inDepth (0 at 0 crush): the inverse (0 for
/// a refused material or width, as CampbellCrushDepth).
CRUMPLE_API double CampbellCrushEnergy(const DamageMaterial& inMaterial, double inWidth, double inDepth);

/// One side of a collision, for the split of its energy: the material of its Campbell object (null: the side
/// does not crush by Campbell's law: a wall, a pole, or a body dented by the impulse factor) and its up axis.
struct CRUMPLE_API CrushSide
{
    const DamageMaterial* mMaterial = nullptr;
    Vec3 mUp = Vec3::UnitZ();
    /// The body's length (CrushBody::mLength), which tells a crush across the body from one along it
    /// (CrushMaterialAlong); null: the ends' stiffness whatever the direction
    const BodyLength* mLength = nullptr;
    Vec3 mForward = Vec3::UnitX(); ///< The body's forward direction, which tells its rear from its front
};

/// Sets the collision's mCrushEnergyA and mCrushEnergyB: its absorbed energy split between the sides in
/// inverse proportion to their crush stiffness B w (two structures in series carry the same force, and each
/// stores about F^2 / (2 k)). A side that does not crush (no material, or one ValidateDamageMaterial refuses)
/// takes none and the other all of it.
CRUMPLE_API void ShareCrushEnergy(Collision& ioCollision, const CrushSide& inA, const CrushSide& inB);

/// The crush a collision with inEnergy (J) for this side makes on a body whose deformer is inDeformer; empty
/// when there is nothing to crush (no closing contact, the energy below G, no vertex in the footprint,
/// or a depth under the material's minimum) or the material is one ValidateDamageMaterial refuses.
/// inBody: MeasureCrushBody of the deformer (DeformableObject keeps it); null measures it here, a pass over
/// the rest mesh.
CRUMPLE_API std::optional<CrushPlan> PlanCampbellCrush(const Collision& inCollision, ECollisionSide inSide, double inEnergy,
                                           const DamageMaterial& inMaterial, const Vec3& inUp,
                                           const ffd::FfdDeformer& inDeformer, const CrushBody* inBody = nullptr);

/// Applies a plan: each zone's controls take the field at their current positions (the B-spline
/// quasi-interpolant of the field, exact for its linear parts), through FfdDeformer::ApplyControlDelta with
/// the material's maximum instantaneous deformation as the step bound. The reports of the zones are merged.
CRUMPLE_API ffd::DentReport ApplyCrushPlan(const CrushPlan& inPlan, double inMaxStep, ffd::FfdDeformer& ioDeformer);

} // namespace crumple::plugin
