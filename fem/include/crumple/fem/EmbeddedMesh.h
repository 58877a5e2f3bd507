// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/fem/TriangleIndices.h>
#include <crumple/base/Math.h>
#include <crumple/base/Result.h>
#include <crumple/fem/TetMesh.h>

#include <array>
#include <span>
#include <vector>

namespace crumple::fem
{

/// Where one display vertex sits inside the simulation mesh: an element and the vertex's barycentric
/// coordinates in it, x = sum_i mWeights[i] x[corner i of mElement].
struct CRUMPLE_API EmbeddedVertex
{
    int mElement = 0;                                     ///< Element (tetrahedron) index, fixed for life
    std::array<double, 4> mWeights{{1.0, 0.0, 0.0, 0.0}}; ///< Barycentric weights, sum 1; negative outside
};

/// A display triangle mesh bound to a tetrahedral mesh by barycentric coordinates, so that it follows the
/// simulation (Morris & Anderson, "GPU destruction", section IV.C; Parker & O'Brien 2009 embed the same
/// way). Each vertex follows one element affinely: rigid motions and affine deformations of that element are
/// reproduced exactly, and a broken-off piece carries the vertices bound to its elements.
class CRUMPLE_API EmbeddedMesh
{
  public:
    /// Largest accepted extrapolation: a vertex whose best element still has a weight below
    /// -cMaxExtrapolation lies about a whole group size outside the group it must follow, almost certainly a
    /// wrong group id.
    static constexpr double cMaxExtrapolation = 1.0;

    /// Binds each display vertex to an element of the group it must follow: among the elements with
    /// TetMesh::GetGroups()[e] == inVertexGroups[v], the one whose barycentric coordinates of the vertex have
    /// the largest minimum (the element containing it when there is one, otherwise the least extrapolating
    /// one; ties go to the lowest element index). Refused with a message naming the vertex or triangle:
    /// mismatched counts, a non-finite position, a group no element belongs to, a vertex extrapolated beyond
    /// cMaxExtrapolation, a triangle index out of range or repeated.
    /// @param[in] inMesh           the simulation mesh in its rest state
    /// @param[in] inRestPositions  #V display vertex rest positions (m), body frame (the mesh's frame)
    /// @param[in] inVertexGroups   #V group id each vertex follows
    /// @param[in] inTriangles      #F display triangles, indices into the vertices
    static Result<EmbeddedMesh> Create(const TetMesh& inMesh, std::span<const Vec3> inRestPositions,
                                       std::span<const int> inVertexGroups,
                                       std::vector<TriangleIndices> inTriangles);

    /// Display vertex positions for the current element connectivity and node positions:
    /// x_v = sum_i w_i inNodePositions[inElementNodes[e_v][i]]. The connectivity is passed here, not taken
    /// from the mesh, because fracture duplicates nodes and remaps element corners when pieces break off
    /// (element indices never change). Refused (outPositions left empty) when inElementNodes does not have
    /// one entry per element of the bound mesh, or a used node index is out of range or its position is not
    /// finite.
    /// @param[in]  inElementNodes   #T current element -> node indices
    /// @param[in]  inNodePositions  #N current node positions (m)
    /// @param[out] outPositions     #V display vertex positions (m), same frame as the nodes
    Status Update(std::span<const TetIndices> inElementNodes, std::span<const Vec3> inNodePositions,
                  std::vector<Vec3>& outPositions) const;

    /// Number of display vertices #V
    int GetVertexCount() const { return static_cast<int>(mVertices.size()); }
    /// Number of elements #T of the mesh it was bound to
    int GetElementCount() const { return mElementCount; }
    /// Binding per display vertex, #V
    const std::vector<EmbeddedVertex>& GetVertices() const { return mVertices; }
    /// Display vertex rest positions (m), #V
    const std::vector<Vec3>& GetRestPositions() const { return mRestPositions; }
    /// Display triangles, #F
    const std::vector<TriangleIndices>& GetTriangles() const { return mTriangles; }
    /// Smallest barycentric weight over all vertices: 0 or more when every vertex lies inside its element,
    /// negative (>= -cMaxExtrapolation) when some are extrapolated
    double GetMinWeight() const;

  private:
    EmbeddedMesh() = default;

    std::vector<EmbeddedVertex> mVertices;
    std::vector<Vec3> mRestPositions;
    std::vector<TriangleIndices> mTriangles;
    int mElementCount = 0;
};

} // namespace crumple::fem
