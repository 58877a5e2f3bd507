// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/ffd/DirectManipulation.h>
#include <crumple/ffd/GramPseudoInverse.h>

#include "PivotedCholesky.h"
#include "RandomGram.h"

#include <Eigen/SVD>
#include <catch2/catch.hpp>

#include <limits>
#include <random>

using namespace crumple::ffd;

namespace
{

// The pivoted Cholesky factor of a random Gram matrix X X^T of rank r (X #n by r, Gaussian entries): the
// shape and the pivoting (|L_ij| <= L_jj) of the factors the direct-manipulation solve hands over.
Eigen::MatrixXd RandomFactor(int inRows, int inRank, std::mt19937_64& ioRandom)
{
    PivotedCholeskyFactor factor = PivotedCholesky(crumple::ffd::test::RandomGram(inRows, inRank, ioRandom), 1.0e-12);
    REQUIRE(factor.mRank == inRank);
    return factor.mL;
}

Eigen::MatrixX3d RandomRhs(int inRows, std::mt19937_64& ioRandom)
{
    std::uniform_real_distribution<double> entry(-1.0, 1.0);
    Eigen::MatrixX3d rhs(inRows, 3);
    for (int i = 0; i < inRows; ++i)
        for (int j = 0; j < 3; ++j)
            rhs(i, j) = entry(ioRandom);
    return rhs;
}

} // namespace

TEST_CASE("The Gram pseudo-inverse equals an SVD pseudo-inverse of L L^T at full and cut rank", "[ffd]")
{
    // Both coupling forms (fewer dependent rows than independent ones and more), full rank, rank one.
    std::mt19937_64 random(5);
    const std::vector<std::pair<int, int>> shapes{{40, 40}, {40, 30}, {40, 10}, {40, 1}, {7, 6}, {7, 2}, {263, 185}};
    bool saw_dependents = false, saw_independents = false;
    for (const auto& [rows, rank] : shapes)
    {
        const Eigen::MatrixXd l = RandomFactor(rows, rank, random);
        const Eigen::MatrixX3d rhs = RandomRhs(rows, random);
        const GramPseudoInverse inverse = PrepareGramPseudoInverse(l).Get();
        const Eigen::MatrixX3d solved = SolveGramPseudoInverse(inverse, l, rhs).Get();

        // An independent computation: the SVD of the Gram matrix itself, cut at its exact rank.
        const Eigen::MatrixXd gram = l * l.transpose();
        Eigen::BDCSVD<Eigen::MatrixXd> svd(gram, Eigen::ComputeFullU | Eigen::ComputeFullV);
        Eigen::MatrixXd pinv = Eigen::MatrixXd::Zero(rows, rows);
        for (int k = 0; k < rank; ++k)
            pinv += svd.matrixV().col(k) * svd.matrixU().col(k).transpose() / svd.singularValues()(k);
        const Eigen::MatrixX3d reference = pinv * rhs;
        const double condition = svd.singularValues()(0) / svd.singularValues()(rank - 1);
        INFO(rows << " rows, rank " << rank << ", cond " << condition);
        // Two backward-stable solves of a system of condition c agree to about c times the rounding unit.
        CHECK((solved - reference).norm() <= 1.0e-13 * condition * reference.norm());
        // The Moore-Penrose conditions that matter to a solve: the answer lies in the range of G (it is G's
        // minimum-norm least-squares solution), and G times it is the rhs projected onto that range.
        const Eigen::MatrixXd range = svd.matrixU().leftCols(rank);
        CHECK((solved - range * (range.transpose() * solved)).norm() <= 1.0e-13 * condition * solved.norm());
        CHECK((gram * solved - range * (range.transpose() * rhs)).norm() <= 1.0e-13 * condition * rhs.norm());
        (inverse.mCouplingOfDependents ? saw_dependents : saw_independents) |= rank < rows;
    }
    CHECK(saw_dependents);
    CHECK(saw_independents);
}

