// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/TetFence.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace crumple::fem
{

namespace
{

Error FieldError(const char* inField, double inValue, const char* inReason)
{
    std::ostringstream message;
    message << "TetFenceSettings." << inField << " = " << inValue << ": " << inReason;
    return MakeError(std::isfinite(inValue) ? EError::InvalidArgument : EError::NonFinite, message.str());
}

// Cells along an extent, evenly divided at about the target size.
int CellsAlong(double inExtent, double inCellSize)
{
    return std::max(1, static_cast<int>(std::lround(inExtent / inCellSize)));
}

} // namespace

Result<TetFence> MakeTetFence(const TetFenceSettings& inSettings)
{
    // Every size must be finite and positive.
    const struct
    {
        const char* mName;
        double mValue;
    } sizes[] = {{"mLength", inSettings.mLength},           {"mHeight", inSettings.mHeight},
                 {"mThickness", inSettings.mThickness},     {"mCellSize", inSettings.mCellSize},
                 {"mPostSpacing", inSettings.mPostSpacing}, {"mPostWidth", inSettings.mPostWidth},
                 {"mRailHeight", inSettings.mRailHeight}};
    for (const auto& size : sizes)
        if (!(size.mValue > 0.0) || !std::isfinite(size.mValue))
            return FieldError(size.mName, size.mValue, "must be finite and > 0 m");
    if (inSettings.mRailCount < 1)
        return FieldError("mRailCount", inSettings.mRailCount, "must be >= 1");
    if (!IsFinite(inSettings.mOrigin))
        return MakeError(EError::NonFinite, "TetFenceSettings.mOrigin must be finite");

    // The lattice over the bounding box (guarded against absurd counts before any allocation).
    TetGridSettings grid;
    grid.mOrigin = inSettings.mOrigin;
    grid.mSize = Vec3(inSettings.mLength, inSettings.mThickness, inSettings.mHeight);
    const double counts[3] = {std::round(inSettings.mLength / inSettings.mCellSize),
                              std::round(inSettings.mThickness / inSettings.mCellSize),
                              std::round(inSettings.mHeight / inSettings.mCellSize)};
    if (std::max(counts[0], 1.0) * std::max(counts[1], 1.0) * std::max(counts[2], 1.0) > TetGridSettings::cMaxCells)
        return FieldError("mCellSize", inSettings.mCellSize, "makes more cells than TetGridSettings::cMaxCells");
    grid.mCellCount = {CellsAlong(inSettings.mLength, inSettings.mCellSize),
                       CellsAlong(inSettings.mThickness, inSettings.mCellSize),
                       CellsAlong(inSettings.mHeight, inSettings.mCellSize)};
    grid.mSplit = inSettings.mSplit;
    const std::array<int, 3>& n = grid.mCellCount;
    const double dx = inSettings.mLength / n[0], dz = inSettings.mHeight / n[2];
    // intent: no more posts or rails than cells to hold them (INT_MAX rails overflowed, a 2e-9 m spacing looped
    // for seconds, and 1e-9 m was cut to one interval by the integer conversion)
    if (!(inSettings.mLength / inSettings.mPostSpacing <= static_cast<double>(n[0])))
        return FieldError("mPostSpacing", inSettings.mPostSpacing, "makes more posts than the fence has cells along its length");
    if (inSettings.mRailCount > n[2])
        return FieldError("mRailCount", inSettings.mRailCount, "is more than the fence has cells up its height");

    // Posts and rails snapped to whole cells: round(w / d) cells (at least one) starting at the cell nearest
    // to c - w/2. A relative bias of 1e-9 breaks the tie of a centre exactly on a cell boundary towards +,
    // whatever the round-off of c / d.
    auto mark = [](std::vector<std::uint8_t>& ioCells, double inCentre, double inWidth, double inSpacing)
    {
        const int count = static_cast<int>(ioCells.size());
        const int width = std::clamp(static_cast<int>(std::lround(inWidth / inSpacing)), 1, count);
        const int low = std::clamp(static_cast<int>(std::floor(inCentre / inSpacing - 0.5 * width + 0.5 + 1e-9)), 0,
                                   count - width);
        for (int cell = low; cell < low + width; ++cell)
            ioCells[cell] = 1;
    };
    // Post centres: both ends (flush) and evenly spread between, about mPostSpacing apart.
    const int intervals = std::max(1, static_cast<int>(std::lround(inSettings.mLength / inSettings.mPostSpacing)));
    const double post_width = std::max(inSettings.mPostWidth, dx);
    std::vector<std::uint8_t> post_columns(n[0], 0), rail_rows(n[2], 0);
    for (int post = 0; post <= intervals; ++post)
        mark(post_columns,
             std::clamp(inSettings.mLength * post / intervals, 0.5 * post_width, inSettings.mLength - 0.5 * post_width),
             post_width, dx);
    for (int rail = 0; rail < inSettings.mRailCount; ++rail)
        mark(rail_rows, inSettings.mHeight * (rail + 1) / (inSettings.mRailCount + 1),
             std::max(inSettings.mRailHeight, dz), dz);

    // Keep the cells in a post column or a rail row.
    std::vector<std::uint8_t> keep(static_cast<std::size_t>(n[0]) * n[1] * n[2], 0);
    for (int k = 0; k < n[2]; ++k)
        for (int j = 0; j < n[1]; ++j)
            for (int i = 0; i < n[0]; ++i)
                keep[i + n[0] * (j + n[1] * k)] = post_columns[i] != 0 || rail_rows[k] != 0 ? 1 : 0;

    Result<TetMesh> mesh = TetGridCells(grid, keep);
    if (mesh.HasError())
        return mesh.GetError();
    TetFence fence{std::move(mesh.Get()), {}, n};
    for (int node = 0; node < fence.mMesh.GetNodeCount(); ++node)
        if (fence.mMesh.GetRestPositions()[node].z() == inSettings.mOrigin.z())
            fence.mGroundNodes.push_back(node);
    return fence;
}

} // namespace crumple::fem
