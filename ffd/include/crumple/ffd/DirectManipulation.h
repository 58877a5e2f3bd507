// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Result.h>
#include <crumple/ffd/FfdLattice.h>

#include <Eigen/Core>
#include <Eigen/QR>

#include <span>
#include <vector>

namespace crumple::ffd
{

/// Direct manipulation of an FFD lattice (Hughes & Kaufman 1992; D4MD eq. 3): for constrained points P
/// with wanted displacements dP, the control displacements are dC = B^+ dP, the minimum-norm
/// least-squares solution, where row r of B holds the 64 B-spline weights of point r over the controls
/// that reach it. B^+ is applied through a complete orthogonal decomposition (column-pivoted QR followed
/// by an RQ of the triangular factor), which is rank revealing: pivots below
/// inRelativeTolerance x the largest are treated as zero. Coincident points (identical rows) or
/// collinear points (rank-deficient B) therefore give the minimum-norm solution instead of blowing up.
struct DirectManipulationData
{
    std::vector<int> mControls;  ///< Linear indices of B's columns, ascending (the controls reached)
    Eigen::MatrixXd mB;          ///< #points by #controls weight matrix
    Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> mDecomposition; ///< Factorization of mB
    int mRank = 0;               ///< Numerical rank of mB under the tolerance
};

/// Default relative pivot tolerance of the rank-revealing decomposition. Pivots of B whose magnitude is
/// below 1e-8 of the largest are dropped: far below any weight a point can have on a reachable control
/// (>= (1/6)^3 / 64 ~ 7e-5 relative for an isolated point), far above round-off (~1e-15).
constexpr double cDefaultRankTolerance = 1.0e-8;

/// Builds B for points given by their lattice locations and factorizes it (the precompute step).
/// @param[in] inLattice    the lattice the points are in
/// @param[in] inLocations  #points locations (cell and local parameter)
/// @param[in] inRelativeTolerance pivot threshold relative to the largest pivot, in (0, 1)
DirectManipulationData DirectManipulationPrecompute(const FfdLattice& inLattice,
                                                    std::span<const LatticeLocation> inLocations,
                                                    double inRelativeTolerance = cDefaultRankTolerance);

/// Solves dC = B^+ dP (the solve step).
/// @param[in] inData         from DirectManipulationPrecompute
/// @param[in] inDisplacements #points by 3 wanted displacements (m)
/// @return #controls by 3 control displacements (m), rows in the order of inData.mControls
Eigen::MatrixX3d DirectManipulationSolve(const DirectManipulationData& inData, const Eigen::MatrixX3d& inDisplacements);

} // namespace crumple::ffd
