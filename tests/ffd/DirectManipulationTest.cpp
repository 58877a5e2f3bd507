// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/ffd/DirectManipulation.h>

#include "DrawVec3.h"

#include <Eigen/Cholesky>
#include <Eigen/SVD>
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>

using namespace crumple;
using namespace crumple::ffd;

namespace
{

FfdLattice MakeLattice(int inControls)
{
    FfdLatticeSettings settings;
    settings.mSize = Vec3(2.0, 1.0, 1.0);
    settings.mControlCount = {inControls, inControls, inControls};
    return FfdLattice::Create(settings).Get();
}

std::vector<LatticeLocation> RandomLocations(const FfdLattice& inLattice, int inCount, std::mt19937_64& ioRandom)
{
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<LatticeLocation> locations;
    const auto& cells = inLattice.GetCellCount();
    for (int i = 0; i < inCount; ++i)
    {
        const Vec3 u = common::DrawVec3([&] { return unit(ioRandom); });
        locations.push_back(inLattice.Locate(Vec3(u.x() * cells[0], u.y() * cells[1], u.z() * cells[2])));
    }
    return locations;
}

Eigen::MatrixX3d RandomDisplacements(int inCount, std::mt19937_64& ioRandom)
{
    std::uniform_real_distribution<double> range(-0.05, 0.05);
    Eigen::MatrixX3d d(inCount, 3);
    for (int i = 0; i < inCount; ++i)
        for (int j = 0; j < 3; ++j)
            d(i, j) = range(ioRandom);
    return d;
}

// Applies a solve to the lattice, so that the check goes through FfdLattice::Displacement, not through B.
void Apply(FfdLattice& ioLattice, const DirectManipulationData& inData, const Eigen::MatrixX3d& inControlDelta)
{
    for (std::size_t k = 0; k < inData.mControls.size(); ++k)
        ioLattice.GetControlDisplacements()[static_cast<std::size_t>(inData.mControls[k])] +=
            inControlDelta.row(static_cast<Eigen::Index>(k)).transpose();
}

} // namespace

TEST_CASE("Direct manipulation moves every point exactly when underdetermined", "[ffd]")
{
    std::mt19937_64 random(11);
    FfdLattice lattice = MakeLattice(10);
    // Spread points: one per distinct cell keeps B full row rank.
    std::vector<LatticeLocation> locations;
    for (int i = 0; i < 7; ++i)
    {
        LatticeLocation location;
        location.mCell = {i, (i * 3) % 7, (i * 5) % 7};
        location.mT = Vec3(0.2 + 0.1 * i, 0.7 - 0.05 * i, 0.5);
        locations.push_back(location);
    }
    const Eigen::MatrixX3d wanted = RandomDisplacements(7, random);
    const DirectManipulationData data = DirectManipulationPrecompute(lattice, locations);
    CHECK(data.mRank == 7);
    const Eigen::MatrixX3d delta = DirectManipulationSolve(data, wanted);
    Apply(lattice, data, delta);
    for (std::size_t i = 0; i < locations.size(); ++i)
    {
        const Vec3 target = wanted.row(static_cast<Eigen::Index>(i)).transpose();
        CHECK((lattice.Displacement(locations[i]) - target).norm() <= 1.0e-9 * target.norm());
    }

    // Minimum norm: the solution equals B^T (B B^T)^-1 dP, computed independently.
    const Eigen::MatrixXd b = DirectManipulationMatrix(data);
    const Eigen::MatrixXd gram = b * b.transpose();
    const Eigen::MatrixX3d reference = b.transpose() * gram.ldlt().solve(wanted);
    CHECK((delta - reference).norm() <= 1.0e-9 * reference.norm());
}

