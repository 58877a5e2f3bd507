// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/ffd/PointDisplacement.h>

#include <span>
#include <vector>

namespace crumple::ffd
{

/// Fills the gaps of a sparse contact set by linear interpolation (D4MD section 6.2): a wide impactor,
/// e.g. a box face whose four corners are the only contacts an engine reports, must make one coherent
/// dent rather than four spikes.
///
/// The points are projected on the plane normal to their mean displacement and triangulated there
/// (Delaunay, Bowyer-Watson). Inside each triangle, and along each edge longer than the spacing,
/// samples are placed on a grid of pitch inSpacing; each sample's position and displacement are the
/// barycentric (linear) interpolation of the triangle's corners. Collinear sets are interpolated along
/// their line. Sets no wider than inSpacing are returned unchanged. A sample closer than half the pitch to
/// a given point or to a sample kept before it is dropped (the grid's samples come before the edges'): the
/// lattice cannot tell such neighbours apart, and each costs the direct-manipulation solve a row.
/// @param[in] inPoints   #P constrained points, body frame (m)
/// @param[in] inSpacing  sample pitch (m), typically the lattice control spacing; > 0
/// @param[in] inMaxPoints cap on the output size; the pitch grows until the samples fit
/// @return the input points followed by the interpolated samples, in a deterministic order
CRUMPLE_API std::vector<PointDisplacement> InterpolateWideImpact(std::span<const PointDisplacement> inPoints, double inSpacing,
                                                     std::size_t inMaxPoints = 512);

} // namespace crumple::ffd
