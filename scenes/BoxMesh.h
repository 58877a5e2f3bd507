// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/ffd/TriangleMesh.h>

#include <array>

namespace crumple::common
{

/// A closed box mesh centred on the origin, each face subdivided into a grid (shared vertices along edges,
/// outward counter-clockwise triangles). 2 (nx ny + ny nz + nz nx) quads, twice as many triangles.
/// @param[in] inHalfExtents half size along x, y, z (m)
/// @param[in] inSegments    grid segments along x, y, z, >= 1
ffd::TriangleMesh MakeBoxMesh(const Vec3& inHalfExtents, const std::array<int, 3>& inSegments);

/// Segments per axis so that a box of these half extents has about inTriangles triangles with near-square quads.
std::array<int, 3> BoxSegmentsForTriangles(const Vec3& inHalfExtents, int inTriangles);

} // namespace crumple::common