TEST_CASE("Direct manipulation is the least-squares optimum when overdetermined", "[ffd]")
{
    std::mt19937_64 random(12);
    const FfdLattice lattice = MakeLattice(4); // one cell, 64 controls
    const std::vector<LatticeLocation> locations = RandomLocations(lattice, 200, random);
    const Eigen::MatrixX3d wanted = RandomDisplacements(200, random);
    // A tolerance that drops no pivot: the kernel then is the exact least-squares solver.
    const DirectManipulationData data = DirectManipulationPrecompute(lattice, locations, 1.0e-12);
    REQUIRE(data.mControls.size() == 64);
    REQUIRE(data.mRank == 64);
    const Eigen::MatrixX3d delta = DirectManipulationSolve(data, wanted);
    const Eigen::MatrixXd b = DirectManipulationMatrix(data);

    // Optimality: the residual is orthogonal to the columns of B (normal equations).
    const Eigen::MatrixX3d gradient = b.transpose() * (b * delta - wanted);
    const double scale = (b.transpose() * wanted).norm();
    CHECK(gradient.norm() <= 1.0e-9 * scale);
    // No other solution is better: perturbing it increases the residual.
    const double best = (b * delta - wanted).norm();
    std::uniform_real_distribution<double> tiny(-1.0e-3, 1.0e-3);
    for (int trial = 0; trial < 20; ++trial)
    {
        Eigen::MatrixX3d other = delta;
        for (Eigen::Index k = 0; k < other.size(); ++k)
            other.data()[k] += tiny(random);
        CHECK((b * other - wanted).norm() >= best);
    }

    // The default tolerance drops weak directions: never better than the optimum, with smaller controls
    // (these targets are random noise, the worst case for dropping directions: 8.6 % more residual here).
    const DirectManipulationData regularized = DirectManipulationPrecompute(lattice, locations);
    const Eigen::MatrixX3d bounded = DirectManipulationSolve(regularized, wanted);
    const double residual = (b * bounded - wanted).norm();
    INFO("rank " << regularized.mRank << ", residual " << residual << " vs optimum " << best);
    CHECK(regularized.mRank < 64);
    CHECK(residual >= best * (1.0 - 1.0e-12));
    CHECK(bounded.norm() <= delta.norm());
}

TEST_CASE("Coincident constrained points do not blow up", "[ffd]")
{
    FfdLattice lattice = MakeLattice(6);
    LatticeLocation location;
    location.mCell = {1, 1, 1};
    location.mT = Vec3(0.3, 0.4, 0.5);
    const std::vector<LatticeLocation> locations(5, location);
    Eigen::MatrixX3d wanted(5, 3);
    for (int i = 0; i < 5; ++i)
        wanted.row(i) = Eigen::RowVector3d(0.01 * i, 0.0, -0.02);
    const DirectManipulationData data = DirectManipulationPrecompute(lattice, locations);
    CHECK(data.mRank == 1);
    const Eigen::MatrixX3d delta = DirectManipulationSolve(data, wanted);
    REQUIRE(delta.allFinite());
    Apply(lattice, data, delta);
    // The least-squares answer for one point wanted five ways is their mean.
    const Vec3 mean = wanted.colwise().mean().transpose();
    CHECK((lattice.Displacement(location) - mean).norm() <= 1.0e-12);
}

TEST_CASE("Collinear constrained points give a bounded minimum-norm answer", "[ffd]")
{
    FfdLattice lattice = MakeLattice(8);
    std::vector<LatticeLocation> locations;
    Eigen::MatrixX3d wanted(40, 3);
    for (int i = 0; i < 40; ++i)
    {
        // A dense line of points along x (many more than the controls can tell apart along y and z).
        locations.push_back(lattice.Locate(Vec3(0.1 + 4.8 * i / 39.0, 2.5, 2.5)));
        wanted.row(i) = Eigen::RowVector3d(0.0, 0.0, -0.03);
    }
    const DirectManipulationData data = DirectManipulationPrecompute(lattice, locations);
    CHECK(data.mRank < static_cast<int>(locations.size()));
    const Eigen::MatrixX3d delta = DirectManipulationSolve(data, wanted);
    REQUIRE(delta.allFinite());
    // Moving every reached control by the same push is one exact solution; the minimum-norm one is no larger.
    const double uniform_norm = 0.03 * std::sqrt(static_cast<double>(data.mControls.size()));
    CHECK(delta.norm() <= uniform_norm * (1.0 + 1.0e-9));
    Apply(lattice, data, delta);
    for (const LatticeLocation& location : locations)
        CHECK((lattice.Displacement(location) - Vec3(0.0, 0.0, -0.03)).norm() <= 1.0e-9);
}

