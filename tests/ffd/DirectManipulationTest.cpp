// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/ffd/DirectManipulation.h>

#include <Eigen/Cholesky>
#include <catch2/catch.hpp>

#include <cmath>
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
        locations.push_back(inLattice.Locate(Vec3(unit(ioRandom) * cells[0], unit(ioRandom) * cells[1], unit(ioRandom) * cells[2])));
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
    const Eigen::MatrixXd gram = data.mB * data.mB.transpose();
    const Eigen::MatrixX3d reference = data.mB.transpose() * gram.ldlt().solve(wanted);
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

    // Optimality: the residual is orthogonal to the columns of B (normal equations).
    const Eigen::MatrixX3d gradient = data.mB.transpose() * (data.mB * delta - wanted);
    const double scale = (data.mB.transpose() * wanted).norm();
    CHECK(gradient.norm() <= 1.0e-9 * scale);
    // No other solution is better: perturbing it increases the residual.
    const double best = (data.mB * delta - wanted).norm();
    std::uniform_real_distribution<double> tiny(-1.0e-3, 1.0e-3);
    for (int trial = 0; trial < 20; ++trial)
    {
        Eigen::MatrixX3d other = delta;
        for (Eigen::Index k = 0; k < other.size(); ++k)
            other.data()[k] += tiny(random);
        CHECK((data.mB * other - wanted).norm() >= best);
    }

    // The default tolerance drops weak directions: never better than the optimum, with smaller controls
    // (these targets are random noise, the worst case for dropping directions: 8.6 % more residual here).
    const DirectManipulationData regularized = DirectManipulationPrecompute(lattice, locations);
    const Eigen::MatrixX3d bounded = DirectManipulationSolve(regularized, wanted);
    const double residual = (regularized.mB * bounded - wanted).norm();
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
