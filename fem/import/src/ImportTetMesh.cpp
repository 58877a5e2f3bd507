// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem_import/ImportTetMesh.h>
#include <crumple/fem_import/LoadSurfaceMesh.h>
#include <crumple/fem_import/Tetrahedralize.h>

namespace crumple::fem
{

Result<TetMesh> ImportTetMesh(const std::filesystem::path& inPath, const TetgenSettings& inSettings)
{
    Result<SurfaceMesh> surface = LoadSurfaceMesh(inPath);
    if (surface.HasError())
        return surface.GetError();
    Result<TetMesh> mesh = Tetrahedralize(surface.Get(), inSettings);
    if (mesh.HasError())
        return MakeError(mesh.GetError().mCode, inPath.string() + ": " + mesh.GetError().mMessage);
    return mesh;
}

} // namespace crumple::fem
