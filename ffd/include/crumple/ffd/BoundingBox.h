// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Math.h>

#include <span>

namespace crumple::ffd
{

/// An axis-aligned box (m).
struct CRUMPLE_API AlignedBox
{
    Vec3 mMin = Vec3::Zero(); ///< Smallest coordinates
    Vec3 mMax = Vec3::Zero(); ///< Largest coordinates
};

/// The axis-aligned bounding box of a point set (a zero box at the origin for an empty set).
CRUMPLE_API AlignedBox BoundingBox(std::span<const Vec3> inPoints);

} // namespace crumple::ffd
