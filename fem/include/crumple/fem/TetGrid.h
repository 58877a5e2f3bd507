// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/fem/TetMesh.h>

#include <cstdint>
#include <span>

namespace crumple::fem
{

/// How a TetGrid cuts each cube into tetrahedra.
enum class ECubeSplit : std::uint8_t
{
    /// Five tetrahedra (the paper's section IV.A): a central regular one on four alternate corners and four
    /// corner ones. The central one always takes the corners whose global index parity (i + j + k) is even,
    /// so the split mirrors from cube to cube and the face diagonals of neighbours match (conforming).
    Five,
    /// Six tetrahedra around the main diagonal (Kuhn / Freudenthal split), the same in every cube:
    /// conforming, all six congruent, but anisotropic (stiffer along the diagonal).
    Six,
};

/// Describes a box of mCellCount cubes (cuboids) cut into tetrahedra. A plate is a box with one cell across
/// its thickness, a beam one with few cells across its section: there is one builder for all three.
struct CRUMPLE_API TetGridSettings
{
    Vec3 mOrigin = Vec3::Zero();              ///< Minimum corner (m), body frame
    Vec3 mSize = Vec3::Ones();                ///< Extent along x, y, z (m), each > 0
    std::array<int, 3> mCellCount{{1, 1, 1}}; ///< Cells along x, y, z, each >= 1, at most cMaxCells in all
    ECubeSplit mSplit = ECubeSplit::Five;     ///< Tetrahedra per cell

    static constexpr int cMaxCells = 1 << 22; ///< Guards against a typo allocating gigabytes
};

/// Builds the tetrahedral mesh of a box. Node (i, j, k), 0 <= i <= n_x etc., has index i + (n_x + 1)(j + (n_y
/// + 1) k) and position mOrigin + (i, j, k) .* mSize ./ mCellCount; cell (i, j, k) is group i + n_x (j + n_y
/// k) and owns the consecutive elements 5 g .. 5 g + 4 (or 6 g .. 6 g + 5), all positively oriented. Refused:
/// non-finite origin or size, a size <= 0, a cell count < 1 or too many cells.
/// @param[in] inSettings  the box
/// @return (n_x+1)(n_y+1)(n_z+1) nodes and 5 or 6 n_x n_y n_z elements
CRUMPLE_API Result<TetMesh> TetGrid(const TetGridSettings& inSettings);

/// TetGrid() restricted to the cells whose flag in inKeepCells is nonzero (cell (i, j, k) at index
/// i + n_x (j + n_y k)); the nodes no kept cell uses are dropped and the others keep lattice order, so
/// TetGridNode() does not apply unless every cell is kept. Groups stay the cell indices. Cells that share
/// only an edge or a corner are joined there (conforming). Refused: the TetGrid() cases, a flag count that
/// is not the cell count, no cell kept. An empty span keeps every cell (TetGrid()).
CRUMPLE_API Result<TetMesh> TetGridCells(const TetGridSettings& inSettings, std::span<const std::uint8_t> inKeepCells);

/// Index of grid node (i, j, k) in a TetGrid with inCellCount cells: i + (n_x + 1)(j + (n_y + 1) k).
CRUMPLE_API int TetGridNode(const std::array<int, 3>& inCellCount, int inI, int inJ, int inK);

} // namespace crumple::fem
