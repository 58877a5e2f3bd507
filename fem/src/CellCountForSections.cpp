// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/CellCountForSections.h>
#include <crumple/fem/TetGrid.h>
#include <crumple/fem/WallAxes.h>

#include <cmath>
#include <sstream>

namespace crumple::fem
{

Result<std::array<int, 3>> CellCountForSections(const Vec3& inSize, const ProceduralEdgeSettings& inSettings,
                                                int inThicknessCells)
{
    // Inputs.
    if (Status valid = ValidateProceduralEdgeSettings(inSettings); !valid)
        return valid.GetError();
    if (!IsFinite(inSize) || !(inSize.minCoeff() > 0.0))
    {
        std::ostringstream message;
        message << "CellCountForSections: size (" << inSize.x() << ", " << inSize.y() << ", " << inSize.z()
                << ") m must be finite and > 0";
        return MakeError(EError::InvalidArgument, message.str());
    }
    if (inThicknessCells < 1 || inThicknessCells > TetGridSettings::cMaxCells)
        return MakeError(EError::InvalidArgument, "CellCountForSections: inThicknessCells = " +
                                                      std::to_string(inThicknessCells) + " must be >= 1");

    // Round the number of average sections that fit, at least one.
    const std::array<int, 3> axes = WallAxes(inSize);
    const double along[2] = {inSize[axes[0]] / inSettings.mAverageSectionWidth,
                             inSize[axes[1]] / inSettings.mAverageSectionHeight};
    std::array<int, 3> count{{1, 1, 1}};
    double cells = inThicknessCells;
    for (int in_plane = 0; in_plane < 2; ++in_plane)
    {
        const double rounded = std::max(1.0, std::round(along[in_plane]));
        if (rounded > TetGridSettings::cMaxCells)
            return MakeError(EError::InvalidArgument, "CellCountForSections: " + std::to_string(rounded) +
                                                          " sections along one axis is more than 2^22");
        count[axes[in_plane]] = static_cast<int>(rounded);
        cells *= rounded;
    }
    count[axes[2]] = inThicknessCells;
    if (cells > TetGridSettings::cMaxCells)
        return MakeError(EError::InvalidArgument, "CellCountForSections: " + std::to_string(cells) +
                                                      " cells is more than the 2^22 allowed");
    return count;
}

} // namespace crumple::fem
