// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/ffd/TriangleMesh.h>

#include <cstddef>

namespace crumple::ffd
{

/// Makes the triangles of each flat region of a mesh Delaunay: an edge between two triangles that lie in
/// one plane (same vertex indices on both sides, unit normals within inFlatCosine of each other) is flipped
/// when the two angles facing it add up to more than pi, until none does. The surface does not change, only
/// how its flat parts are cut into triangles; vertices, their order and their count stay.
///
/// Why: exporters cut a flat face with a curved edge (a bumper's underside) into a fan of slivers, triangles
/// a metre long and a fraction of a millimetre high. A dent is a smooth field sampled at the vertices, and
/// its curvature across a sliver's length moves the far vertex more than the sliver is high: the triangle
/// turns over although the field folds nothing. Delaunay triangles of the same face follow the field.
///
/// @param[in,out] ioMesh     the mesh; ValidateTriangleMesh must accept it (else it is left as it was)
/// @param[in]     inFlatCosine two triangles are coplanar when their unit normals' dot product is at least
///                           this, in (0, 1]; the default is an angle of about 0.08 degrees
/// @return the number of flips made, or an error for bad input (the mesh unchanged)
CRUMPLE_API Result<std::size_t> FlipFlatEdges(TriangleMesh& ioMesh, double inFlatCosine = 1.0 - 1.0e-6);

} // namespace crumple::ffd
