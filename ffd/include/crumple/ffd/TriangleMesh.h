// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Math.h>
#include <crumple/base/Result.h>

#include <array>
#include <cstdint>
#include <vector>

namespace crumple::ffd
{

/// An indexed triangle mesh (a render mesh), counter-clockwise triangles seen from outside.
struct CRUMPLE_API TriangleMesh
{
    std::vector<Vec3> mPositions;                        ///< #V positions, body frame (m)
    std::vector<std::array<std::uint32_t, 3>> mTriangles; ///< #F vertex index triples
};

/// Farthest a mesh vertex may be from its body's origin (m): far beyond any vehicle or prop, and far enough
/// inside the double range that edge cross products (normals, areas) and dents cannot overflow.
constexpr double cMaxMeshCoordinate = 1.0e6;

/// Checks a mesh at the API boundary: at least one triangle, at most 2^32 - 2 vertices and (2^32 - 1) / 3
/// triangles (a deformer indexes corners in 32 bits), finite positions within cMaxMeshCoordinate of the
/// origin, indices in range.
CRUMPLE_API Status ValidateTriangleMesh(const TriangleMesh& inMesh);

} // namespace crumple::ffd
