// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "CellSurfaceIndex.h"

#include <algorithm>
#include <array>
#include <limits>
#include <utility>

namespace crumple::ffd
{

CellSurfaceIndex CellSurfaceIndex::Build(const TriangleMesh& inMesh, std::span<const int> inVertexCell, int inCellCount)
{
    CellSurfaceIndex index;
    const auto cells = static_cast<std::size_t>(inCellCount);

    // intent: each triangle's distinct cells, ascending (at most three)
    auto distinct_cells = [&](const std::array<std::uint32_t, 3>& inTriangle, std::array<int, 3>& outCells) {
        int count = 0;
        for (std::uint32_t v : inTriangle)
        {
            const int cell = inVertexCell[v];
            bool known = false;
            for (int i = 0; i < count; ++i)
                known = known || outCells[static_cast<std::size_t>(i)] == cell;
            if (cell >= 0 && !known)
                outCells[static_cast<std::size_t>(count++)] = cell;
        }
        // intent: insertion sort of at most three cells
        for (int i = 1; i < count; ++i)
            for (int j = i; j > 0 && outCells[static_cast<std::size_t>(j)] < outCells[static_cast<std::size_t>(j - 1)]; --j)
                std::swap(outCells[static_cast<std::size_t>(j)], outCells[static_cast<std::size_t>(j - 1)]);
        return count;
    };

    // intent: each triangle's cells once (-1 past its count); the loose ones, in no zone, apart
    std::vector<std::array<int, 3>> triangle_cells(inMesh.mTriangles.size());
    index.mTriangleStart.assign(cells + 1, 0);
    for (std::uint32_t t = 0; t < inMesh.mTriangles.size(); ++t)
    {
        std::array<int, 3>& own = triangle_cells[t];
        own = {-1, -1, -1};
        const int count = distinct_cells(inMesh.mTriangles[t], own);
        if (count == 0)
            index.mLooseTriangles.push_back(t);
        for (int i = 0; i < count; ++i)
            ++index.mTriangleStart[static_cast<std::size_t>(own[static_cast<std::size_t>(i)]) + 1];
    }

    // intent: triangles per cell (counting sort keeps ascending triangle order inside a cell)
    for (std::size_t c = 0; c < cells; ++c)
        index.mTriangleStart[c + 1] += index.mTriangleStart[c];
    index.mTriangles.resize(index.mTriangleStart[cells]);
    std::vector<std::uint32_t> fill(index.mTriangleStart.begin(), index.mTriangleStart.end() - 1);
    for (std::uint32_t t = 0; t < inMesh.mTriangles.size(); ++t)
    {
        const std::array<int, 3>& own = triangle_cells[t];
        for (std::size_t i = 0; i < 3 && own[i] >= 0; ++i)
            index.mTriangles[fill[static_cast<std::size_t>(own[i])]++] = t;
    }

    // intent: ring vertices per cell: corners of the cell's triangles that lie in another cell (or in no
    // zone); counted, filled, then sorted and made unique inside each cell's run in place
    // (in triangle order: the mesh's arrays are read in memory order, only the small per-cell tallies jump)
    auto for_each_ring = [&](auto&& inVisit) {
        for (std::uint32_t t = 0; t < inMesh.mTriangles.size(); ++t)
            for (std::size_t i = 0; i < 3 && triangle_cells[t][i] >= 0; ++i)
                for (std::uint32_t v : inMesh.mTriangles[t])
                    if (inVertexCell[v] != triangle_cells[t][i])
                        inVisit(static_cast<std::size_t>(triangle_cells[t][i]), v);
    };
    std::vector<std::uint32_t> ring_start(cells + 1, 0);
    for_each_ring([&](std::size_t inCell, std::uint32_t) { ++ring_start[inCell + 1]; });
    for (std::size_t c = 0; c < cells; ++c)
        ring_start[c + 1] += ring_start[c];
    std::vector<std::uint32_t> ring(ring_start[cells]);
    std::vector<std::uint32_t> ring_fill(ring_start.begin(), ring_start.end() - 1);
    for_each_ring([&](std::size_t inCell, std::uint32_t inVertex) { ring[ring_fill[inCell]++] = inVertex; });
    index.mRingStart.assign(cells + 1, 0);
    index.mRing.reserve(ring.size());
    for (std::size_t c = 0; c < cells; ++c)
    {
        const auto begin = ring.begin() + ring_start[c], end = ring.begin() + ring_start[c + 1];
        std::sort(begin, end);
        index.mRing.insert(index.mRing.end(), begin, std::unique(begin, end));
        index.mRingStart[c + 1] = static_cast<std::uint32_t>(index.mRing.size());
    }

    // intent: the other cells each cell's triangles reach (its ring vertices' cells), ascending
    index.mLinkStart.assign(cells + 1, 0);
    std::vector<int> linked;
    for (std::size_t c = 0; c < cells; ++c)
    {
        linked.clear();
        for (std::uint32_t r = index.mRingStart[c]; r < index.mRingStart[c + 1]; ++r)
            if (const int cell = inVertexCell[index.mRing[r]]; cell >= 0)
                linked.push_back(cell);
        std::sort(linked.begin(), linked.end());
        index.mLinked.insert(index.mLinked.end(), linked.begin(), std::unique(linked.begin(), linked.end()));
        index.mLinkStart[c + 1] = static_cast<std::uint32_t>(index.mLinked.size());
    }

    // intent: reach boxes from each cell's vertices and its triangles' corners; loose vertices and triangles
    constexpr double cInf = std::numeric_limits<double>::infinity();
    index.mReachLow.assign(cells, Vec3::Constant(cInf));
    index.mReachHigh.assign(cells, Vec3::Constant(-cInf));
    index.mLooseCorner.assign(cells, 0);
    for (std::uint32_t v = 0; v < inVertexCell.size(); ++v)
    {
        const int cell = inVertexCell[v];
        if (cell < 0)
        {
            index.mLooseVertices.push_back(v);
            continue;
        }
        index.mReachLow[static_cast<std::size_t>(cell)] = index.mReachLow[static_cast<std::size_t>(cell)].cwiseMin(inMesh.mPositions[v]);
        index.mReachHigh[static_cast<std::size_t>(cell)] = index.mReachHigh[static_cast<std::size_t>(cell)].cwiseMax(inMesh.mPositions[v]);
    }
    for (std::uint32_t t = 0; t < inMesh.mTriangles.size(); ++t)
    {
        const std::array<std::uint32_t, 3>& triangle = inMesh.mTriangles[t];
        const Vec3 low = inMesh.mPositions[triangle[0]].cwiseMin(inMesh.mPositions[triangle[1]]).cwiseMin(inMesh.mPositions[triangle[2]]);
        const Vec3 high = inMesh.mPositions[triangle[0]].cwiseMax(inMesh.mPositions[triangle[1]]).cwiseMax(inMesh.mPositions[triangle[2]]);
        for (std::size_t i = 0; i < 3 && triangle_cells[t][i] >= 0; ++i)
        {
            const auto c = static_cast<std::size_t>(triangle_cells[t][i]);
            index.mReachLow[c] = index.mReachLow[c].cwiseMin(low);
            index.mReachHigh[c] = index.mReachHigh[c].cwiseMax(high);
            for (std::uint32_t v : triangle)
                if (inVertexCell[v] < 0)
                    index.mLooseCorner[c] = 1;
        }
    }
    return index;
}

void CellSurfaceIndex::InsertTriangles(std::span<const int> inCells, AscendingIndexSet& ioTriangles) const
{
    for (int cell : inCells)
    {
        const std::span<const std::uint32_t> triangles = TrianglesOf(cell);
        ioTriangles.InsertAscending(triangles.data(), triangles.data() + triangles.size());
    }
}

void CellSurfaceIndex::InsertRing(std::span<const int> inCells, AscendingIndexSet& ioVertices) const
{
    for (int cell : inCells)
        ioVertices.InsertAscending(mRing.data() + mRingStart[static_cast<std::size_t>(cell)],
                                   mRing.data() + mRingStart[static_cast<std::size_t>(cell) + 1]);
}

} // namespace crumple::ffd
