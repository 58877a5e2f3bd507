// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/ffd/TriangleMesh.h>

#include <algorithm>
#include <string>

namespace crumple::ffd
{

Status ValidateTriangleMesh(const TriangleMesh& inMesh)
{
    if (inMesh.mPositions.empty() || inMesh.mTriangles.empty())
        return MakeError(EError::DegenerateGeometry, "TriangleMesh is empty: it needs vertices and triangles");
    if (inMesh.mPositions.size() > 0xFFFFFFFEu)
        return MakeError(EError::InvalidArgument, "TriangleMesh has more than 2^32 - 2 vertices");
    if (inMesh.mTriangles.size() > 0xFFFFFFFFu / 3)
        return MakeError(EError::InvalidArgument, "TriangleMesh has more than (2^32 - 1) / 3 triangles");
    for (std::size_t v = 0; v < inMesh.mPositions.size(); ++v)
    {
        if (!IsFinite(inMesh.mPositions[v]))
            return MakeError(EError::NonFinite, "TriangleMesh.mPositions[" + std::to_string(v) + "] is not finite");
        // Cross products of edges (normals, areas) must not overflow: coordinates past 1e150 m made NaN normals.
        if (!(inMesh.mPositions[v].cwiseAbs().maxCoeff() <= cMaxMeshCoordinate))
            return MakeError(EError::OutOfRange, "TriangleMesh.mPositions[" + std::to_string(v) +
                                                     "] is farther than 1e6 m from the body's origin");
    }
    const std::size_t vertex_count = inMesh.mPositions.size();
    for (std::size_t f = 0; f < inMesh.mTriangles.size(); ++f)
        for (std::uint32_t index : inMesh.mTriangles[f])
            if (index >= vertex_count)
                return MakeError(EError::OutOfRange, "TriangleMesh.mTriangles[" + std::to_string(f) +
                                                         "] uses vertex " + std::to_string(index) + " of " +
                                                         std::to_string(vertex_count));
    // intent: a mesh with no surface (every vertex on one point or one line) has nothing to dent and no
    // normal to give; its lattice would span nothing. One triangle of non-zero area is enough.
    const bool has_area = std::any_of(inMesh.mTriangles.begin(), inMesh.mTriangles.end(),
                                      [&](const auto& inTriangle)
                                      {
                                          const Vec3& a = inMesh.mPositions[inTriangle[0]];
                                          return (inMesh.mPositions[inTriangle[1]] - a)
                                                     .cross(inMesh.mPositions[inTriangle[2]] - a)
                                                     .squaredNorm() > 0.0;
                                      });
    if (!has_area)
        return MakeError(
            EError::DegenerateGeometry,
            "TriangleMesh has no surface: every triangle has zero area (its vertices lie on one point "
            "or one line)");
    return Status::Ok();
}

} // namespace crumple::ffd
