// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/ffd/TriangleMesh.h>

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
/// vertices, with the smaller of those cells beside it, and is reported under the first touched one only, so
/// it is reported once without a mark.
class CellSurfaceIndex
{
public:
    /// @param[in] inMesh        the rest mesh
    /// @param[in] inVertexCell  #V: each vertex's cell (numbered across zones), -1 for a vertex of no zone
    /// @param[in] inCellCount   cells of all zones
    static CellSurfaceIndex Build(const TriangleMesh& inMesh, std::span<const int> inVertexCell, int inCellCount);

    /// Appends the triangles with a vertex in one of inCells, each once.
    /// @param[in] inCells      touched cells, ascending
    /// @param[in] inCellMarks  per cell: nonzero exactly for inCells
    void AppendTriangles(std::span<const int> inCells, std::span<const std::uint8_t> inCellMarks,
                         std::vector<std::uint32_t>& ioTriangles) const;

    /// Appends the vertices outside inCells that share a triangle with a vertex in one of them, each once.
    /// @param[in] inVertexCell  as given to Build
    /// @param[in,out] ioVertexMarks  #V, all zero on entry and on return
    void AppendRing(std::span<const int> inCells, std::span<const std::uint8_t> inCellMarks,
                    std::span<const int> inVertexCell, std::vector<std::uint8_t>& ioVertexMarks,
                    std::vector<std::uint32_t>& ioVertices) const;

private:
    // One triangle listed under a cell: the cells of its other vertices that come before this one (-1: none).
    struct Entry
    {
        std::uint32_t mTriangle;
        int mEarlierCell[2];
    };

    std::vector<std::uint32_t> mEntryStart; ///< #cells + 1: CSR offsets into mEntries
    std::vector<Entry> mEntries;
    std::vector<std::uint32_t> mRingStart;  ///< #cells + 1: CSR offsets into mRing
    std::vector<std::uint32_t> mRing;       ///< Per cell: vertices outside it sharing a triangle with one inside, ascending
};

} // namespace crumple::ffd
