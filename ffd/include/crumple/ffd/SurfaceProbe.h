// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Math.h>

#include <limits>

namespace crumple::ffd
{

/// A probe of the deformed surface along a direction: the prism of body points p whose coordinates
/// mSide.p and mThird.p lie in [mSideMin, mSideMax] and [mThirdMin, mThirdMax] (an impactor's face swept
/// along mDirection). Body frame, m. The three axes are unit and mutually perpendicular.
struct CRUMPLE_API SurfaceProbe
{
    Vec3 mDirection = Vec3::UnitX(); ///< d: unit direction the probe looks along (into the body)
    Vec3 mSide = Vec3::UnitY();      ///< First unit axis across d
    Vec3 mThird = Vec3::UnitZ();     ///< Second unit axis across d
    double mSideMin = 0.0, mSideMax = 0.0;   ///< The prism along mSide (m)
    double mThirdMin = 0.0, mThirdMax = 0.0; ///< The prism along mThird (m)
};

/// What a probe found on the deformed surface (FfdDeformer::ProbeSurface).
struct CRUMPLE_API SurfaceProbeResult
{
    /// Smallest d.p over the surface inside the prism (m): over its vertices inside, and over the part inside
    /// of each triangle that crosses the prism's boundary; +infinity when the surface misses the prism.
    double mFront = std::numeric_limits<double>::infinity();
    bool mVertexInside = false; ///< Some vertex lies inside the prism
    /// How far the surface under the probe has moved along d so far (m), >= 0: the largest d.(p - rest) of a
    /// vertex inside, or, when no vertex is inside, of a corner of a triangle crossing the prism.
    double mMoved = 0.0;
};

} // namespace crumple::ffd
