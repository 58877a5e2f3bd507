// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/fem/TetGrid.h>
#include <crumple/fem/TetSolver.h>

#include <catch2/catch.hpp>

#include <array>

namespace crumple::test
{

/// Anchors every node of the layer inI along x (0: the x = 0 face) of a TetGrid of inCellCount cells: a bar
/// clamped at one end.
inline void AnchorGridLayer(fem::TetSolver& ioSolver, const std::array<int, 3>& inCellCount, int inI)
{
    for (int j = 0; j <= inCellCount[1]; ++j)
        for (int k = 0; k <= inCellCount[2]; ++k)
            REQUIRE(ioSolver.SetNodeFixed(fem::TetGridNode(inCellCount, inI, j, k), true).IsValid());
}

} // namespace crumple::test
