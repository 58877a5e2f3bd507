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

/// Default relative pivot tolerance of the rank-revealing decomposition: pivots of B below 1e-3 of the
/// largest are treated as zero. A direction that B can only excite that weakly would need control
/// displacements over a thousand times the dent to satisfy, which is a blow-up, not a dent: dense or
/// planar contact sets (38 contacts plus interpolated samples on one car face) reach pivot ratios of 1e-6
/// and then ask for controls of 30 m to make a 0.1 m dent. Measured on that case (crumple-bench,
/// lattice_resolution): 1e-8 -> controls 33 m; 1e-5 -> 1.4 m and 135 % overshoot at the face corner;
/// 1e-3 -> 0.22 m, 5 % overshoot, contact error 0.24 %; 1e-2 -> no overshoot, contact error 1.2 %.
constexpr double cDefaultRankTolerance = 1.0e-3;

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
