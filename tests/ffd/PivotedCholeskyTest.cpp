// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// White-box: the blocked pivoted Cholesky against its definition and an unblocked reference.
#include "PivotedCholesky.h"
#include "RandomGram.h"

#include <catch2/catch.hpp>

#include <random>

using namespace crumple::ffd;
using crumple::ffd::test::RandomGram;

namespace
{

// The textbook algorithm (Higham, section 10.3), unblocked: the oracle for the pivot order.
std::vector<int> ReferencePivots(Eigen::MatrixXd inG, double inRelativeThreshold, int& outRank)
{
    const Eigen::Index n = inG.rows();
    std::vector<int> pivots(static_cast<std::size_t>(n));
    for (Eigen::Index i = 0; i < n; ++i)
        pivots[static_cast<std::size_t>(i)] = static_cast<int>(i);
    const double stop = inRelativeThreshold * inG.diagonal().maxCoeff();
    Eigen::Index k = 0;
    for (; k < n; ++k)
    {
        Eigen::Index best = k;
        for (Eigen::Index i = k + 1; i < n; ++i)
            if (inG(i, i) > inG(best, best))
                best = i;
        if (!(inG(best, best) > stop))
            break;
        inG.row(k).swap(inG.row(best));
        inG.col(k).swap(inG.col(best));
        std::swap(pivots[static_cast<std::size_t>(k)], pivots[static_cast<std::size_t>(best)]);
        // Schur complement of the pivot, in full.
        const Eigen::VectorXd column = inG.col(k).tail(n - k - 1) / std::sqrt(inG(k, k));
        inG.bottomRightCorner(n - k - 1, n - k - 1) -= column * column.transpose();
    }
    outRank = static_cast<int>(k);
    return pivots;
}

} // namespace

TEST_CASE("Pivoted Cholesky: blocked factor reproduces the matrix, the reference pivots and the rank", "[ffd]")
{
    std::mt19937_64 random(13);
    // Sizes across the panel width (32): one panel, several, a partial last one; full rank and rank-deficient.
    const std::vector<std::pair<int, int>> shapes{{1, 1}, {5, 5}, {31, 31}, {32, 32}, {33, 20}, {70, 70},
                                                  {70, 45}, {100, 64}, {150, 97}, {263, 185}};
    for (const auto& [rows, rank] : shapes)
    {
        const Eigen::MatrixXd g = RandomGram(rows, rank, random);
        const double threshold = 1.0e-12;
        const PivotedCholeskyFactor factor = PivotedCholesky(g, threshold);
        int reference_rank = 0;
        const std::vector<int> reference = ReferencePivots(g, threshold, reference_rank);
        INFO(rows << " rows, rank " << rank);
        CHECK(factor.mRank == rank);
        CHECK(reference_rank == rank);
        CHECK(factor.mPivots == reference);
        REQUIRE(factor.mL.rows() == rows);
        REQUIRE(factor.mL.cols() == factor.mRank);

        // P G P^T = L L^T, to the rounding of a backward-stable factorization.
        Eigen::MatrixXd permuted(rows, rows);
        for (int i = 0; i < rows; ++i)
            for (int j = 0; j < rows; ++j)
                permuted(i, j) = g(factor.mPivots[static_cast<std::size_t>(i)], factor.mPivots[static_cast<std::size_t>(j)]);
        CHECK((permuted - factor.mL * factor.mL.transpose()).norm() <= 1.0e-12 * g.norm());

        // Lower trapezoidal, the diagonal non-increasing, no entry above its column's pivot (complete pivoting).
        for (int j = 0; j < factor.mRank; ++j)
        {
            for (int i = 0; i < j; ++i)
                CHECK(factor.mL(i, j) == 0.0);
            if (j > 0)
                CHECK(factor.mL(j, j) <= factor.mL(j - 1, j - 1) * (1.0 + 1.0e-12));
            for (int i = j + 1; i < rows; ++i)
                CHECK(std::abs(factor.mL(i, j)) <= factor.mL(j, j) * (1.0 + 1.0e-12));
        }
    }
}

TEST_CASE("Pivoted Cholesky stops at the relative threshold", "[ffd]")
{
    // A diagonal matrix: the pivots are its entries in decreasing order; those at or below the threshold
    // times the largest are left out, whatever panel they fall in.
    Eigen::MatrixXd g = Eigen::MatrixXd::Zero(80, 80);
    for (int i = 0; i < 80; ++i)
        g(i, i) = std::pow(0.5, (i * 37) % 80);
    const PivotedCholeskyFactor factor = PivotedCholesky(g, std::pow(0.5, 40));
    CHECK(factor.mRank == 40);
    for (int k = 0; k < factor.mRank; ++k)
        CHECK(factor.mL(k, k) == std::sqrt(std::pow(0.5, k)));
    CHECK(PivotedCholesky(Eigen::MatrixXd::Zero(4, 4), 1.0e-6).mRank == 0);
    CHECK(PivotedCholesky(RowMajorMatrix(0, 0), 1.0e-6).mRank == 0);
}
