// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Math.h>

#include <array>

namespace crumple::ffd
{

/// Describes one deformation volume: an oriented box in the body frame carrying a uniform cubic
/// B-spline lattice. The box spans exactly the region where the spline is defined (D4MD section 5:
/// no phantom controls), so with n controls along an axis the box holds n - 3 spline segments and the
/// controls sit one spacing outside the box on each side.
struct CRUMPLE_API FfdLatticeSettings
{
    Vec3 mOrigin = Vec3::Zero();            ///< Box corner with lattice coordinate (0,0,0), body frame (m), each
                                            ///< coordinate within cMaxExtent
    Mat3 mAxes = Mat3::Identity();          ///< Box edge directions as columns, body frame, orthonormal, det +1
    Vec3 mSize = Vec3::Ones();              ///< Box extent along each axis (m), in (1e-9, cMaxExtent]
    std::array<int, 3> mControlCount{{4, 4, 4}}; ///< Controls per axis, >= 4 (at most cMaxControlsPerAxis)

    static constexpr int cMinControlsPerAxis = 4;   ///< A cubic needs four controls per segment
    static constexpr int cMaxControlsPerAxis = 256; ///< Guards against a typo allocating gigabytes
    /// Bound on the origin's coordinates and the size (m): ten times the meshes' (cMaxMeshCoordinate), so any
    /// box around a mesh fits, and lattice coordinates keep their precision
    static constexpr double cMaxExtent = 1.0e7;
};

} // namespace crumple::ffd
