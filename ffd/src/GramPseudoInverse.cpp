// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/ffd/GramPseudoInverse.h>

#include <string>

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

Result<GramPseudoInverse> PrepareGramPseudoInverse(const Eigen::Ref<const Eigen::MatrixXd>& inL)
{
    if (!(inL.cols() <= inL.rows()))
        return MakeError(EError::InvalidArgument, "PrepareGramPseudoInverse: L has more columns (" + std::to_string(inL.cols()) +
                                                      ") than rows (" + std::to_string(inL.rows()) + ")");
    // intent: the lower trapezoid is all that is read; a NaN anywhere in it fails allFinite, and one on the
    // diagonal also fails "> 0" (a minimum over the diagonal would skip it)
    const Eigen::Index r = inL.cols();
    for (Eigen::Index column = 0; column < r; ++column)
        if (!inL.col(column).tail(inL.rows() - column).allFinite())
            return MakeError(EError::NonFinite, "PrepareGramPseudoInverse: L has a value that is not finite in column " +
                                                    std::to_string(column));
    if (!(inL.diagonal().array() > 0.0).all())
        return MakeError(EError::InvalidArgument, "PrepareGramPseudoInverse: L's diagonal must be positive");
    GramPseudoInverse inverse;
    const Eigen::Index dependent = inL.rows() - r;
    inverse.mRank = static_cast<int>(r);
    inverse.mFactorDiagonal = inL.diagonal();
    // intent: S^T = L11^-T L21^T, one triangular solve with the dependent rows as right-hand sides; none when
    // either side is empty (Eigen's triangular solve binds a reference to an empty matrix's first entry: UB)
    inverse.mDependentT = inL.bottomRows(dependent).transpose();
    if (dependent == 0 || r == 0)
    {
        inverse.mCoupling.compute(Eigen::MatrixXd(0, 0)); // unused, but set: an uncomputed LLT copies indeterminate state
        return inverse;
    }
    inL.topRows(r).triangularView<Eigen::Lower>().transpose().solveInPlace(inverse.mDependentT);

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

Result<Eigen::MatrixX3d> SolveGramPseudoInverse(const GramPseudoInverse& inInverse, const Eigen::Ref<const Eigen::MatrixXd>& inL,
                                                const Eigen::MatrixX3d& inRhs)
{
    const Eigen::Index r = inInverse.mRank;
    // intent: the factor prepared from, by shape (#n = r + the dependent rows) and diagonal bit for bit (O(r))
    if (inL.rows() != r + inInverse.mDependentT.cols() || inL.cols() != r || inInverse.mFactorDiagonal.size() != r ||
        (r > 0 && !(inL.diagonal().array() == inInverse.mFactorDiagonal.array()).all()))
        return MakeError(EError::InvalidArgument, "SolveGramPseudoInverse: L is not the factor the inverse was prepared from");
    if (inRhs.rows() != inL.rows())
        return MakeError(EError::InvalidArgument, "SolveGramPseudoInverse: the right-hand side has " + std::to_string(inRhs.rows()) +
                                                      " rows, L has " + std::to_string(inL.rows()));
    if (!inRhs.allFinite())
        return MakeError(EError::NonFinite, "SolveGramPseudoInverse: the right-hand side is not finite");
    // intent: the pseudo-inverse of a zero Gram matrix (rank 0) is zero
    if (r == 0)
        return Result<Eigen::MatrixX3d>(Eigen::MatrixX3d::Zero(inL.rows(), 3));
    const Eigen::Index dependent = inL.rows() - r;
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
    return Result<Eigen::MatrixX3d>(std::move(result));
}

} // namespace crumple::ffd
