// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/fem/SurfaceMesh.h>

#include <span>

namespace crumple::fem
{

/// Signed volume enclosed by a closed triangle surface (divergence theorem): sum over triangles of
/// p0 . (p1 x p2) / 6. Positive for outward-oriented triangles, independent of the origin for a closed
/// surface. Indices are not checked: pass a surface that ValidateClosedSurface accepts.
/// @param[in] inPositions  #V vertex positions (m)
/// @param[in] inTriangles  #F triangles indexing inPositions
/// @return signed volume (m^3)
CRUMPLE_API double SurfaceVolume(std::span<const Vec3> inPositions, std::span<const TriangleIndices> inTriangles);

} // namespace crumple::fem
