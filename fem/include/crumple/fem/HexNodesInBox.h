// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Math.h>
#include <crumple/fem/HexMesh.h>

#include <vector>

namespace crumple::fem
{

/// Nodes whose position lies in an axis-aligned box, bounds included: the usual way to pick fixed (boundary)
/// nodes, a tip face to load, or a surface whose dents to precompute. A box with a NaN bound or min > max
/// selects nothing.
/// @param[in] inMesh  the mesh
/// @param[in] inMin   smallest corner of the box, body frame (m)
/// @param[in] inMax   largest corner of the box, body frame (m)
/// @return node indices, ascending
CRUMPLE_API std::vector<int> HexNodesInBox(const HexMesh& inMesh, const Vec3& inMin, const Vec3& inMax);

} // namespace crumple::fem
