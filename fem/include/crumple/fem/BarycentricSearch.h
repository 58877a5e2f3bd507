// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>
#include <crumple/base/Result.h>

#include <crumple/base/Math.h>
#include <crumple/fem/TetMesh.h>

#include <array>
#include <limits>
#include <span>
#include <vector>

namespace crumple::fem
{

/// The element a point is bound to: among the candidates, the one whose smallest barycentric weight is
/// largest (the containing element if there is one, else the nearest in weight space).
struct CRUMPLE_API BarycentricHit
{
    int mElement = -1;                                            ///< Element index, -1 when none won
    std::array<double, 4> mWeights{};                             ///< Its barycentric weights, sum 1
    double mMinWeight = -std::numeric_limits<double>::infinity(); ///< Smallest of mWeights (< 0 outside)
};

/// Barycentric coordinates of points in the elements of a tetrahedral mesh, with every element's edge matrix
/// inverted once up front (EmbeddedMesh binds display vertices with it, props::CollisionNodalImpulses spreads
/// contact impulses). The weights of x in element (p0, p1, p2, p3) solve D l = x - p0 with D =
/// EdgeMatrix(p0, p1, p2, p3), then w = (1 - l1 - l2 - l3, l1, l2, l3) in that order of subtraction.
class CRUMPLE_API BarycentricSearch
{
  public:
    /// Inverts the edge matrix of every element of inElementNodes (#T corner node indices into inPositions,
    /// #N, m). A degenerate element gets a non-finite inverse, so its weights are NaN and it never wins.
    /// Refused, with the element named, when a corner index is outside [0, #N).
    static Result<BarycentricSearch> Create(std::span<const TetIndices> inElementNodes, std::span<const Vec3> inPositions);

    /// Barycentric weights of inPoint (m, same frame as the positions) in inElement; negative outside it, NaN
    /// for an element index outside [0, #T).
    std::array<double, 4> Weights(int inElement, const Vec3& inPoint) const;

    /// The element of inCandidates (element indices, searched in the given order) with the largest minimum
    /// weight at inPoint. The comparison is strict, so the first of equal candidates wins and NaN never does;
    /// mElement is -1 when no candidate won (empty list, all degenerate or out of range).
    BarycentricHit FindBest(std::span<const int> inCandidates, const Vec3& inPoint) const;

    /// As FindBest above, over every element in index order.
    BarycentricHit FindBest(const Vec3& inPoint) const;

  private:
    BarycentricSearch() = default;

    /// Keeps inElement in ioBest if its minimum weight at inPoint beats ioBest's.
    void Consider(int inElement, const Vec3& inPoint, BarycentricHit& ioBest) const;

    /// What the weights of one element need: its first corner and the inverse of its edge matrix.
    struct ElementMap
    {
        Vec3 mOrigin;       ///< Corner p0 (m)
        Mat3 mInverseEdges; ///< D^-1 (1/m), non-finite for a degenerate element
    };
    std::vector<ElementMap> mMaps; ///< One per element, #T
};

} // namespace crumple::fem
