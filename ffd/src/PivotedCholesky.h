// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>

#include <vector>

namespace crumple::ffd
{

/// A row-major dense matrix: the factorization reads and writes along rows.
using RowMajorMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

/// A rank-revealing Cholesky factor of a symmetric positive semi-definite matrix G: with the symmetric
/// permutation P (row k of P G P^T is row mPivots[k] of G), P G P^T ~ L L^T with L lower trapezoidal,
/// #n by mRank. The error of the approximation is the Schur complement left when the factorization stopped:
/// a positive semi-definite matrix whose diagonal is below the stopping threshold.
struct PivotedCholeskyFactor
{
    Eigen::MatrixXd mL;        ///< #n by mRank lower trapezoidal factor, rows in pivot order
    std::vector<int> mPivots;  ///< #n: pivot order (the first mRank are the independent rows)
    int mRank = 0;             ///< Number of pivots above the threshold
};

/// Cholesky with complete (diagonal) pivoting (Higham, "Accuracy and Stability of Numerical Algorithms",
/// 2nd ed., section 10.3): at each step the largest remaining diagonal is eliminated, and the factorization
/// stops when it is at most inRelativeThreshold times the largest diagonal of G. For G = A^T A this picks
/// the same pivots as a column-pivoted QR of A, with |R_kk|^2 = the pivots, so stopping at tau^2 here is
/// the rank decision |R_kk| <= tau |R_00| of a rank-revealing QR. Ties go to the lower index, so the
/// factor is a pure function of G's bytes. Cost: O(n rank^2), most of it in matrix-matrix products (blocked
/// as LAPACK's dpstrf: panels of columns, then one symmetric update of the rest).
/// @param[in] inG                  #n by #n symmetric positive semi-definite, taken by value and factored in
///                                 place (move it in to save a copy); only its lower triangle is read
/// @param[in] inRelativeThreshold  stop when the largest remaining diagonal is <= this times max diag(G)
PivotedCholeskyFactor PivotedCholesky(RowMajorMatrix inG, double inRelativeThreshold);

} // namespace crumple::ffd
