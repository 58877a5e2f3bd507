// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/fem/TetGrid.h>

#include <vector>

namespace crumple::fem
{

/// Describes a fence: square posts at a regular spacing joined by horizontal rails, all cut from one lattice
/// of cubes, so posts and rails are conforming and each cube can break away on its own. The fence runs along
/// +x from mOrigin, its thickness along +y, its height along +z (z up, the base at mOrigin.z).
struct CRUMPLE_API TetFenceSettings
{
    Vec3 mOrigin = Vec3::Zero(); ///< Minimum corner (m), body frame
    double mLength = 4.0;        ///< Along x (m), > 0
    double mHeight = 1.2;        ///< Along z (m), > 0
    double mThickness = 0.1;     ///< Along y (m), > 0: posts and rails are this thick
    double mCellSize = 0.1;      ///< Target cube edge (m), > 0; each axis is divided evenly, at least 1 cell
    double mPostSpacing = 2.0;   ///< Between post centres (m), > 0, at least mLength / (cells along x); a post stands at each end
    double mPostWidth = 0.1;     ///< Along x (m), > 0; at least one cell
    int mRailCount = 2;          ///< Rails, in [1, cells up the height], centred at heights H (r + 1) / (mRailCount + 1) ...
    double mRailHeight = 0.1;    ///< ... each this tall (m), > 0; at least one cell
    ECubeSplit mSplit = ECubeSplit::Five; ///< Tetrahedra per cube
};

/// A fence mesh and the nodes to anchor: the bottoms of its posts.
struct CRUMPLE_API TetFence
{
    TetMesh mMesh;                ///< Posts and rails
    std::vector<int> mGroundNodes; ///< Nodes at the base (z = mOrigin.z), ascending
    std::array<int, 3> mCellCount{}; ///< The lattice the fence was cut from (group id = i + n_x (j + n_y k))
};

/// Builds a fence (TetGridCells over its bounding box). Refused with a message naming the field: non-finite
/// or non-positive sizes, fewer than one rail, more cells than TetGridSettings::cMaxCells.
CRUMPLE_API Result<TetFence> MakeTetFence(const TetFenceSettings& inSettings);

} // namespace crumple::fem
