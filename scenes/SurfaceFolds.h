// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/ffd/TriangleMesh.h>

#include <span>

namespace crumple::common
{

/// Vertices whose normal now points against their rest normal (dot < 0): the surface has folded over
/// there. Vertex normals are area-weighted over the vertex's triangles, so a sliver triangle that a smooth
/// dent tips over (a thin triangle of a real mesh can) does not count; a sound dent, however deep, turns no
/// vertex over.
/// @param[in] inRestNormals  #V unit vertex normals before
/// @param[in] inNormals      #V unit vertex normals after
int FoldedVertices(std::span<const Vec3> inRestNormals, std::span<const Vec3> inNormals);

/// Triangles whose face normal the dents turned over (its dot product with the rest face normal < 0): a
/// fold of the surface itself. Triangles of zero rest area are skipped. Unlike FoldedVertices it does not
/// count a vertex on a sharp ridge whose averaged normal tips over when the crush compacts the ridge.
int FoldedTriangles(const ffd::TriangleMesh& inRest, std::span<const Vec3> inPositions);

} // namespace crumple::common
