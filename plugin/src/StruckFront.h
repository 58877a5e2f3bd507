// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/ffd/FfdDeformer.h>
#include <crumple/plugin/CampbellCrush.h>

#include <cstdint>
#include <span>
#include <vector>

namespace crumple::plugin
{

/// A rectangle across a plan's direction d: [mSideMin, mSideMax] along mSide, [mThirdMin, mThirdMax] along
/// mThird (m).
struct CrossRect
{
    double mSideMin = 0.0, mSideMax = 0.0;
    double mThirdMin = 0.0, mThirdMax = 0.0;
};

/// The struck surface's depth behind the front in each bin of a StruckFront's grid before any fill or slope
/// limit: +inf where no vertex or large triangle stands in the bin's column (beside the body), the slab's
/// depth where the body is met only behind it.
struct SurfaceBins
{
    double mSideOrigin = 0.0, mThirdOrigin = 0.0, mBin = 0.0;
    int mSideCount = 0, mThirdCount = 0;
    std::vector<double> mDepth; ///< Side fastest (m)
};

/// The struck surface's depth behind inPlan's front (StruckFront) over the field's widest reach across d
/// around inRegion (widened by the flat layer, the ramp and a spacing), in bins of the plan's spacing; depths
/// are capped at inPlan.mDepth, the slab the caller measures in. Each vertex marks its bin as met by the
/// body and lowers it to its own depth; each of inLargeTriangles (those that can hold a bin centre none of
/// their vertices stands for) within the slab sets the depth at the bin centres it covers. A bin the body
/// meets only deeper than the slab holds the slab's depth; a bin it never meets (beside or above the body)
/// takes its nearest met neighbours' depth, so the front is extended, not sloped, past the body's outline.
/// Two chamfer sweeps then make the grid inSlope-Lipschitz. An all-zero grid (a flat front square to d)
/// comes back empty.
/// outSurface, when given, receives the bins as measured (SurfaceBins), also for a flat front.
StruckFront MeasureStruckFront(const CrushPlan& inPlan, const CrossRect& inRegion, const ffd::FfdDeformer& inDeformer,
                               std::span<const std::uint32_t> inLargeTriangles, double inSlope,
                               SurfaceBins* outSurface = nullptr);

/// The crush depth C at which inPlan's struck profile absorbs inEnergy: Campbell's law integrated across the
/// footprint's width, as CRASH3 integrates a measured profile (E = integral of A c + B c^2 / 2, and G per
/// unit width once, on an undamaged front), each of 32 stations across the width crushing by C less its
/// surface's depth (the least over the footprint's height, at its bin spacing), on top of the crush
/// inPrevious already there. A flat front gives inFlatDepth, the closed form's; any other a deeper C, found by
/// bisection between that and inFlatDepth plus the deepest station's depth (which bracket inEnergy).
double ProfileCrushDepth(const CrushPlan& inPlan, const DamageMaterial& inMaterial, double inPrevious, double inEnergy,
                         double inFlatDepth);

} // namespace crumple::plugin
