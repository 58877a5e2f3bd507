// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/fem/TriangleIndices.h>
#include <crumple/base/Math.h>
#include <crumple/base/Result.h>

#include <array>
#include <vector>

namespace crumple::fem
{

/// A triangle surface in double precision: the input of Tetrahedralize and what LoadSurfaceMesh returns.
struct CRUMPLE_API SurfaceMesh
{
    std::vector<Vec3> mPositions;            ///< #V vertex positions (m), body frame
    std::vector<TriangleIndices> mTriangles; ///< #F triangles, indices into mPositions
};

/// Checks that a surface can bound a solid: at least one triangle, finite positions, indices in range, no
/// triangle repeating a vertex, and closed: every edge (an unordered vertex pair) used by exactly two
/// triangles. Orientation is not checked (a tetrahedralizer does not need it). Refusals:
/// EError::InvalidArgument (no triangles, too many vertices), EError::NonFinite, EError::OutOfRange,
/// EError::DegenerateGeometry (repeated vertex, open or non-manifold edges: the message gives their count and
/// one edge's end positions).
/// @param[in] inSurface  #V positions and #F triangles
CRUMPLE_API Status ValidateClosedSurface(const SurfaceMesh& inSurface);

} // namespace crumple::fem
