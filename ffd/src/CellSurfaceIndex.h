// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Math.h>
#include <crumple/ffd/TriangleMesh.h>

#include "AscendingIndexSet.h"

#include <cstdint>
#include <span>
#include <vector>

namespace crumple::ffd
{

/// The surface around the cells of a deformer's zones, precomputed so that a dent finds the triangles and the
/// vertex normals it changes from the cells it touched, in sequential passes over per-cell lists instead of
/// a walk over every moved vertex's triangles with a mark per triangle.
///
/// Cells are numbered across all zones (a zone's cells follow the previous zone's). A dent moves exactly the
/// vertices in its touched cells. A triangle's face normal changes when one
/// of its vertices is in a touched cell; a vertex normal changes when it is in a touched cell or shares a
/// triangle with a vertex that is (its "ring"). Each triangle is listed under every distinct zone cell of its
/// vertices; a dent inserts the lists of its touched cells into a bit set (AscendingIndexSet), which keeps a
/// triangle or vertex listed under two touched cells once and hands them back in the mesh's order.
///
/// For region queries (FfdDeformer::ProbeSurface) each cell also keeps its reach box: the rest-frame box of
/// its vertices and of every vertex of its triangles, so a triangle larger than a cell is found from any
/// cell of its vertices. Vertices and triangles in no zone are kept apart (loose), for a query to scan always.
class CellSurfaceIndex
{
public:
    /// @param[in] inMesh        the rest mesh
    /// @param[in] inVertexCell  #V: each vertex's cell (numbered across zones), -1 for a vertex of no zone
    /// @param[in] inCellCount   cells of all zones
    static CellSurfaceIndex Build(const TriangleMesh& inMesh, std::span<const int> inVertexCell, int inCellCount);
    /// Inserts the triangles with a vertex in one of inCells.
    void InsertTriangles(std::span<const int> inCells, AscendingIndexSet& ioTriangles) const;
    /// Inserts the vertices outside a cell of inCells that share a triangle with a vertex in it (some may lie in
    /// another cell of inCells).
    void InsertRing(std::span<const int> inCells, AscendingIndexSet& ioVertices) const;
    /// The triangles with a vertex in inCell, ascending
    std::span<const std::uint32_t> TrianglesOf(int inCell) const
    {
        return std::span<const std::uint32_t>(mTriangles).subspan(mTriangleStart[static_cast<std::size_t>(inCell)],
                                                                  mTriangleStart[static_cast<std::size_t>(inCell) + 1] - mTriangleStart[static_cast<std::size_t>(inCell)]);
    }
    /// Rest-frame box of the cell's vertices and its triangles' vertices (body frame, m); empty (low > high)
    /// for a cell without vertices
    const Vec3& ReachLow(int inCell) const { return mReachLow[static_cast<std::size_t>(inCell)]; }
    const Vec3& ReachHigh(int inCell) const { return mReachHigh[static_cast<std::size_t>(inCell)]; }
    /// True when one of the cell's triangles has a corner in no zone (which never moves: a query bounding the
    /// cell's surface by how far the vertices of its cells moved must also allow no move)
    bool HasLooseCorner(int inCell) const { return mLooseCorner[static_cast<std::size_t>(inCell)] != 0; }
    /// The other cells that hold a vertex of one of inCell's triangles, ascending: how far inCell's surface
    /// moved is bounded by how far the vertices of these cells and of inCell moved (and, HasLooseCorner, by
    /// no move)
    std::span<const int> LinkedCells(int inCell) const
    {
        return std::span<const int>(mLinked).subspan(mLinkStart[static_cast<std::size_t>(inCell)],
                                                     mLinkStart[static_cast<std::size_t>(inCell) + 1] - mLinkStart[static_cast<std::size_t>(inCell)]);
    }
    /// Vertices in no zone, ascending
    const std::vector<std::uint32_t>& LooseVertices() const { return mLooseVertices; }
    /// Triangles with no vertex in a zone, ascending
    const std::vector<std::uint32_t>& LooseTriangles() const { return mLooseTriangles; }

private:
    std::vector<std::uint32_t> mTriangleStart; ///< #cells + 1: CSR offsets into mTriangles
    std::vector<std::uint32_t> mTriangles;     ///< Per cell: TrianglesOf
    std::vector<std::uint32_t> mRingStart;  ///< #cells + 1: CSR offsets into mRing
    std::vector<std::uint32_t> mRing;       ///< Per cell: vertices outside it sharing a triangle with one inside, ascending
    std::vector<Vec3> mReachLow, mReachHigh; ///< Per cell: reach box (body frame, m)
    std::vector<std::uint8_t> mLooseCorner;  ///< Per cell: HasLooseCorner
    std::vector<std::uint32_t> mLinkStart;  ///< #cells + 1: CSR offsets into mLinked
    std::vector<int> mLinked;               ///< Per cell: LinkedCells
    std::vector<std::uint32_t> mLooseVertices;
    std::vector<std::uint32_t> mLooseTriangles;
};

} // namespace crumple::ffd
