// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/fem/TetMesh.h>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace crumple::common
{

/// A tetrahedral prop's surface as it is drawn and written: the boundary faces of its elements.
struct TetSurface
{
    std::vector<std::array<std::uint32_t, 3>> mTriangles; ///< Boundary faces, indices into the prop's nodes
    std::vector<Vec3> mNormals;                           ///< Per node: area-weighted mean of its faces' normals
                                                          ///< (+z for a node on no face)
};

/// The surface of inElements at inPositions (fem::TetBoundary: it follows fracture, so a crack's faces are
/// surface on both sides). Elements flagged in inLeftOut (one byte each, or empty) are left out: pieces
/// that left the prop as bodies of their own. crumple-replay and the racing samples write their props'
/// OBJ files with it, so a live prop and its replay can be compared byte for byte.
/// @param[in] inPositions  #N node positions (m)
/// @param[in] inElements   #T elements' node indices, each < #N
/// @param[in] inLeftOut    #T flags, or empty
TetSurface MakeTetSurface(std::span<const Vec3> inPositions, std::span<const fem::TetIndices> inElements,
                          std::span<const std::uint8_t> inLeftOut = {});

} // namespace crumple::common
