// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/ffd/TriangleMesh.h>

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
    return Status::Ok();
}

} // namespace crumple::ffd
