// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>
#include <crumple/base/Result.h>

#include <Eigen/Cholesky>
#include <Eigen/Core>

namespace crumple::ffd
{

/// The Moore-Penrose inverse of a rank-revealed Gram matrix L L^T, prepared for solves.
///
/// L is #n by r, lower trapezoidal with a positive diagonal (a pivoted Cholesky factor cut at rank r):
/// L = [L11; L21] = M L11 with M = [I; S] and S = L21 L11^-1, the dependent rows written in the independent
/// ones. For M of full column rank, (M A M^T)^+ = M N A^-1 N M^T with A = L11 L11^T and
/// N = (M^T M)^-1 = (I + S^T S)^-1 = I - S^T (I + S S^T)^-1 S (Woodbury). This is the same operator as
/// L (L^T L)^-2 L^T, but its products run over the #n - r dependent rows instead of all #n: forming S costs
/// (#n - r) r^2 / 2 multiplications and the smaller of the two coupling matrices about as much, against
/// #n r^2 / 2 for L^T L and r^3 / 6 for its Cholesky factor.
struct CRUMPLE_API GramPseudoInverse
{
    Eigen::MatrixXd mDependentT;             ///< r by (#n - r): S^T = L11^-T L21^T
    Eigen::LLT<Eigen::MatrixXd> mCoupling;   ///< Cholesky factor of I + S^T S (r by r), or of I + S S^T
    bool mCouplingOfDependents = false;      ///< True: mCoupling is of I + S S^T ((#n - r) by (#n - r), the smaller)
    int mRank = 0;                           ///< r
    Eigen::VectorXd mFactorDiagonal;         ///< L's diagonal (r), bit for bit: a solve with another factor is refused
};

/// Prepares the pseudo-inverse of inL inL^T. Only the lower trapezoid of inL is read.
/// @param[in] inL  #n by r (r <= #n), lower trapezoidal, finite, with a positive diagonal
/// @return the prepared inverse, or an error (InvalidArgument, NonFinite) for an inL that is not such a factor
CRUMPLE_API Result<GramPseudoInverse> PrepareGramPseudoInverse(const Eigen::Ref<const Eigen::MatrixXd>& inL);

/// (inL inL^T)^+ inRhs, for the inL the inverse was prepared from.
/// @param[in] inRhs  #n by 3, rows in the order of inL's rows, finite
/// @return #n by 3, or an error for an inL of another shape or diagonal than the prepared one's
///         (InvalidArgument) or a right-hand side of another row count (InvalidArgument) or not finite (NonFinite)
CRUMPLE_API Result<Eigen::MatrixX3d> SolveGramPseudoInverse(const GramPseudoInverse& inInverse,
                                                            const Eigen::Ref<const Eigen::MatrixXd>& inL,
                                                            const Eigen::MatrixX3d& inRhs);

} // namespace crumple::ffd