TEST_CASE("The Gram solve equals a dense SVD pseudo-inverse on random sets", "[ffd]")
{
    // Random lattices and point sets on both sides of #points = #controls; where the tolerance drops no
    // direction, B^+ is unique, and the dense SVD of B is an independent computation of it.
    std::mt19937_64 random(21);
    std::uniform_int_distribution<int> controls(4, 14);
    int compared_under = 0, compared_over = 0, compared_solutions = 0;
    for (int trial = 0; trial < 40; ++trial)
    {
        FfdLattice lattice = MakeLattice(controls(random));
        const bool over = trial % 2 == 1;
        const int count = over ? 80 + trial : 3 + trial;
        std::vector<LatticeLocation> locations;
        if (over)
        {
            // Many points in one cell: more rows than the 64 columns they reach.
            std::uniform_real_distribution<double> unit(0.0, 1.0);
            for (int i = 0; i < count; ++i)
                locations.push_back(lattice.Locate(common::DrawVec3([&] { return unit(random); })));
        }
        else
            locations = RandomLocations(lattice, count, random);
        const Eigen::MatrixX3d wanted = RandomDisplacements(count, random);
        const DirectManipulationData data = DirectManipulationPrecompute(lattice, locations, over ? 1.0e-12 : 1.0e-6);
        const int full = std::min<int>(count, static_cast<int>(data.mControls.size()));
        if (data.mRank < full)
            continue; // truncated: the two decompositions may drop different directions
        REQUIRE(data.mGramOfPoints == !over);

        const Eigen::MatrixXd b = DirectManipulationMatrix(data);
        const Eigen::BDCSVD<Eigen::MatrixXd> svd(b, Eigen::ComputeThinU | Eigen::ComputeThinV);
        // Two correct least-squares solvers agree only to about cond(B)^2 times the rounding unit (Golub & Van
        // Loan 5.3.8): beyond cond 1e3 that bound passes 1e-9, and which one is nearer the exact answer depends
        // on the compiler (clang's rounding differed from gcc's by 3e-3 at a cond of about 1e7).
        // The residuals agree to the rounding unit whatever the conditioning: compare them always.
        const double condition = svd.singularValues()(0) / svd.singularValues()(svd.singularValues().size() - 1);
        const bool well_conditioned = condition <= 1.0e3;
        (over ? compared_over : compared_under) += 1;
        compared_solutions += well_conditioned ? 1 : 0;
        for (EDirectManipulationPrior prior : {EDirectManipulationPrior::None, EDirectManipulationPrior::QuasiInterpolant})
        {
            const Eigen::MatrixX3d start = prior == EDirectManipulationPrior::None
                                               ? Eigen::MatrixX3d::Zero(b.cols(), 3)
                                               : Eigen::MatrixX3d(QuasiInterpolant(data, wanted));
            const Eigen::MatrixX3d reference = start + svd.solve(Eigen::MatrixX3d(wanted - b * start));
            const Eigen::MatrixX3d delta = DirectManipulationSolve(data, wanted, prior);
            INFO("trial " << trial << " points " << count << " controls " << data.mControls.size() << " cond " << condition);
            CHECK(std::abs((b * delta - wanted).norm() - (b * reference - wanted).norm()) <= 1.0e-9 * wanted.norm());
            if (well_conditioned)
                CHECK((delta - reference).norm() <= 1.0e-9 * reference.norm());
        }
    }
    // The comparison must have happened on both sides.
    INFO("compared " << compared_under << " underdetermined and " << compared_over << " overdetermined sets");
    CHECK(compared_under >= 10);
    CHECK(compared_over >= 10);
    CHECK(compared_solutions >= 10);
}

