// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/TetGrid.h>
#include <crumple/fem/TetVolume.h>

#include <sstream>
#include <utility>

namespace crumple::fem
{

namespace
{

// Local corner c = (bit 0: +x, bit 1: +y, bit 2: +z) of a cell.
constexpr int cX = 1;
constexpr int cY = 2;
constexpr int cZ = 4;

// Five-tet split with the central element on the even local corners (0, x+y, x+z, y+z); the corner elements
// sit on the odd corners, each with its three edge neighbours.
constexpr std::array<std::array<int, 4>, 5> cFiveEven{{{0, cX | cY, cX | cZ, cY | cZ},
                                                       {cX, 0, cX | cY, cX | cZ},
                                                       {cY, 0, cX | cY, cY | cZ},
                                                       {cZ, 0, cX | cZ, cY | cZ},
                                                       {cX | cY | cZ, cX | cY, cX | cZ, cY | cZ}}};
// The mirror split: central element on the odd corners.
constexpr std::array<std::array<int, 4>, 5> cFiveOdd{{{cX, cY, cZ, cX | cY | cZ},
                                                      {0, cX, cY, cZ},
                                                      {cX | cY, cX, cY, cX | cY | cZ},
                                                      {cX | cZ, cX, cZ, cX | cY | cZ},
                                                      {cY | cZ, cY, cZ, cX | cY | cZ}}};
// Six-tet (Kuhn) split: corner 0 -> e_a -> e_a + e_b -> all, one path per axis permutation.
constexpr std::array<std::array<int, 4>, 6> cSix{{{0, cX, cX | cY, cX | cY | cZ},
                                                  {0, cX, cX | cZ, cX | cY | cZ},
                                                  {0, cY, cX | cY, cX | cY | cZ},
                                                  {0, cY, cY | cZ, cX | cY | cZ},
                                                  {0, cZ, cX | cZ, cX | cY | cZ},
                                                  {0, cZ, cY | cZ, cX | cY | cZ}}};

} // namespace

int TetGridNode(const std::array<int, 3>& inCellCount, int inI, int inJ, int inK)
{
    return inI + (inCellCount[0] + 1) * (inJ + (inCellCount[1] + 1) * inK);
}

Result<TetMesh> TetGrid(const TetGridSettings& inSettings)
{
    return TetGridCells(inSettings, {});
}

Result<TetMesh> TetGridCells(const TetGridSettings& inSettings, std::span<const std::uint8_t> inKeepCells)
{
    // Refuse a box that is not finite, has no extent or too many cells.
    if (!IsFinite(inSettings.mOrigin) || !IsFinite(inSettings.mSize))
        return MakeError(EError::NonFinite, "TetGridSettings: mOrigin and mSize must be finite");
    long long cells = 1;
    for (int axis = 0; axis < 3; ++axis)
    {
        if (!(inSettings.mSize[axis] > 0.0))
        {
            std::ostringstream message;
            message << "TetGridSettings.mSize[" << axis << "] = " << inSettings.mSize[axis]
                    << " m must be > 0";
            return MakeError(EError::DegenerateGeometry, message.str());
        }
        if (inSettings.mCellCount[axis] < 1 || inSettings.mCellCount[axis] > TetGridSettings::cMaxCells)
            return MakeError(EError::InvalidArgument,
                             "TetGridSettings.mCellCount[" + std::to_string(axis) +
                                 "] = " + std::to_string(inSettings.mCellCount[axis]) + " must be >= 1");
        // intent: checked as it grows (each factor is at most 2^22, so no product overflows before the check)
        cells *= inSettings.mCellCount[axis];
        if (cells > TetGridSettings::cMaxCells)
            return MakeError(EError::InvalidArgument, "TetGridSettings.mCellCount: more than the 2^22 cells allowed");
    }
    if (inSettings.mSplit != ECubeSplit::Five && inSettings.mSplit != ECubeSplit::Six)
        return MakeError(EError::InvalidArgument, "TetGridSettings.mSplit is not an ECubeSplit");
    if (!inKeepCells.empty() && static_cast<long long>(inKeepCells.size()) != cells)
        return MakeError(EError::InvalidArgument, "TetGridCells: " + std::to_string(inKeepCells.size()) +
                                                      " cell flags for " + std::to_string(cells) + " cells");
    const auto kept = [&](long long inCell) { return inKeepCells.empty() || inKeepCells[inCell] != 0; };

    // Nodes on the lattice, x fastest.
    const std::array<int, 3>& n = inSettings.mCellCount;
    const Vec3 spacing = inSettings.mSize.cwiseQuotient(Vec3(n[0], n[1], n[2]));
    std::vector<Vec3> positions;
    positions.reserve(static_cast<std::size_t>(n[0] + 1) * (n[1] + 1) * (n[2] + 1));
    for (int k = 0; k <= n[2]; ++k)
        for (int j = 0; j <= n[1]; ++j)
            for (int i = 0; i <= n[0]; ++i)
                positions.push_back(inSettings.mOrigin + Vec3(i, j, k).cwiseProduct(spacing));

    // Elements cell by cell (x fastest), the split mirrored on odd cells for the five-tet pattern.
    const int per_cell = inSettings.mSplit == ECubeSplit::Five ? 5 : 6;
    std::vector<TetIndices> tets;
    std::vector<int> groups;
    tets.reserve(static_cast<std::size_t>(cells) * per_cell);
    groups.reserve(static_cast<std::size_t>(cells) * per_cell);
    for (int k = 0; k < n[2]; ++k)
        for (int j = 0; j < n[1]; ++j)
            for (int i = 0; i < n[0]; ++i)
            {
                const int group = i + n[0] * (j + n[1] * k);
                if (!kept(group))
                    continue;
                const bool odd = ((i + j + k) & 1) != 0;
                for (int t = 0; t < per_cell; ++t)
                {
                    const std::array<int, 4>& local = inSettings.mSplit == ECubeSplit::Six ? cSix[t]
                                                      : odd                                ? cFiveOdd[t]
                                                                                           : cFiveEven[t];
                    TetIndices nodes;
                    for (int corner = 0; corner < 4; ++corner)
                    {
                        const int c = local[corner];
                        nodes[corner] = TetGridNode(n, i + ((c & cX) != 0 ? 1 : 0),
                                                    j + ((c & cY) != 0 ? 1 : 0), k + ((c & cZ) != 0 ? 1 : 0));
                    }
                    // Positive orientation: swap the last two corners of a negatively oriented element.
                    if (TetVolume(positions[nodes[0]], positions[nodes[1]], positions[nodes[2]],
                                  positions[nodes[3]]) < 0.0)
                        std::swap(nodes[2], nodes[3]);
                    tets.push_back(nodes);
                    groups.push_back(group);
                }
            }

    if (tets.empty())
        return MakeError(EError::InvalidArgument, "TetGridCells: no cell is kept");

    // Without a mask every lattice node is used; with one, drop the unused nodes, keeping lattice order.
    if (!inKeepCells.empty())
    {
        std::vector<int> new_index(positions.size(), -1);
        for (const TetIndices& tet : tets)
            for (int node : tet)
                new_index[node] = 0;
        std::vector<Vec3> used;
        for (std::size_t node = 0; node < positions.size(); ++node)
            if (new_index[node] == 0)
            {
                new_index[node] = static_cast<int>(used.size());
                used.push_back(positions[node]);
            }
        for (TetIndices& tet : tets)
            for (int& node : tet)
                node = new_index[node];
        positions = std::move(used);
    }
    return TetMesh::Create(std::move(positions), std::move(tets), std::move(groups));
}

} // namespace crumple::fem
