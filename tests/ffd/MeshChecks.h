// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// What the mesh-preparation tests measure on a triangle mesh: areas, closedness, triangles turned over.
#pragma once

#include <crumple/ffd/TriangleMesh.h>

#include <array>
#include <cstdint>

namespace crumple::ffd::test
{

/// Half the cross product of two edges: the triangle's area along its normal.
Vec3 AreaVector(const TriangleMesh& inMesh, const std::array<std::uint32_t, 3>& inTriangle);

/// Sum of the triangles' areas.
double TotalArea(const TriangleMesh& inMesh);

/// Every directed edge once, and its reverse once: a closed, consistently oriented, manifold surface.
bool IsClosedManifold(const TriangleMesh& inMesh);

/// Triangles of inRest whose area vector points against the same triangle's in inNow (same triangles).
int TurnedOver(const TriangleMesh& inRest, const TriangleMesh& inNow);

/// The smallest and largest corner angle of a mesh's triangles (rad).
struct AngleRange
{
    double mSmallest = 0.0;
    double mLargest = 0.0;
};
AngleRange CornerAngleRange(const TriangleMesh& inMesh);

/// A pole's pocket pushed along -x: 0.27 m at y = 0, fading over 0.3 m (smooth, and folding nothing: x' = x -
/// w(y) keeps every horizontal surface's orientation).
TriangleMesh Pocket(const TriangleMesh& inMesh);

} // namespace crumple::ffd::test
