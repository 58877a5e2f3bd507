// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "PivotedCholesky.h"

#include <cmath>
#include <numeric>
#include <utility>

namespace crumple::ffd
{

PivotedCholeskyFactor PivotedCholesky(const Eigen::MatrixXd& inG, double inRelativeThreshold)
{
    const Eigen::Index n = inG.rows();
    PivotedCholeskyFactor factor;
    factor.mPivots.resize(static_cast<std::size_t>(n));
    std::iota(factor.mPivots.begin(), factor.mPivots.end(), 0);
    if (n == 0)
        return factor;

    // Remaining diagonal of the Schur complement, in pivot order.
    Eigen::VectorXd diagonal = inG.diagonal();
    const double stop = inRelativeThreshold * diagonal.maxCoeff();
    // Row-major: the inner products below run along rows of L. Not zeroed (a dent's 300 points made that
    // a 0.7 MB fill and its page faults): every entry read below the diagonal is written first, and the
    // strictly upper part is zeroed once at the end.
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> l(n, n);
    std::vector<int>& pivots = factor.mPivots;
    Eigen::VectorXd column(n);

    Eigen::Index k = 0;
    for (; k < n; ++k)
    {
        // intent: the largest remaining diagonal (first one on ties) becomes pivot k
        Eigen::Index best = k;
        for (Eigen::Index i = k + 1; i < n; ++i)
            if (diagonal[i] > diagonal[best])
                best = i;
        if (!(diagonal[best] > stop))
            break;
        if (best != k)
        {
            std::swap(pivots[static_cast<std::size_t>(k)], pivots[static_cast<std::size_t>(best)]);
            std::swap(diagonal[k], diagonal[best]);
            l.row(k).head(k).swap(l.row(best).head(k));
        }

        // intent: column k of L from G's column of the pivot, minus the part already eliminated (one
        // matrix-vector product over the rows below, so that Eigen vectorizes it)
        const double pivot = std::sqrt(diagonal[k]);
        l(k, k) = pivot;
        const auto pk = static_cast<Eigen::Index>(pivots[static_cast<std::size_t>(k)]);
        const Eigen::Index below = n - k - 1;
        column.head(below).noalias() = l.block(k + 1, 0, below, k) * l.row(k).head(k).transpose();
        for (Eigen::Index i = k + 1; i < n; ++i)
        {
            const auto pi = static_cast<Eigen::Index>(pivots[static_cast<std::size_t>(i)]);
            const double g = pi > pk ? inG(pi, pk) : inG(pk, pi);
            const double value = (g - column[i - k - 1]) / pivot;
            l(i, k) = value;
            diagonal[i] -= value * value;
        }
    }
    factor.mRank = static_cast<int>(k);
    factor.mL = l.leftCols(k);
    factor.mL.triangularView<Eigen::StrictlyUpper>().setZero();
    return factor;
}

} // namespace crumple::ffd
