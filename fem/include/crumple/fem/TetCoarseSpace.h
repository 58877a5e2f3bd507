// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>
#include <crumple/base/Math.h>
#include <crumple/base/Result.h>
#include <crumple/fem/IsotropicMaterialMatrix.h>
#include <crumple/fem/TetElementRest.h>
#include <crumple/fem/TetMesh.h>

#include <Eigen/Core>

#include <span>
#include <vector>

namespace crumple::fem
{

/// Limits of BuildTetCoarseSpace.
struct CRUMPLE_API TetCoarseSpaceSettings
{
    /// Most coarse unknowns (six per aggregate): the coarse system is inverted densely, about 2.3 (6 A)^3 flops
    /// (at 384, about a third of the 20 ms a 17,600-tetrahedron fence's space takes to build, and 0.6 MB as
    /// floats), each time the connectivity, the anchors or the time step change. Aggregates grow to keep
    /// within it.
    int mMaxCoarseUnknowns = 384;
    /// Fewest free nodes an aggregate is grown to (a smaller one is merged into a neighbour where it has
    /// one).
    int mMinAggregateNodes = 24;
    /// Fewest aggregates worth a coarse space; with fewer the space is empty. The additive correction counts
    /// the modes block Jacobi already reaches twice, which a few large aggregates do not repay: steel beams
    /// at 1/60 s took 80 instead of 41 iterations with 2 aggregates, 99 instead of 62 with 4 and 251 instead
    /// of 246 with 8 (of 300 nodes each), and 66-144 instead of 221-246 with 15 to 61; a 5 cm wooden fence
    /// 328 instead of 2,442 with 14.
    int mMinAggregates = 12;
};

/// A coarse space for the conjugate-gradient solves of an implicit FEM step that cannot use a factored
/// preconditioner (the GPU's: a factor needs sequential triangular solves): the free nodes are grouped into
/// connected aggregates (breadth-first from the lowest unassigned node, over the elements' edges), and each
/// aggregate's six rigid modes (three translations, three rotations about its rest centre) span the coarse
/// space, P (#free x 3 by 6 A). With the rest system A0 = a M + b K0 (fem::TetSolver's implicit system at
/// rest, the corotated model's tangent at rest frames) the two-level additive preconditioner is
///   B r = D^-1 r + P (P^T A0 P)^-1 P^T r,
/// D the 3x3 diagonal blocks of the current system. Block Jacobi alone smooths only what varies from node to
/// node, so its iteration count grows with the stiffness and the mesh (a 17,600-tetrahedron wooden fence at
/// 1/120 s did not converge to 1e-6 in 5,000 iterations; with 0.1 m aggregates of its 2.5 cm cubes, 55).
/// Aggregates never cross a crack: they follow the current connectivity. An aggregate with fewer than four
/// free nodes keeps its translations only (its rotation rows are zero in P and identity in the inverse).
/// A body with fewer aggregates than TetCoarseSpaceSettings::mMinAggregates, or with more separate pieces of
/// free nodes than mMaxCoarseUnknowns / 6 (each piece needs an aggregate of its own), gets an empty space (no
/// aggregate: block Jacobi alone).
struct CRUMPLE_API TetCoarseSpace
{
    std::vector<int> mNodeAggregate; ///< #N aggregate of each node, -1 for an anchored node
    std::vector<Vec3>
        mNodeOffset; ///< #N rest position less the aggregate's rest centre (m); zero when it rotates not
    std::vector<int> mAggregateStart; ///< #A + 1 offsets into mAggregateNodes
    std::vector<int> mAggregateNodes; ///< Each aggregate's nodes, ascending
    Eigen::MatrixXd mInverse; ///< (P^T A0 P)^-1, 6 A by 6 A: translations then rotations per aggregate

    /// Number of aggregates A
    int GetAggregateCount() const { return static_cast<int>(mAggregateStart.size()) - 1; }
};

/// Builds the coarse space of the implicit system a M + b K0 over the free nodes (inInverseMasses > 0).
/// @param[in] inElementNodes   #T current element -> node indices (after cracks: the duplicated nodes)
/// @param[in] inRest           #T rest data (TetElementRest)
/// @param[in] inRestPositions  #N rest position of each current node (m)
/// @param[in] inMasses         #N lumped masses (kg)
/// @param[in] inInverseMasses  #N 1/kg, 0 for an anchored node
/// @param[in] inMaterialMatrix C (Pa)
/// @param[in] inMassScale      a = 1 + h alpha
/// @param[in] inStiffnessScale b = h^2 + h beta (s^2)
/// @param[in] inSettings       limits (TetCoarseSpaceSettings)
/// @param[in] inFrames         #T element frames (unit quaternions) to build the corotated system at, or none
///                             (rest frames)
/// @param[in] inPositions      #N current node positions (m) the rigid modes turn about, or none (rest)
/// Refused: inconsistent sizes, an index out of range, a non-finite position, frame or scale, a negative
/// scale, no free node, and a coarse system that is not positive definite (a degenerate mesh).
CRUMPLE_API Result<TetCoarseSpace>
BuildTetCoarseSpace(std::span<const TetIndices> inElementNodes, std::span<const TetElementRest> inRest,
                    std::span<const Vec3> inRestPositions, std::span<const double> inMasses,
                    std::span<const double> inInverseMasses, const Matrix6& inMaterialMatrix,
                    double inMassScale, double inStiffnessScale,
                    const TetCoarseSpaceSettings& inSettings = {}, std::span<const Quat> inFrames = {},
                    std::span<const Vec3> inPositions = {});

} // namespace crumple::fem
