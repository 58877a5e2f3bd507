// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Result.h>
#include <crumple/fem/TetMesh.h>
#include <crumple/fem_import/TetgenSettings.h>

#include <filesystem>

namespace crumple::fem
{

/// Reads a closed surface mesh file and fills it with tetrahedra: LoadSurfaceMesh, then Tetrahedralize. An
/// open or corrupt file is refused before tetgen runs. Positions in metres as stored in the file.
/// @param[in] inPath      OBJ, PLY, STL, glTF, ... file of a closed surface
/// @param[in] inSettings  how tetgen runs
CRUMPLE_API Result<TetMesh> ImportTetMesh(const std::filesystem::path& inPath, const TetgenSettings& inSettings = {});

} // namespace crumple::fem
