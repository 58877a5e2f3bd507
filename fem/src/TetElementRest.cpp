// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/EdgeMatrix.h>
#include <crumple/fem/TetElementRest.h>

namespace crumple::fem
{

std::vector<TetElementRest> TetRestData(const TetMesh& inMesh)
{
    // D_m^-1 and V0 = det(D_m) / 6 per element; the mesh guarantees det(D_m) > 0.
    const std::vector<Vec3>& x = inMesh.GetRestPositions();
    std::vector<TetElementRest> rest(static_cast<std::size_t>(inMesh.GetTetCount()));
    for (int tet = 0; tet < inMesh.GetTetCount(); ++tet)
    {
        const TetIndices& nodes = inMesh.GetTets()[tet];
        const Mat3 edges = EdgeMatrix(x[nodes[0]], x[nodes[1]], x[nodes[2]], x[nodes[3]]);
        rest[tet].mRestEdgeInverse = edges.inverse();
        rest[tet].mRestVolume = edges.determinant() / 6.0;
    }
    return rest;
}

} // namespace crumple::fem
