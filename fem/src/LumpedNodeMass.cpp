// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/LumpedNodeMass.h>

namespace crumple::fem
{

std::vector<double> LumpedNodeMass(const TetMesh& inMesh, double inDensity)
{
    // A quarter of every element's mass to each corner, in element order (deterministic sums).
    std::vector<double> masses(static_cast<std::size_t>(inMesh.GetNodeCount()), 0.0);
    for (int tet = 0; tet < inMesh.GetTetCount(); ++tet)
    {
        const double quarter = 0.25 * inDensity * inMesh.GetRestVolume(tet);
        for (int node : inMesh.GetTets()[tet])
            masses[node] += quarter;
    }
    return masses;
}

} // namespace crumple::fem
