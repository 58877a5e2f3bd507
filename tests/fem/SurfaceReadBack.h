// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Result.h>
#include <crumple/fem/SurfaceMesh.h>

#include <filesystem>

namespace crumple::fem::test
{

/// Parses an OBJ written by SaveSurfaceObj ("v x y z" and "f a b c" lines, 1-based), independently of the
/// library: the test's own reader, strict about anything else.
Result<SurfaceMesh> ReadBackObj(const std::filesystem::path& inPath);

/// Parses a PLY written by SaveSurfacePly: checks the exact header (binary_little_endian 1.0, double x y z,
/// list uchar int vertex_indices), then reads the little-endian payload and requires it to end exactly.
Result<SurfaceMesh> ReadBackPly(const std::filesystem::path& inPath);

} // namespace crumple::fem::test
