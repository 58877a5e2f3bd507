// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>
#include <crumple/base/Result.h>

#include <crumple/ffd/TriangleMesh.h>

#include <cstddef>

namespace crumple::ffd
{

/// A triangle is a sliver when it has no area to speak of: twice its area at most cSliverAreaRatio times the
/// square of its longest edge (its height under half of that ratio of its longest edge: a corner within about
/// 0.006 degrees of 180, or two corners at one position).
inline constexpr double cSliverAreaRatio = 1.0e-4;

/// Removes the slivers that bound nothing: those whose every edge (vertices at the same position taken as
/// one, across seams) either no other triangle uses or at least two others do. Such a triangle lies over an
/// edge of the surface that two other triangles already close, or hangs off it: an exporter's zero-area
/// triangle over an edge (a point on the edge and its two ends) that a re-cut would split as a cap, carrying
/// the split into the surface beside it. A sliver inside the surface (an edge of it shared with exactly one
/// other triangle) stays, as the surface would open without it. Vertices stay (a sliver's own corner is left
/// unused); the other triangles keep their order.
/// @param[in,out] ioMesh the mesh; ValidateTriangleMesh must accept it (else it is left as it was)
/// @return how many triangles were removed, or an error for bad input (the mesh unchanged)
CRUMPLE_API Result<std::size_t> DropLooseSlivers(TriangleMesh& ioMesh);

} // namespace crumple::ffd
