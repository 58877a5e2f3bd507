// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Result.h>
#include <crumple/fem/SurfaceMesh.h>

#include <filesystem>

namespace crumple::fem
{

/// Reads a closed triangle surface with assimp (crumple::fem_import links it): OBJ, PLY, STL, glTF / GLB, OFF
/// and the other formats assimp knows. Polygons are triangulated; points and lines are ignored. All meshes of
/// the scene are merged, each placed by its node transforms (applied in double precision). Vertices with
/// exactly the same position are joined across meshes (so faces with separate normals or UVs share their
/// corners), in order of first appearance; a triangle that then repeats a vertex (zero area) is dropped.
///
/// Units: positions are taken as metres, as stored, without any unit conversion (glTF is metres by its
/// specification; OBJ, PLY and STL carry no unit). Assimp stores positions as 32-bit floats, so a file's
/// doubles arrive rounded to float precision (about 6e-8 relative).
///
/// Refused: a missing file (EError::IoError), a file assimp cannot parse (EError::CorruptData with assimp's
/// message), no triangle, a non-finite coordinate, or a surface that ValidateClosedSurface refuses, such as
/// an open one (the message counts the edges not used by exactly two triangles and gives one by its end
/// positions). Every message starts with the path.
///
/// The file is parsed in a child process (RunIsolated): assimp crashes, aborts or loops on some malformed
/// files (scripts/fuzz.sh finds such files within seconds), and a file from a mod or a user must not take
/// the game down. Such a file is refused with EError::CorruptData ("the parser crashed on it", "took longer
/// than"). Measured: the isolation adds the cost of a fork and of sending the mesh back through a pipe
/// (docs/fuzzing.md).
/// @param[in] inPath    the file
/// @param[in] inTimeout seconds the parse may take before it is stopped, in (0, 1e6] (crumple::cMaxIsolatedTimeout)
/// @return #V joined vertex positions (m) and #F triangles (winding as in the file)
CRUMPLE_API Result<SurfaceMesh> LoadSurfaceMesh(const std::filesystem::path& inPath, double inTimeout = 30.0);

} // namespace crumple::fem
