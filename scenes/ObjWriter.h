// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Result.h>
#include <crumple/ffd/TriangleMesh.h>

#include <filesystem>
#include <span>

namespace crumple::common
{

/// Writes a Wavefront OBJ (positions, normals, triangles). Written to a temporary file and renamed, so a
/// failed write leaves no partial file.
Status WriteObj(const std::filesystem::path& inPath, std::span<const Vec3> inPositions, std::span<const Vec3> inNormals,
                std::span<const std::array<std::uint32_t, 3>> inTriangles);

} // namespace crumple::common
