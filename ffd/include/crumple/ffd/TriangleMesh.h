// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Math.h>
#include <crumple/base/Result.h>

#include <array>
#include <cstdint>
#include <vector>

namespace crumple::ffd
{

/// An indexed triangle mesh (a render mesh), counter-clockwise triangles seen from outside.
struct TriangleMesh
{
    std::vector<Vec3> mPositions;                        ///< #V positions, body frame (m)
    std::vector<std::array<std::uint32_t, 3>> mTriangles; ///< #F vertex index triples
};

/// Checks a mesh at the API boundary: at least one triangle, finite positions, indices in range.
Status ValidateTriangleMesh(const TriangleMesh& inMesh);

} // namespace crumple::ffd
