// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <cstdint>

namespace crumple::ffd
{

/// What one FfdDeformer::ApplyDent did; counts are for instrumentation, tests and benchmarks.
struct CRUMPLE_API DentReport
{
    int mPointsApplied = 0;        ///< Constrained points that reached a zone (after merging)
    int mPointsMerged = 0;         ///< Points merged into a neighbour closer than the merge distance, or on
                                   ///< the coarser grid of a zone with more than 1,024 points
    int mPointsIgnored = 0;        ///< Points outside every zone (beyond the capture distance)
    int mControlsChanged = 0;      ///< Controls whose displacement changed
    int mControlsPushed = 0;       ///< Of those, controls the fold guard moved because a neighbour was pushed
                                   ///< into them (0 unless a dent is deep for the lattice spacing)
    int mControlsClipped = 0;      ///< Controls whose change against the push direction was removed
                                   ///< (FfdDeformerSettings::mOneSidedDents, OneSidedControls)
    double mScale = 1.0;           ///< Smallest factor a zone's dent was scaled by to respect the step bound and
                                   ///< the maximum total deformation (1 when nothing was limited)
    int mRankDeficiency = 0;       ///< Sum over zones of (#points - rank of B used): > 0 for coincident/collinear
                                   ///< sets and for targets the gain bound made the solve drop directions of
    double mSolveTolerance = 0.0;  ///< Largest relative pivot tolerance a zone's solve ended at (the settings'
                                   ///< mRankTolerance unless the gain bound raised it)
    std::uint32_t mVerticesMoved = 0;    ///< Vertices whose position was recomputed
    std::uint32_t mTrianglesUpdated = 0; ///< Triangles whose face normal was recomputed
    std::uint32_t mNormalsUpdated = 0;   ///< Vertices whose normal was recomputed
    double mMaxPointError = 0.0;   ///< Max over applied points of |achieved - wanted displacement| (m)
    double mMaxWanted = 0.0;       ///< Max wanted displacement magnitude (m), to make mMaxPointError relative
    int mContactsClamped = 0;      ///< Contacts whose depth the material's maximum instantaneous deformation cut
                                   ///< (set by plugin::DeformableObject::ApplyCollision; 0 from ApplyDent)
    int mStackedUp = 0;            ///< Crushes that stacked up against the occupant cell, crushing less than
                                   ///< Campbell's law asks (plugin::CrushPlan::mStackedUp; set as mContactsClamped)

    /// True when a bound limited this dent: a contact's depth clamped or the dent scaled down.
    bool IsLimited() const { return mContactsClamped > 0 || mScale < 1.0; }
};

} // namespace crumple::ffd
