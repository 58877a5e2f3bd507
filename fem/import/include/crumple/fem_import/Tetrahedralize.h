// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Result.h>
#include <crumple/fem/SurfaceMesh.h>
#include <crumple/fem/TetMesh.h>
#include <crumple/fem_import/TetgenSettings.h>

namespace crumple::fem
{

/// Fills a closed surface with tetrahedra by running TetGen as a separate process (see TetgenSettings for
/// why), as "tetgen -pzQ[Y] [-q<ratio>] [-a<volume>]": the surface is a piecewise linear complex (-p),
/// numbered from 0 (-z), quietly (-Q). The mesh fills exactly the enclosed polyhedron (total volume =
/// SurfaceVolume). With mKeepSurface (-Y) its boundary is the surface's own triangles (tetgen may
/// re-triangulate coplanar neighbours, as on the faces of a cube); without, tetgen may add nodes inside the
/// surface facets.
///
/// The surface is written (OFF, 17 significant digits) into a fresh folder under mTemporaryDirectory, tetgen
/// runs there with no shell (posix_spawn, an argument array), its .1.node and .1.ele files are read back, and
/// the folder is removed whatever happens. Nodes 0 .. #V - 1 are the surface vertices, in order and bit for
/// bit (restored from the input after checking tetgen's printed values); the points tetgen adds (inside,
/// and on the surface facets without mKeepSurface) follow. TetGen 1.5 writes its elements positively oriented
/// (TetVolume > 0, the TetMesh convention); any element that is not gets two indices swapped. Every element
/// is its own group.
///
/// Refused, before tetgen runs: a surface ValidateClosedSurface refuses, settings out of range
/// (EError::InvalidArgument), tetgen not found (EError::IoError: "tetgen not found (looked for 'tetgen' on
/// PATH): install Debian's tetgen package (apt-get install tetgen) or set TetgenSettings::mExecutable").
/// After it runs: a failure (EError::DegenerateGeometry with tetgen's exit status and the end of its output;
/// TetGen 1.5 aborts without printing a reason when its output is not a terminal, so Tetrahedralize then
/// runs "tetgen -pzd" once more, and if the surface intersects itself the message says so and names two
/// crossing triangles), unreadable output (EError::CorruptData), a surface vertex tetgen dropped (a
/// near-duplicate within its tolerance), or an element TetMesh::Create refuses (a sliver: use a stricter,
/// lower mMaxRadiusEdgeRatio). Deterministic: the same surface and settings give the same mesh.
/// @param[in] inSurface   closed surface, #V positions (m) and #F triangles (orientation not needed)
/// @param[in] inSettings  program, quality and size bounds
/// @return the tetrahedral mesh, #N >= #V nodes
CRUMPLE_API Result<TetMesh> Tetrahedralize(const SurfaceMesh& inSurface, const TetgenSettings& inSettings = {});

} // namespace crumple::fem
