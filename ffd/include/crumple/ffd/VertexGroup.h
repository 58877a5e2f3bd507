// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Math.h>

#include <cstdint>
#include <span>

namespace crumple::ffd
{

/// Some of a deformer's vertices and a box that holds their current positions (FfdDeformer::
/// ForEachVertexGroup): a scan over the surface can skip the whole group when its box says no vertex in it
/// can count. Body frame, m.
struct VertexGroup
{
    /// False for the vertices in no zone: they never move, and no box is kept for them (scan them all)
    bool mBounded = true;
    /// Every current position p of mVertices lies within mMoved of the box [mLow, mHigh]: |p - q| <= mMoved
    /// for some q in it (FfdDeformer::ForEachVertexGroup hands the box of the current positions themselves,
    /// with mMoved 0)
    Vec3 mLow = Vec3::Zero(), mHigh = Vec3::Zero();
    double mMoved = 0.0;
    std::span<const std::uint32_t> mVertices; ///< Indices into the deformer's positions
};

} // namespace crumple::ffd
