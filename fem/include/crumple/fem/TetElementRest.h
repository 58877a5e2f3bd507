// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/fem/TetMesh.h>

#include <vector>

namespace crumple::fem
{

/// What an element needs from its rest shape, computed once. Plastic rest-shape changes will modify these per
/// element without touching the mesh.
struct CRUMPLE_API TetElementRest
{
    Mat3 mRestEdgeInverse = Mat3::Identity(); ///< D_m^-1 (1/m), 3 by 3, inverse of the rest EdgeMatrix
    double mRestVolume = 0.0;                 ///< V0 (m^3), > 0
};

/// Rest data of every element of a mesh, in element order.
/// @param[in] inMesh  a valid mesh (positive volumes)
/// @return #T rest data
CRUMPLE_API std::vector<TetElementRest> TetRestData(const TetMesh& inMesh);

} // namespace crumple::fem
