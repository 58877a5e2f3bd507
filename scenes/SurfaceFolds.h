// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/ffd/FfdDeformer.h>
#include <crumple/ffd/TriangleMesh.h>

#include <span>

namespace crumple::common
{

/// Below this fraction of their summed areas a vertex's triangles' normals cancel: the rule the deformer's
/// own normals follow (ffd::cSheetCancellation), read here so that the two agree.
inline constexpr double cSheetCancellation = ffd::cSheetCancellation;

/// Vertices whose normal now points against their rest normal (area-weighted over the vertex's triangles,
/// at rest and at inPositions; dot < 0): the surface has folded over there. A sliver triangle that a smooth
/// dent tips over (a thin triangle of a real mesh can) does not count; a sound dent, however deep, turns no
/// vertex over. Vertices whose rest normal is round-off (cSheetCancellation: both sides of a double-sided
/// sheet on the same vertices) have no direction to turn against and are not counted (FoldedTriangles sees
/// their triangles). Positions of another length than the rest mesh's count nothing.
int FoldedVertices(const ffd::TriangleMesh& inRest, std::span<const Vec3> inPositions);

/// Triangles whose face normal the dents turned over (its dot product with the rest face normal < 0): a
/// fold of the surface itself. Triangles of zero rest area are skipped. Unlike FoldedVertices it does not
/// count a vertex on a sharp ridge whose averaged normal tips over when the crush compacts the ridge.
int FoldedTriangles(const ffd::TriangleMesh& inRest, std::span<const Vec3> inPositions);

} // namespace crumple::common
