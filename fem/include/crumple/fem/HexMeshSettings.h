// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Math.h>

#include <array>

namespace crumple::fem
{

/// Describes a structured hexahedral mesh of an axis-aligned box (body frame): mCellCount[0] x mCellCount[1] x
/// mCellCount[2] equal cells. HexMesh::Create(const HexMeshSettings&) builds it; node and element numbering are
/// documented on HexMesh.
struct CRUMPLE_API HexMeshSettings
{
    Vec3 mOrigin = Vec3::Zero();                ///< Box corner with the smallest coordinates, body frame (m), finite
    Vec3 mSize = Vec3::Ones();                  ///< Box extent along x, y, z (m), finite and > 0
    std::array<int, 3> mCellCount{{1, 1, 1}};   ///< Cells per axis, in [1, cMaxCellsPerAxis]

    static constexpr int cMaxCellsPerAxis = 1024;        ///< Guards against a typo allocating gigabytes
    /// At most 262,144 cells in all: beyond this the sparse factorization needs gigabytes, which is a typo for a
    /// game prop, not a dent model.
    static constexpr int cMaxCellTotal = 1 << 18;
};

} // namespace crumple::fem
