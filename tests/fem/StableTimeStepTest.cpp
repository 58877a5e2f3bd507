// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/StableTimeStep.h>
#include <crumple/fem/TetGrid.h>
#include <crumple/fem/TetSolver.h>

#include <catch2/catch.hpp>

#include <Eigen/Eigenvalues>

using namespace crumple;
using namespace crumple::fem;

namespace
{

// The largest eigenfrequency omega_max (rad/s) of M^-1 K at rest, K assembled column by column from the
// elastic forces of tiny displacements (exactly linear for the corotated model near rest).
double LargestEigenfrequency(TetSolver& ioSolver)
{
    const std::vector<Vec3> rest = ioSolver.GetMesh().GetRestPositions();
    const int dofs = 3 * ioSolver.GetMesh().GetNodeCount();
    const double epsilon = 1.0e-7;
    Eigen::MatrixXd k(dofs, dofs);
    std::vector<Vec3> forces;
    for (int column = 0; column < dofs; ++column)
    {
        std::vector<Vec3> moved = rest;
        moved[column / 3][column % 3] += epsilon;
        REQUIRE(ioSolver.SetPositions(moved).IsValid());
        ioSolver.ElasticForces(forces);
        for (int row = 0; row < dofs; ++row)
            k(row, column) = -forces[row / 3][row % 3] / epsilon;
    }
    REQUIRE(ioSolver.SetPositions(rest).IsValid());

    // Symmetric scaling M^-1/2 K M^-1/2 with the lumped masses.
    Eigen::VectorXd inverse_root(dofs);
    for (int row = 0; row < dofs; ++row)
        inverse_root[row] = 1.0 / std::sqrt(ioSolver.GetMasses()[row / 3]);
    const Eigen::MatrixXd scaled =
        inverse_root.asDiagonal() * (0.5 * (k + k.transpose())) * inverse_root.asDiagonal();
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(scaled, Eigen::EigenvaluesOnly);
    return std::sqrt(eigen.eigenvalues().maxCoeff());
}

} // namespace

TEST_CASE("StableTimeStep is a proven bound, not far from the true limit", "[fem]")
{
    for (ECubeSplit split : {ECubeSplit::Five, ECubeSplit::Six})
        for (double poisson : {0.0, 0.3, 0.45})
        {
            TetGridSettings grid;
            grid.mSize = Vec3(0.3, 0.2, 0.1);
            grid.mCellCount = {3, 2, 1};
            grid.mSplit = split;
            FemMaterialSettings material;
            material.mYoungsModulus = 1.0e9;
            material.mPoissonRatio = poisson;
            material.mDensity = 1000.0;
            TetSolverSettings settings;
            settings.mStabilitySafetyFactor = 1.0;
            TetSolver solver = TetSolver::Create(TetGrid(grid).Get(), material, settings).Get();

            // Symplectic Euler is stable below 2 / omega_max; the bound must not exceed that.
            const double omega = LargestEigenfrequency(solver);
            const double bound = solver.GetStableTimeStep();
            const double exact = 2.0 / omega;
            WARN((split == ECubeSplit::Five ? "five" : "six")
                 << "-tet, nu " << poisson << ": bound " << bound << " s, exact limit 2/omega_max " << exact
                 << " s, ratio " << bound / exact);
            CHECK(bound <= exact);
            CHECK(bound >= 0.3 * exact); // conservative, but not absurdly
        }
}

TEST_CASE("Explicit Euler beyond the limit blows up (the paper's instability), the solver's sub-steps do not",
          "[fem]")
{
    TetGridSettings grid;
    grid.mSize = Vec3(0.3, 0.2, 0.1);
    grid.mCellCount = {3, 2, 1};
    FemMaterialSettings material;
    material.mYoungsModulus = 1.0e9;
    TetSolverSettings settings;
    settings.mGravity = Vec3::Zero();
    settings.mIntegrator = EIntegrator::SymplecticEuler;
    TetSolver solver = TetSolver::Create(TetGrid(grid).Get(), material, settings).Get();
    REQUIRE(solver.ApplyImpulse(5, Vec3(0.0, 0.0, 0.1)).IsValid());

    // Hand-rolled explicit Euler with 3x the proven stable sub-step (the paper's fixed-step scheme): energy
    // explodes.
    {
        const double dt = 3.0 * solver.GetStableTimeStep() / settings.mStabilitySafetyFactor;
        std::vector<Vec3> x = solver.GetPositions(), v = solver.GetVelocities(), forces;
        TetSolver probe = solver;
        bool beyond_bound = false; // past what a solver takes (TetSolver::cMaxStateMagnitude): blown up
        for (int step = 0; step < 200 && !beyond_bound; ++step)
        {
            if (const Status set = probe.SetPositions(x); set.HasError())
            {
                REQUIRE((set.GetError().mCode == EError::OutOfRange || set.GetError().mCode == EError::NonFinite));
                WARN("fixed-step explicit Euler at 3x the bound: positions past 1e100 m after " << step << " steps");
                beyond_bound = true;
                break;
            }
            probe.ElasticForces(forces);
            for (std::size_t node = 0; node < x.size(); ++node)
            {
                v[node] += dt * probe.GetInverseMasses()[node] * forces[node];
                x[node] += dt * v[node];
            }
        }
        if (!beyond_bound)
        {
            REQUIRE(probe.SetPositions(x).IsValid());
            REQUIRE(probe.SetVelocities(v).IsValid());
            const double energy = probe.TotalEnergy();
            WARN("fixed-step explicit Euler at 3x the bound: energy " << solver.TotalEnergy() << " J -> "
                                                                      << energy << " J after 200 steps");
            CHECK(!(energy < 1.0e3 * solver.TotalEnergy())); // blown up (or already non-finite)
        }
    }

    // The solver at any requested step: sub-stepped, energy conserved to a few percent, never diverged.
    const double initial = solver.TotalEnergy();
    for (int step = 0; step < 20; ++step)
    {
        Result<TetStepResult> result = solver.Step(1.0 / 60.0);
        REQUIRE(result.IsValid());
        CHECK(result.Get().mEvents == ETetStepEvent::None);
    }
    CHECK(std::abs(solver.TotalEnergy() - initial) < 0.05 * initial);
}
