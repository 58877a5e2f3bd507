// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Result.h>
#include <crumple/fem/ESurfaceFormat.h>
#include <crumple/fem/SurfaceMesh.h>

#include <filesystem>
#include <span>

namespace crumple::fem
{

/// Writes a triangle surface for offline rendering, in the format given (see ESurfaceFormat for the exact
/// layout), with every position in inPositions in order (the caller compacts; FrameSequenceWriter does).
/// Refused with nothing written: no vertex or no triangle (EError::InvalidArgument), a non-finite position
/// (EError::NonFinite), a triangle index outside [0, #V) (EError::OutOfRange). The bytes go to
/// "<inPath>.partial", which is then renamed to inPath, so a reader never sees a half-written file and a
/// failed write leaves an existing inPath as it was; an unwritable folder is EError::IoError with the
/// system's reason.
/// @param[in] inPath       destination file (its folder must exist); an existing file is replaced
/// @param[in] inPositions  #V vertex positions (m), any frame
/// @param[in] inTriangles  #F triangles indexing inPositions, written as given (orientation kept)
/// @param[in] inFormat     OBJ text or binary PLY
CRUMPLE_API Status SaveSurface(const std::filesystem::path& inPath, std::span<const Vec3> inPositions,
                   std::span<const TriangleIndices> inTriangles, ESurfaceFormat inFormat);

/// SaveSurface in ESurfaceFormat::Obj.
CRUMPLE_API Status SaveSurfaceObj(const std::filesystem::path& inPath, std::span<const Vec3> inPositions,
                      std::span<const TriangleIndices> inTriangles);

/// SaveSurface in ESurfaceFormat::Ply.
CRUMPLE_API Status SaveSurfacePly(const std::filesystem::path& inPath, std::span<const Vec3> inPositions,
                      std::span<const TriangleIndices> inTriangles);

} // namespace crumple::fem
