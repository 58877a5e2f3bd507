// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "PivotedCholesky.h"

#include <crumple/base/Assert.h>

#include <crumple/ffd/CubicBSplineWeights.h>
#include <crumple/ffd/DirectManipulation.h>

#include <algorithm>
#include <array>

namespace crumple::ffd
{

namespace
{

constexpr int cWeightsPerRow = 64;

using AxisWeights = std::array<std::array<double, 4>, 3>;

AxisWeights WeightsOf(const LatticeLocation& inLocation)
{
    return {CubicBSplineWeights(inLocation.mT.x()), CubicBSplineWeights(inLocation.mT.y()),
            CubicBSplineWeights(inLocation.mT.z())};
}

// One point's 1D weights along an axis, with three zeros on either side: the overlap with a point inOffset
// cells further along is then the same four products whatever the offset.
using PaddedWeights = std::array<double, 10>;

PaddedWeights Padded(const std::array<double, 4>& inWeights)
{
    PaddedWeights padded{};
    std::copy(inWeights.begin(), inWeights.end(), padded.begin() + 3);
    return padded;
}

// Overlap of two points' 1D weights along one axis: sum over the controls both reach of w_i w_j. Point j's
// cell is inOffset cells (-3 to 3) after point i's, so control b of j is control b + inOffset of i. The
// padding adds exact zeros before and after the shared products, in their ascending order, so the sum is
// the one over the shared controls alone, bit for bit.
double AxisOverlap(const PaddedWeights& inWi, const std::array<double, 4>& inWj, int inOffset)
{
    const double* wi = inWi.data() + 3 + inOffset;
    double sum = 0.0;
    for (std::size_t b = 0; b < 4; ++b)
        sum += wi[b] * inWj[b];
    return sum;
}

// The lower triangle of B B^T (its strictly upper part is left unset: PivotedCholesky reads nothing else),
// from the tensor-product structure: each entry is a product of three 1D overlaps.
RowMajorMatrix PointGram(std::span<const LatticeLocation> inLocations)
{
    const auto n = static_cast<Eigen::Index>(inLocations.size());
    std::vector<AxisWeights> weights;
    std::vector<std::array<PaddedWeights, 3>> padded;
    weights.reserve(inLocations.size());
    padded.reserve(inLocations.size());
    for (const LatticeLocation& location : inLocations)
    {
        weights.push_back(WeightsOf(location));
        padded.push_back({Padded(weights.back()[0]), Padded(weights.back()[1]), Padded(weights.back()[2])});
    }
    RowMajorMatrix gram(n, n);
    // intent: row by row (contiguous in memory), the columns up to the diagonal
    for (Eigen::Index i = 0; i < n; ++i)
    {
        const LatticeLocation& li = inLocations[static_cast<std::size_t>(i)];
        const std::array<PaddedWeights, 3>& pi = padded[static_cast<std::size_t>(i)];
        for (Eigen::Index j = 0; j <= i; ++j)
        {
            const LatticeLocation& lj = inLocations[static_cast<std::size_t>(j)];
            // Points four or more cells apart on any axis share no control: test the cells before any weight.
            const int dx = lj.mCell[0] - li.mCell[0], dy = lj.mCell[1] - li.mCell[1], dz = lj.mCell[2] - li.mCell[2];
            if (dx < -3 || dx > 3 || dy < -3 || dy > 3 || dz < -3 || dz > 3)
            {
                gram(i, j) = 0.0;
                continue;
            }
            const AxisWeights& wj = weights[static_cast<std::size_t>(j)];
            double product = 1.0;
            product *= AxisOverlap(pi[0], wj[0], dx);
            product *= AxisOverlap(pi[1], wj[1], dy);
            product *= AxisOverlap(pi[2], wj[2], dz);
            gram(i, j) = product;
        }
    }
    return gram;
}

// B^T Y: scatter each row's weights times its row of Y into the controls.
Eigen::MatrixX3d ApplyTranspose(const DirectManipulationData& inData, const Eigen::MatrixX3d& inY)
{
    Eigen::MatrixX3d result = Eigen::MatrixX3d::Zero(static_cast<Eigen::Index>(inData.mControls.size()), 3);
    for (int row = 0; row < inData.mPointCount; ++row)
    {
        const int* columns = &inData.mRowColumns[static_cast<std::size_t>(row) * cWeightsPerRow];
        const double* weights = &inData.mRowWeights[static_cast<std::size_t>(row) * cWeightsPerRow];
        for (int k = 0; k < cWeightsPerRow; ++k)
            result.row(columns[k]) += weights[k] * inY.row(row);
    }
    return result;
}

// B X: gather each row's weights over the rows of X.
Eigen::MatrixX3d Apply(const DirectManipulationData& inData, const Eigen::MatrixX3d& inX)
{
    Eigen::MatrixX3d result = Eigen::MatrixX3d::Zero(inData.mPointCount, 3);
    for (int row = 0; row < inData.mPointCount; ++row)
    {
        const int* columns = &inData.mRowColumns[static_cast<std::size_t>(row) * cWeightsPerRow];
        const double* weights = &inData.mRowWeights[static_cast<std::size_t>(row) * cWeightsPerRow];
        for (int k = 0; k < cWeightsPerRow; ++k)
            result.row(row) += weights[k] * inX.row(columns[k]);
    }
    return result;
}

// B^+ inRhs through the pivoted Cholesky factor of B B^T, truncated to its first inRank pivots.
Eigen::MatrixX3d GramSolve(const DirectManipulationData& inData, const Eigen::MatrixX3d& inRhs, int inRank)
{
    const auto n = static_cast<Eigen::Index>(inData.mPivots.size());
    Eigen::MatrixX3d permuted(n, 3);
    for (Eigen::Index k = 0; k < n; ++k)
        permuted.row(k) = inRhs.row(inData.mPivots[static_cast<std::size_t>(k)]);

    // Pseudo-inverse of the rank-revealed Gram matrix G ~ L L^T: the prepared one at the factor's rank, else
    // that of L's leading columns (a lower cut, when the tolerance was raised). The factor is this file's own
    // (a positive diagonal, finite) and the right-hand side a residual of finite displacements, so neither
    // is refused; if one were, no control moves rather than some.
    Result<Eigen::MatrixX3d> solved = MakeError(EError::InvalidArgument, "GramSolve: not solved");
    if (inRank == inData.mPseudoInverse.mRank)
        solved = SolveGramPseudoInverse(inData.mPseudoInverse, inData.mL, permuted);
    else if (Result<GramPseudoInverse> lower = PrepareGramPseudoInverse(inData.mL.leftCols(inRank)); lower)
        solved = SolveGramPseudoInverse(lower.Get(), inData.mL.leftCols(inRank), permuted);
    CRUMPLE_ASSERT(solved.IsValid(), "GramSolve: the Gram pseudo-inverse refused the library's own factor");
    if (!solved)
        return Eigen::MatrixX3d::Zero(static_cast<Eigen::Index>(inData.mControls.size()), 3);

    Eigen::MatrixX3d y(n, 3);
    for (Eigen::Index k = 0; k < n; ++k)
        y.row(inData.mPivots[static_cast<std::size_t>(k)]) = solved.Get().row(k);
    // B^+ = B^T (B B^T)^+.
    return ApplyTranspose(inData, y);
}

// Rank of the Gram factor at a relative tolerance: its pivots L_kk^2 do not increase, so the rank is the
// count of those above tau^2 times the first.
int GramRank(const DirectManipulationData& inData, double inTolerance)
{
    const double first = inData.mL(0, 0) * inData.mL(0, 0);
    int rank = 0;
    while (rank < inData.mRank && inData.mL(rank, rank) * inData.mL(rank, rank) > inTolerance * inTolerance * first)
        ++rank;
    return rank;
}

// The tall path at a tolerance: the stored decomposition, or a new one at a raised tolerance.
Eigen::MatrixX3d TallSolve(const DirectManipulationData& inData, const Eigen::MatrixX3d& inRhs, double inTolerance,
                           int& outRank)
{
    if (inTolerance == inData.mTolerance)
    {
        outRank = inData.mRank;
        return inData.mTall.solve(inRhs);
    }
    Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> raised;
    raised.setThreshold(inTolerance);
    raised.compute(Eigen::MatrixXd(DirectManipulationMatrix(inData)));
    outRank = static_cast<int>(raised.rank());
    return raised.solve(inRhs);
}

} // namespace

DirectManipulationData DirectManipulationPrecompute(const FfdLattice& inLattice,
                                                    std::span<const LatticeLocation> inLocations,
                                                    double inRelativeTolerance)
{
    DirectManipulationData data;
    data.mPointCount = static_cast<int>(inLocations.size());

    // Columns: the union of the 64 controls of every point, sorted so that B does not depend on point order.
    // A column map over the whole lattice marks each control once (linear in the points, no sort of 64 per point).
    std::vector<int> row_controls; // each row's controls in (c, b, a) order
    row_controls.reserve(inLocations.size() * cWeightsPerRow);
    std::vector<int> column_of(static_cast<std::size_t>(inLattice.GetControlCount()), -1);
    for (const LatticeLocation& location : inLocations)
        for (int c = 0; c < 4; ++c)
            for (int b = 0; b < 4; ++b)
                for (int a = 0; a < 4; ++a)
                {
                    const int control = inLattice.ControlIndex(location.mCell[0] + a, location.mCell[1] + b,
                                                               location.mCell[2] + c);
                    row_controls.push_back(control);
                    if (column_of[static_cast<std::size_t>(control)] < 0)
                    {
                        column_of[static_cast<std::size_t>(control)] = 0;
                        data.mControls.push_back(control);
                    }
                }
    std::sort(data.mControls.begin(), data.mControls.end());
    for (std::size_t column = 0; column < data.mControls.size(); ++column)
        column_of[static_cast<std::size_t>(data.mControls[column])] = static_cast<int>(column);

    // Rows of B in a fixed 64-per-row layout: tensor-product weights and their columns.
    data.mRowColumns.resize(row_controls.size());
    data.mRowWeights.resize(row_controls.size());
    for (std::size_t row = 0; row < inLocations.size(); ++row)
    {
        const AxisWeights w = WeightsOf(inLocations[row]);
        for (int c = 0; c < 4; ++c)
            for (int b = 0; b < 4; ++b)
                for (int a = 0; a < 4; ++a)
                {
                    const std::size_t entry = row * cWeightsPerRow + static_cast<std::size_t>(a + 4 * (b + 4 * c));
                    data.mRowColumns[entry] = column_of[static_cast<std::size_t>(row_controls[entry])];
                    data.mRowWeights[entry] = w[0][static_cast<std::size_t>(a)] * w[1][static_cast<std::size_t>(b)] *
                                              w[2][static_cast<std::size_t>(c)];
                }
    }
    if (inLocations.empty())
        return data;

    // Tall B (more points than controls): dense rank-revealing decomposition of B itself.
    data.mGramOfPoints = inLocations.size() <= data.mControls.size();
    if (!data.mGramOfPoints)
    {
        data.mTolerance = inRelativeTolerance;
        data.mTall.setThreshold(inRelativeTolerance);
        data.mTall.compute(Eigen::MatrixXd(DirectManipulationMatrix(data)));
        data.mRank = static_cast<int>(data.mTall.rank());
        return data;
    }

    // Wide B: factor B B^T, whose pivots are squared singular values of B.
    const double tolerance = std::max(inRelativeTolerance, cMinRankTolerance);
    data.mTolerance = tolerance;
    PivotedCholeskyFactor factor = PivotedCholesky(PointGram(inLocations), tolerance * tolerance);
    data.mL = std::move(factor.mL);
    data.mPivots = std::move(factor.mPivots);
    data.mRank = factor.mRank;
    // intent: the factor is PivotedCholesky's (positive diagonal, finite for finite weights): never refused;
    // if it were, the solve prepares again at its rank and moves no control
    Result<GramPseudoInverse> prepared = PrepareGramPseudoInverse(data.mL);
    CRUMPLE_ASSERT(prepared.IsValid(), "DirectManipulationPrecompute: the Gram pseudo-inverse refused the factor");
    if (prepared)
        data.mPseudoInverse = std::move(prepared).Get();
    else
        data.mPseudoInverse.mRank = -1;
    return data;
}

Eigen::MatrixX3d QuasiInterpolant(const DirectManipulationData& inData, const Eigen::MatrixX3d& inDisplacements)
{
    Eigen::MatrixX3d sum = ApplyTranspose(inData, inDisplacements);
    Eigen::VectorXd weight = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(inData.mControls.size()));
    for (std::size_t entry = 0; entry < inData.mRowWeights.size(); ++entry)
        weight[inData.mRowColumns[entry]] += inData.mRowWeights[entry];
    for (Eigen::Index k = 0; k < sum.rows(); ++k)
        if (weight[k] > 0.0)
            sum.row(k) /= weight[k];
    return sum;
}

