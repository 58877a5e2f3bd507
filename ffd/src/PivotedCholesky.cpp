// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "PivotedCholesky.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

namespace crumple::ffd
{

namespace
{

// Columns factored per panel before the trailing matrix is updated by one symmetric rank-k product: the
// update is then a matrix-matrix product (the bulk of the work), the panel's own columns matrix-vector ones.
constexpr Eigen::Index cPanelWidth = 32;

// Swaps indices inK < inP of the symmetric matrix held in the lower triangle of ioA, where columns before
// inK hold factor rows (swapped whole) and the rest the not yet factored matrix (LAPACK's dsyswapr).
void SymmetricSwap(RowMajorMatrix& ioA, Eigen::Index inK, Eigen::Index inP)
{
    ioA.row(inK).head(inK).swap(ioA.row(inP).head(inK));
    std::swap(ioA(inK, inK), ioA(inP, inP));
    for (Eigen::Index j = inK + 1; j < inP; ++j)
        std::swap(ioA(j, inK), ioA(inP, j));
    for (Eigen::Index i = inP + 1; i < ioA.rows(); ++i)
        std::swap(ioA(i, inK), ioA(i, inP));
}

} // namespace

PivotedCholeskyFactor PivotedCholesky(RowMajorMatrix inG, double inRelativeThreshold)
{
    const Eigen::Index n = inG.rows();
    PivotedCholeskyFactor factor;
    factor.mPivots.resize(static_cast<std::size_t>(n));
    std::iota(factor.mPivots.begin(), factor.mPivots.end(), 0);
    if (n == 0)
        return factor;

    // Blocked right-looking factorization in place (LAPACK's dpstrf): the lower triangle of a becomes L
    // column by column; the diagonal of the remaining Schur complement is kept up to date column by column,
    // so the pivots are those of the unblocked algorithm.
    RowMajorMatrix& a = inG;
    std::vector<int>& pivots = factor.mPivots;
    Eigen::VectorXd diagonal = a.diagonal();
    const double stop = inRelativeThreshold * diagonal.maxCoeff();

    Eigen::Index k = 0;
    bool stopped = false;
    for (Eigen::Index panel = 0; panel < n && !stopped; panel += cPanelWidth)
    {
        const Eigen::Index panel_end = std::min(n, panel + cPanelWidth);
        for (k = panel; k < panel_end; ++k)
        {
            // intent: the largest remaining diagonal (first one on ties) becomes pivot k
            Eigen::Index best = k;
            for (Eigen::Index i = k + 1; i < n; ++i)
                if (diagonal[i] > diagonal[best])
                    best = i;
            if (!(diagonal[best] > stop))
            {
                stopped = true;
                break;
            }
            if (best != k)
            {
                std::swap(pivots[static_cast<std::size_t>(k)], pivots[static_cast<std::size_t>(best)]);
                std::swap(diagonal[k], diagonal[best]);
                SymmetricSwap(a, k, best);
            }

            // intent: column k of L: the matrix's column, updated through the last panel, less this panel's
            // columns so far (one matrix-vector product over the rows below, so that Eigen vectorizes it)
            const double pivot = std::sqrt(diagonal[k]);
            a(k, k) = pivot;
            const Eigen::Index below = n - k - 1;
            const Eigen::Index done = k - panel;
            if (done > 0)
                a.col(k).tail(below).noalias() -= a.block(k + 1, panel, below, done) * a.row(k).segment(panel, done).transpose();
            a.col(k).tail(below) /= pivot;
            for (Eigen::Index i = k + 1; i < n; ++i)
                diagonal[i] -= a(i, k) * a(i, k);
        }
        // intent: the trailing matrix less the panel's columns, one symmetric rank-k product (lower half)
        const Eigen::Index trailing = n - k;
        if (!stopped && trailing > 0)
            a.block(k, k, trailing, trailing)
                .selfadjointView<Eigen::Lower>()
                .rankUpdate(a.block(k, panel, trailing, k - panel), -1.0);
    }
    factor.mRank = static_cast<int>(k);
    factor.mL = a.leftCols(k);
    factor.mL.triangularView<Eigen::StrictlyUpper>().setZero();
    return factor;
}

} // namespace crumple::ffd
