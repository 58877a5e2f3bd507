// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/ffd/GramPseudoInverse.h>

#include <crumple/base/Assert.h>

namespace crumple::ffd
{

namespace
{

// N inU with N = (I + S^T S)^-1, through whichever coupling matrix was factored.
Eigen::MatrixX3d ApplyCoupling(const GramPseudoInverse& inInverse, const Eigen::MatrixX3d& inU)
{
    if (inInverse.mDependentT.cols() == 0)
        return inU;
    if (!inInverse.mCouplingOfDependents)
        return inInverse.mCoupling.solve(inU);
    // Woodbury: (I + S^T S)^-1 = I - S^T (I + S S^T)^-1 S.
    const Eigen::MatrixX3d su = inInverse.mDependentT.transpose() * inU;
    return inU - inInverse.mDependentT * inInverse.mCoupling.solve(su);
}

} // namespace

GramPseudoInverse PrepareGramPseudoInverse(const Eigen::Ref<const Eigen::MatrixXd>& inL)
{
    CRUMPLE_ASSERT(inL.cols() <= inL.rows() && (inL.cols() == 0 || inL.diagonal().minCoeff() > 0.0),
                   "PrepareGramPseudoInverse: L must be #n by r <= #n with a positive diagonal");
    GramPseudoInverse inverse;
    const Eigen::Index r = inL.cols();
    const Eigen::Index dependent = inL.rows() - r;
    inverse.mRank = static_cast<int>(r);
    // intent: S^T = L11^-T L21^T, one triangular solve with the dependent rows as right-hand sides
    inverse.mDependentT = inL.bottomRows(dependent).transpose();
    inL.topRows(r).triangularView<Eigen::Lower>().transpose().solveInPlace(inverse.mDependentT);
    if (dependent == 0)
        return inverse;

    // intent: factor the smaller of I + S^T S (r by r) and I + S S^T (dependent by dependent); only the lower
    // triangle is formed, the factorization reads nothing else
    inverse.mCouplingOfDependents = dependent < r;
    const Eigen::Index size = inverse.mCouplingOfDependents ? dependent : r;
    Eigen::MatrixXd coupling = Eigen::MatrixXd::Identity(size, size);
    if (inverse.mCouplingOfDependents)
        coupling.selfadjointView<Eigen::Lower>().rankUpdate(inverse.mDependentT.transpose());
    else
        coupling.selfadjointView<Eigen::Lower>().rankUpdate(inverse.mDependentT);
    inverse.mCoupling.compute(coupling);
    return inverse;
}

Eigen::MatrixX3d SolveGramPseudoInverse(const GramPseudoInverse& inInverse, const Eigen::Ref<const Eigen::MatrixXd>& inL,
                                        const Eigen::MatrixX3d& inRhs)
{
    const Eigen::Index r = inInverse.mRank;
    const Eigen::Index dependent = inL.rows() - r;
    CRUMPLE_ASSERT(inL.cols() == r && inInverse.mDependentT.rows() == r && inInverse.mDependentT.cols() == dependent &&
                       inRhs.rows() == inL.rows(),
                   "SolveGramPseudoInverse: L or the right-hand side is not the one the inverse was prepared for");
    const auto l11 = inL.topRows(r).triangularView<Eigen::Lower>();
    // intent: M N A^-1 N M^T inRhs, right to left
    Eigen::MatrixX3d u = inRhs.topRows(r);
    if (dependent > 0)
        u.noalias() += inInverse.mDependentT * inRhs.bottomRows(dependent);
    u = ApplyCoupling(inInverse, u);
    l11.solveInPlace(u);
    l11.transpose().solveInPlace(u);
    u = ApplyCoupling(inInverse, u);
    Eigen::MatrixX3d result(inL.rows(), 3);
    result.topRows(r) = u;
    if (dependent > 0)
        result.bottomRows(dependent).noalias() = inInverse.mDependentT.transpose() * u;
    return result;
}

} // namespace crumple::ffd
