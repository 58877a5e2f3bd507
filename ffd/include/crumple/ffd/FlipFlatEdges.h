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

/// The same Delaunay flips where the surface is flat only to within inMaxDeviation: an edge ab between the
/// triangles (a, b, c) and (b, a, d) is flipped to cd when the two angles facing it add up to more than pi,
/// ab and cd cross when seen along ab x cd, the tetrahedron (a, b, c, d) is at most inMaxDeviation thick
/// between the two (so no point of the surface moves farther), and both new triangles face the way the old
/// pair faces together, and no edge joins the positions of c and d yet (also through a seam's split
/// vertices). Each edge is examined once, then the four outer edges of every flip; on a mesh that is not
/// folded a second call finds nothing more (measured), on a folded one it may find a few. Vertices, their
/// order and their count stay.
///
/// Why: a mesh's bevels and T-junctions leave caps, triangles with a corner near 180 degrees a fraction of a
/// millimetre high (the Toy Car's front lip: caps 0.56 mm high and 10 cm long). Their unit normals are round-off
/// and differ from their neighbours', so FlipFlatEdges leaves them, and a dent's field bends more across their
/// length than they are high: they turn over although the field folds nothing. Flipping the cap's long edge
/// to its neighbour's far corner removes it and moves the surface by less than the cap's height.
///
/// Exporters split vertices along texture seams and hard edges, so an edge there has one triangle per side
/// by index. With inAcrossSeams such an edge is one edge when its ends' positions are equal (==, so 0.0 and -0.0
/// are one), and a
/// flip across it makes each new triangle from both sides' vertices: right for a mesh whose vertices carry
/// only a position (crumple-crash's), wrong for a textured one (a flipped triangle would stretch its texture
/// coordinates across the seam).
///
/// @param[in,out] ioMesh          the mesh; ValidateTriangleMesh must accept it (else it is left as it was)
/// @param[in]     inMaxDeviation  how far a flip may move the surface (m, or the mesh's unit), finite and >= 0;
///                                each flip is bounded, not their sum over flips that share a triangle
/// @param[in]     inAcrossSeams   flip across seams too (see above)
/// @param[in]     inCapAngle      0: every nearly flat edge may flip (the flat parts become Delaunay); > 0 (rad,
///                                at most pi): only edges that face a corner of at least this angle flip, a
///                                cap's long edge as Botsch and Kobbelt remove caps ("A Robust Procedure to
///                                Eliminate Degenerate Faces from Triangle Meshes", VMV 2001), so the rest of
///                                the mesh keeps its triangles (crumple-crash passes 150 degrees)
/// @return the number of flips made, or an error for bad input (the mesh unchanged)
CRUMPLE_API Result<std::size_t> FlipNearlyFlatEdges(TriangleMesh& ioMesh, double inMaxDeviation, bool inAcrossSeams = false,
                                                    double inCapAngle = 0.0);

} // namespace crumple::ffd
