// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Math.h>

namespace crumple::ffd
{

/// One constrained point of a dent: where it is and how far it must move.
struct CRUMPLE_API PointDisplacement
{
    Vec3 mPoint = Vec3::Zero();        ///< Point on the current (deformed) surface, body frame (m)
    Vec3 mDisplacement = Vec3::Zero(); ///< Wanted displacement of that point, body frame (m)
};

} // namespace crumple::ffd
