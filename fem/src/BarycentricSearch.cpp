// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/BarycentricSearch.h>

#include <crumple/fem/EdgeMatrix.h>

#include <algorithm>
#include <limits>
#include <string>

namespace crumple::fem
{

Result<BarycentricSearch> BarycentricSearch::Create(std::span<const TetIndices> inElementNodes,
                                                    std::span<const Vec3> inPositions)
{
    // Invert every element's edge matrix once for all points.
    BarycentricSearch search;
    search.mMaps.resize(inElementNodes.size());
    for (std::size_t element = 0; element < inElementNodes.size(); ++element)
    {
        const TetIndices& corners = inElementNodes[element];
        for (int node : corners)
            if (node < 0 || static_cast<std::size_t>(node) >= inPositions.size())
                return MakeError(EError::OutOfRange, "BarycentricSearch: element " + std::to_string(element) + " names node " +
                                                         std::to_string(node) + " of " + std::to_string(inPositions.size()));
        const Vec3& origin = inPositions[corners[0]];
        search.mMaps[element] = {origin, EdgeMatrix(origin, inPositions[corners[1]], inPositions[corners[2]],
                                                    inPositions[corners[3]])
                                             .inverse()};
    }
    return search;
}

std::array<double, 4> BarycentricSearch::Weights(int inElement, const Vec3& inPoint) const
{
    if (inElement < 0 || static_cast<std::size_t>(inElement) >= mMaps.size())
    {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        return {{nan, nan, nan, nan}};
    }
    // l = D^-1 (x - p0), w = (1 - l1 - l2 - l3, l1, l2, l3).
    const ElementMap& map = mMaps[inElement];
    const Vec3 local = map.mInverseEdges * (inPoint - map.mOrigin);
    return {{1.0 - local[0] - local[1] - local[2], local[0], local[1], local[2]}};
}

void BarycentricSearch::Consider(int inElement, const Vec3& inPoint, BarycentricHit& ioBest) const
{
    const std::array<double, 4> weights = Weights(inElement, inPoint);
    const double smallest = *std::min_element(weights.begin(), weights.end());
    if (smallest > ioBest.mMinWeight) // strict: ties keep the earlier candidate, NaN (degenerate) never wins
    {
        ioBest.mElement = inElement;
        ioBest.mWeights = weights;
        ioBest.mMinWeight = smallest;
    }
}

BarycentricHit BarycentricSearch::FindBest(std::span<const int> inCandidates, const Vec3& inPoint) const
{
    BarycentricHit best;
    for (const int element : inCandidates)
        Consider(element, inPoint, best);
    return best;
}

BarycentricHit BarycentricSearch::FindBest(const Vec3& inPoint) const
{
    BarycentricHit best;
    for (std::size_t element = 0; element < mMaps.size(); ++element)
        Consider(static_cast<int>(element), inPoint, best);
    return best;
}

} // namespace crumple::fem