TEST_CASE("A flat push on part of a face moves no control further than the push", "[ffd]")
{
    // A 5 x 4 patch of points on the x = 0.8 face of a 2 x 1 x 1 box pushed 5 cm inwards: the pure minimum-norm
    // solve asks controls for more than the push; the quasi-interpolant prior meets it exactly with none.
    FfdLattice lattice = MakeLattice(12);
    std::vector<LatticeLocation> locations;
    for (int j = 0; j < 5; ++j)
        for (int k = 0; k < 4; ++k)
            locations.push_back(lattice.Locate(lattice.LatticeCoordinate(Vec3(1.6, 0.3 + 0.1 * j, 0.35 + 0.1 * k))));
    const Eigen::MatrixX3d wanted = Eigen::RowVector3d(-0.05, 0.0, 0.0).replicate(20, 1);
    const DirectManipulationData data = DirectManipulationPrecompute(lattice, locations);

    const Eigen::MatrixX3d minimum_norm = DirectManipulationSolve(data, wanted, EDirectManipulationPrior::None);
    const Eigen::MatrixX3d nearest = DirectManipulationSolve(data, wanted, EDirectManipulationPrior::QuasiInterpolant);
    const double deepest = 0.05;
    INFO("largest control: minimum norm " << minimum_norm.rowwise().norm().maxCoeff() << ", with prior "
                                          << nearest.rowwise().norm().maxCoeff());
    CHECK(minimum_norm.rowwise().norm().maxCoeff() > deepest * 1.05); // the overshoot this prior removes
    CHECK(nearest.rowwise().norm().maxCoeff() <= deepest * (1.0 + 1.0e-12));

    // And it is exact at every point, checked through the lattice.
    Apply(lattice, data, nearest);
    for (const LatticeLocation& location : locations)
        CHECK((lattice.Displacement(location) - Vec3(-0.05, 0.0, 0.0)).norm() <= 1.0e-12);
}

TEST_CASE("Targets that disagree between close points cannot drive controls past the gain bound", "[ffd]")
{
    // Neighbouring points a fifth of a cell apart asking for opposite pushes: met only through weak
    // directions of B, so the unbounded solve asks for controls far larger than any target.
    FfdLattice lattice = MakeLattice(12);
    std::vector<LatticeLocation> locations;
    Eigen::MatrixX3d wanted(24, 3);
    for (int i = 0; i < 24; ++i)
    {
        locations.push_back(lattice.Locate(Vec3(4.5 + 0.2 * (i % 2), 2.0 + 0.3 * (i / 2), 4.5)));
        wanted.row(i) = Eigen::RowVector3d(i % 2 == 0 ? -0.05 : 0.05, 0.0, 0.0);
    }
    const DirectManipulationData data = DirectManipulationPrecompute(lattice, locations);
    DirectManipulationSolveInfo unbounded_info, bounded_info;
    const Eigen::MatrixX3d unbounded = DirectManipulationSolve(data, wanted, EDirectManipulationPrior::QuasiInterpolant,
                                                               std::numeric_limits<double>::infinity(), &unbounded_info);
    const Eigen::MatrixX3d bounded =
        DirectManipulationSolve(data, wanted, EDirectManipulationPrior::QuasiInterpolant, 2.0, &bounded_info);
    INFO("unbounded " << unbounded.rowwise().norm().maxCoeff() << " at rank " << unbounded_info.mRank << ", bounded "
                      << bounded.rowwise().norm().maxCoeff() << " at rank " << bounded_info.mRank << " tolerance "
                      << bounded_info.mTolerance);
    REQUIRE(unbounded.rowwise().norm().maxCoeff() > 2.0 * 0.05); // the blow-up the bound is for
    CHECK(bounded.rowwise().norm().maxCoeff() <= 2.0 * 0.05);
    CHECK(bounded_info.mTolerance > data.mTolerance);
    CHECK(bounded_info.mRank < unbounded_info.mRank);
    CHECK(unbounded_info.mTolerance == data.mTolerance);
}
