// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Math.h>
#include <crumple/base/Result.h>
#include <crumple/fem/TriangleIndices.h>

#include <span>
#include <vector>

namespace crumple::fem
{

/// Flat (per-triangle) unit normals n = (b - a) x (c - a) / |(b - a) x (c - a)|, pointing to the side the
/// triangle (a, b, c) is counter-clockwise from. Broken sections have sharp edges, so they are drawn with
/// these rather than with smoothed vertex normals. A zero-area triangle gets the zero vector. Refused
/// (outNormals left empty) when an index is out of range.
/// @param[in]  inPositions  #V vertex positions (m)
/// @param[in]  inTriangles  #F triangles
/// @param[out] outNormals   #F unit normals (dimensionless), same frame as the positions
CRUMPLE_API Status TriangleNormals(std::span<const Vec3> inPositions, std::span<const TriangleIndices> inTriangles,
                       std::vector<Vec3>& outNormals);

} // namespace crumple::fem
