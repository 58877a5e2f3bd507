// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/LumpedNodeMass.h>

namespace crumple::fem
{

std::vector<double> LumpedNodeMass(const TetMesh& inMesh, double inDensity)
{
    return LumpedNodeMass(inMesh.GetTets(), TetRestData(inMesh), inMesh.GetNodeCount(), inDensity);
}

std::vector<double> LumpedNodeMass(std::span<const TetIndices> inElementNodes, std::span<const TetElementRest> inRest,
                                   int inNodeCount, double inDensity)
{
    // A quarter of every element's mass to each corner, in element order (deterministic sums).
    std::vector<double> masses(static_cast<std::size_t>(inNodeCount), 0.0);
    for (std::size_t tet = 0; tet < inElementNodes.size(); ++tet)
    {
        const double quarter = 0.25 * inDensity * inRest[tet].mRestVolume;
        for (int node : inElementNodes[tet])
            masses[node] += quarter;
    }
    return masses;
}

} // namespace crumple::fem