TEST_CASE("The direct-manipulation factor of clustered points on a face has the SVD pseudo-inverse", "[ffd]")
{
    // As a dent's points: on one lattice plane (a car's front face), in pairs a few millimetres apart, on a
    // fine lattice; the factor is cut well below #points and its dependent rows are close to independent ones.
    crumple::ffd::FfdLatticeSettings settings;
    settings.mSize = crumple::Vec3(4.2, 1.8, 1.4);
    settings.mControlCount = {16, 16, 16};
    const FfdLattice lattice = FfdLattice::Create(settings).Get();
    std::mt19937_64 random(9);
    std::uniform_real_distribution<double> y(0.0, 13.0), z(0.0, 13.0), jitter(-0.02, 0.02);
    std::vector<LatticeLocation> locations;
    for (int i = 0; i < 130; ++i)
    {
        const double a = y(random), b = z(random);
        locations.push_back(lattice.Locate(crumple::Vec3(12.5, a, b)));
        // sequenced, last argument first (common::DrawVec3)
        const double near_b = b + jitter(random), near_a = a + jitter(random);
        locations.push_back(lattice.Locate(crumple::Vec3(12.5, near_a, near_b)));
    }
    const DirectManipulationData data = DirectManipulationPrecompute(lattice, locations);
    REQUIRE(data.mGramOfPoints);
    const int rows = static_cast<int>(locations.size());
    INFO("rank " << data.mRank << " of " << rows);
    REQUIRE(data.mRank < rows);
    REQUIRE(data.mRank > rows / 4);

    const Eigen::MatrixX3d rhs = RandomRhs(rows, random);
    const Eigen::MatrixX3d solved = SolveGramPseudoInverse(data.mPseudoInverse, data.mL, rhs).Get();
    const Eigen::MatrixXd gram = data.mL * data.mL.transpose();
    Eigen::BDCSVD<Eigen::MatrixXd> svd(gram, Eigen::ComputeFullU | Eigen::ComputeFullV);
    Eigen::MatrixXd pinv = Eigen::MatrixXd::Zero(rows, rows);
    for (int k = 0; k < data.mRank; ++k)
        pinv += svd.matrixV().col(k) * svd.matrixU().col(k).transpose() / svd.singularValues()(k);
    const double condition = svd.singularValues()(0) / svd.singularValues()(data.mRank - 1);
    INFO("cond " << condition);
    CHECK((solved - pinv * rhs).norm() <= 1.0e-13 * condition * (pinv * rhs).norm());
}

TEST_CASE("The Gram pseudo-inverse refuses what is not a factor, and a solve with another factor", "[ffd]")
{
    std::mt19937_64 random(13);
    const Eigen::MatrixXd l = RandomFactor(12, 7, random);
    const Eigen::MatrixX3d rhs = RandomRhs(12, random);
    const GramPseudoInverse inverse = PrepareGramPseudoInverse(l).Get();
    REQUIRE(SolveGramPseudoInverse(inverse, l, rhs));

    SECTION("rank 0: the pseudo-inverse of a zero Gram matrix is zero")
    {
        const Eigen::MatrixXd empty(12, 0);
        const GramPseudoInverse zero = PrepareGramPseudoInverse(empty).Get();
        CHECK(SolveGramPseudoInverse(zero, empty, rhs).Get() == Eigen::MatrixX3d::Zero(12, 3));
    }
    SECTION("more columns than rows")
    {
        CHECK(PrepareGramPseudoInverse(Eigen::MatrixXd(l.transpose())).GetError().mCode == crumple::EError::InvalidArgument);
    }
    SECTION("a NaN or a zero anywhere on the diagonal, not only the first entry")
    {
        for (const double bad : {std::numeric_limits<double>::quiet_NaN(), 0.0, -1.0})
            for (const Eigen::Index k : {Eigen::Index{0}, Eigen::Index{3}, Eigen::Index{6}})
            {
                Eigen::MatrixXd broken = l;
                broken(k, k) = bad;
                INFO("diagonal entry " << k << " = " << bad);
                CHECK(PrepareGramPseudoInverse(broken).HasError());
            }
    }
    SECTION("a value that is not finite below the diagonal; above it nothing is read")
    {
        Eigen::MatrixXd broken = l;
        broken(10, 2) = std::numeric_limits<double>::infinity();
        CHECK(PrepareGramPseudoInverse(broken).GetError().mCode == crumple::EError::NonFinite);
        Eigen::MatrixXd upper = l;
        upper(1, 4) = std::numeric_limits<double>::quiet_NaN(); // above the diagonal: not part of the factor
        CHECK(PrepareGramPseudoInverse(upper));
    }
    SECTION("a solve with a factor of another shape or diagonal, or a right-hand side of other rows or not finite")
    {
        CHECK(SolveGramPseudoInverse(inverse, l.leftCols(6), rhs).GetError().mCode == crumple::EError::InvalidArgument);
        CHECK(SolveGramPseudoInverse(inverse, l.topRows(11), rhs.topRows(11)).GetError().mCode == crumple::EError::InvalidArgument);
        Eigen::MatrixXd other = l;
        other(5, 5) *= 1.0 + 1.0e-15;
        CHECK(SolveGramPseudoInverse(inverse, other, rhs).GetError().mCode == crumple::EError::InvalidArgument);
        CHECK(SolveGramPseudoInverse(inverse, l, rhs.topRows(11)).GetError().mCode == crumple::EError::InvalidArgument);
        Eigen::MatrixX3d nan_rhs = rhs;
        nan_rhs(4, 1) = std::numeric_limits<double>::quiet_NaN();
        CHECK(SolveGramPseudoInverse(inverse, l, nan_rhs).GetError().mCode == crumple::EError::NonFinite);
    }
}
