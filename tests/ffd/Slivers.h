// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/ffd/TriangleMesh.h>

#include <cstdint>

namespace crumple::test
{

/// Appends inCount slivers (triangles 1 mm by 1 cm) along x from inStart over inLength (m): vertices and
/// triangles enough that a probe of a small mesh stays on its cell-by-cell path instead of scanning
/// everything (FfdDeformer::ProbeSurface's budget).
inline void AddSlivers(ffd::TriangleMesh& ioMesh, const Vec3& inStart, double inLength, int inCount)
{
    for (int i = 0; i < inCount; ++i)
    {
        const double x = inStart.x() + inLength * i / inCount;
        const auto p = static_cast<std::uint32_t>(ioMesh.mPositions.size());
        ioMesh.mPositions.emplace_back(x, inStart.y(), inStart.z());
        ioMesh.mPositions.emplace_back(x + 0.001, inStart.y() + 0.01, inStart.z());
        ioMesh.mPositions.emplace_back(x, inStart.y(), inStart.z() + 0.01);
        ioMesh.mTriangles.push_back({p, p + 1, p + 2});
    }
}

} // namespace crumple::test
