// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/fem/TetGrid.h>
#include <crumple/fem/TetMesh.h>

namespace crumple::test
{

/// A 0.6 m x 0.4 m x 0.2 m block of 3 x 2 x 1 cells (30 tetrahedra, 24 nodes): small enough for the
/// white-box tests of the element passes and the factored system to check every element and node.
inline fem::TetMesh SmallTetBlock()
{
    fem::TetGridSettings grid;
    grid.mSize = Vec3(0.6, 0.4, 0.2);
    grid.mCellCount = {3, 2, 1};
    return fem::TetGrid(grid).Get();
}

} // namespace crumple::test