Eigen::MatrixX3d DirectManipulationSolve(const DirectManipulationData& inData, const Eigen::MatrixX3d& inDisplacements,
                                         EDirectManipulationPrior inPrior, double inMaxControlGain,
                                         DirectManipulationSolveInfo* outInfo)
{
    const auto controls = static_cast<Eigen::Index>(inData.mControls.size());
    DirectManipulationSolveInfo info{0, inData.mTolerance};
    Eigen::MatrixX3d result = Eigen::MatrixX3d::Zero(controls, 3);
    if (controls > 0 && inData.mRank > 0)
    {
        // Nearest to the prior: dC = C0 + B^+ (dP - B C0); C0 = 0 for the minimum-norm solve.
        const Eigen::MatrixX3d prior = inPrior == EDirectManipulationPrior::None
                                           ? Eigen::MatrixX3d::Zero(controls, 3)
                                           : QuasiInterpolant(inData, inDisplacements);
        const Eigen::MatrixX3d residual = inDisplacements - Apply(inData, prior);
        const double bound = inMaxControlGain * inDisplacements.rowwise().norm().maxCoeff();
        int previous_rank = -1;
        for (double tolerance = inData.mTolerance;; tolerance *= 3.1622776601683795)
        {
            // intent: one solve per distinct rank, the tolerance raised until the controls respect the bound
            int rank = 0;
            Eigen::MatrixX3d correction;
            if (inData.mGramOfPoints)
            {
                rank = GramRank(inData, std::min(tolerance, 1.0));
                if (rank == previous_rank && tolerance < 1.0)
                    continue;
                correction = GramSolve(inData, residual, std::max(rank, 1));
            }
            else
                correction = TallSolve(inData, residual, std::min(tolerance, 1.0), rank);
            previous_rank = rank;
            result = prior + correction;
            info = {std::max(rank, 1), std::min(tolerance, 1.0)};
            if (!(result.rowwise().norm().maxCoeff() > bound) || rank <= 1 || tolerance >= 1.0)
                break;
        }
    }
    if (outInfo != nullptr)
        *outInfo = info;
    return result;
}

Eigen::SparseMatrix<double, Eigen::RowMajor> DirectManipulationMatrix(const DirectManipulationData& inData)
{
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(inData.mRowWeights.size());
    for (std::size_t entry = 0; entry < inData.mRowWeights.size(); ++entry)
        entries.emplace_back(static_cast<int>(entry / cWeightsPerRow), inData.mRowColumns[entry], inData.mRowWeights[entry]);
    Eigen::SparseMatrix<double, Eigen::RowMajor> b(inData.mPointCount, static_cast<Eigen::Index>(inData.mControls.size()));
    b.setFromTriplets(entries.begin(), entries.end());
    return b;
}

} // namespace crumple::ffd
