// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Math.h>
#include <crumple/base/Result.h>
#include <crumple/fem/ProceduralEdgeSettings.h>

#include <array>

namespace crumple::fem
{

/// Cell counts along x, y, z for a TetGrid whose cells are evenly spaced display sections of about the
/// average section size (Morris & Anderson, section IV.C: the averages are divided into the object's
/// dimensions, then the sections are evenly spaced): max(1, round(width / mAverageSectionWidth)) cells along
/// the width axis, max(1, round(height / mAverageSectionHeight)) along the height axis and inThicknessCells
/// across the thickness (axes as WallAxes()). The actual section size is then the extent divided by the
/// count: in [1/2, 3/2) times the average once the extent is at least half the average.
/// Refused: invalid settings (ValidateProceduralEdgeSettings), a non-finite or non-positive size, a thickness
/// count < 1, or more than TetGridSettings::cMaxCells cells.
/// @param[in] inSize            extent of the box along x, y, z (m)
/// @param[in] inSettings        the edge parameters
/// @param[in] inThicknessCells  cells across the thickness, >= 1
CRUMPLE_API Result<std::array<int, 3>> CellCountForSections(const Vec3& inSize, const ProceduralEdgeSettings& inSettings,
                                                int inThicknessCells = 1);

} // namespace crumple::fem
