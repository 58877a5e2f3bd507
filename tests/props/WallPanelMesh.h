// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/fem/TetGrid.h>

#include <array>

namespace crumple::test
{

/// The 2 m x 0.2 m x 2 m panel the props tests strike: the WorldFixture's wall in its body frame, x in
/// [0, 0.2], y and z in [-1, 1], inCells cubes along x, y, z.
inline fem::TetMesh WallPanelMesh(const std::array<int, 3>& inCells)
{
    fem::TetGridSettings grid;
    grid.mOrigin = Vec3(0.0, -1.0, -1.0);
    grid.mSize = Vec3(0.2, 2.0, 2.0);
    grid.mCellCount = inCells;
    return fem::TetGrid(grid).Get();
}

} // namespace crumple::test
