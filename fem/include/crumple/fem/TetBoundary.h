// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/fem/SurfaceMesh.h>
#include <crumple/fem/TetMesh.h>

#include <span>
#include <vector>

namespace crumple::fem
{

/// The boundary of a tetrahedral mesh: the element faces that belong to exactly one element (a face is the
/// unordered triple of its node indices). It takes the element -> node indices rather than a TetMesh so that
/// it follows fracture: once a piece's nodes are duplicated and its elements' corners remapped, the faces
/// along the crack no longer match and become boundary faces.
///
/// Order: by element, then by the corner the face is opposite to (0, 1, 2, 3); each triangle is
/// outward-oriented for a positively oriented element (TetVolume > 0): for corners (0, 1, 2, 3) the faces are
/// (1, 2, 3), (0, 3, 2), (0, 1, 3), (0, 2, 1). Deterministic: it depends only on inTets. A face shared by
/// three or more elements (an invalid mesh) is not boundary. Indices are not checked against a node count.
/// @param[in] inTets  #T elements, 4 node indices each
/// @return #B boundary triangles of node indices, #B <= 4 #T
CRUMPLE_API std::vector<TriangleIndices> TetBoundary(std::span<const TetIndices> inTets);

} // namespace crumple::fem
