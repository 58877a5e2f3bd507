// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/LumpedNodeMass.h>

#include <cmath>
#include <string>

namespace crumple::fem
{

Result<std::vector<double>> LumpedNodeMass(const TetMesh& inMesh, double inDensity)
{
    return LumpedNodeMass(inMesh.GetTets(), TetRestData(inMesh), inMesh.GetNodeCount(), inDensity);
}

Result<std::vector<double>> LumpedNodeMass(std::span<const TetIndices> inElementNodes, std::span<const TetElementRest> inRest,
                                           int inNodeCount, double inDensity)
{
    if (!std::isfinite(inDensity) || !(inDensity > 0.0))
        return MakeError(EError::InvalidArgument, "LumpedNodeMass: the density must be finite and > 0 kg/m^3");
    if (inRest.size() != inElementNodes.size() || inNodeCount < 0)
        return MakeError(EError::InvalidArgument, "LumpedNodeMass: " + std::to_string(inElementNodes.size()) + " elements, " +
                                                      std::to_string(inRest.size()) + " rest data, " +
                                                      std::to_string(inNodeCount) + " nodes");
    for (std::size_t tet = 0; tet < inElementNodes.size(); ++tet)
    {
        for (int node : inElementNodes[tet])
            if (node < 0 || node >= inNodeCount)
                return MakeError(EError::OutOfRange, "LumpedNodeMass: element " + std::to_string(tet) + " names node " +
                                                         std::to_string(node) + " of " + std::to_string(inNodeCount));
        if (!std::isfinite(inRest[tet].mRestVolume) || !(inRest[tet].mRestVolume > 0.0))
            return MakeError(EError::DegenerateGeometry, "LumpedNodeMass: element " + std::to_string(tet) +
                                                             " has a rest volume that is not finite and > 0");
    }
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
