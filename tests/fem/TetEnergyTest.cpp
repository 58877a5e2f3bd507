// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/TetGrid.h>
#include <crumple/fem/TetSolver.h>

#include <catch2/catch.hpp>

#include <algorithm>

using namespace crumple;
using namespace crumple::fem;

namespace
{

// An undamped soft cantilever (1 m x 0.1 m x 0.1 m, 20 x 2 x 2 cells, E = 10 MPa, rho = 1000 kg/m^3, clamped
// at x = 0, no gravity) released from its static shape under a 20 N tip load (tip deflection ~5 cm): it
// swings in its first bending mode, about 2 Hz.
TetSolver MakeReleasedCantilever(EElasticModel inModel, TetSolverSettings inSettings)
{
    TetGridSettings grid;
    grid.mSize = Vec3(1.0, 0.1, 0.1);
    grid.mCellCount = {20, 2, 2};
    FemMaterialSettings material;
    material.mYoungsModulus = 1.0e7;
    material.mDensity = 1000.0;
    material.mModel = inModel;
    inSettings.mGravity = Vec3::Zero();
    inSettings.mSleepSpeed = 0.0;
    TetSolver solver = TetSolver::Create(TetGrid(grid).Get(), material, inSettings).Get();
    for (int k = 0; k <= 2; ++k)
        for (int j = 0; j <= 2; ++j)
        {
            REQUIRE(solver.SetNodeFixed(TetGridNode(grid.mCellCount, 0, j, k), true).IsValid());
            REQUIRE(
                solver.SetExternalForce(TetGridNode(grid.mCellCount, 20, j, k), Vec3(0.0, 0.0, -20.0 / 9.0))
                    .IsValid());
        }
    REQUIRE(solver.SolveStatic().IsValid());
    solver.ClearExternalForces();
    return solver;
}

} // namespace

TEST_CASE("Energy: undamped symplectic Euler keeps the total energy within 1 % over 1,000 steps", "[fem]")
{
    for (EElasticModel model : {EElasticModel::CorotatedLinear, EElasticModel::StVenantKirchhoff})
    {
        TetSolverSettings settings;
        settings.mIntegrator = EIntegrator::SymplecticEuler;
        TetSolver solver = MakeReleasedCantilever(model, settings);
        const double initial = solver.TotalEnergy();
        REQUIRE(initial > 0.1);

        // 1,000 steps of 1 ms (each split into the automatic stable sub-steps): two swings.
        double worst = 0.0, highest_kinetic = 0.0;
        int sub_steps = 0;
        for (int step = 0; step < 1000; ++step)
        {
            Result<TetStepResult> result = solver.Step(1.0e-3);
            REQUIRE(result.IsValid());
            REQUIRE(result.Get().mEvents == ETetStepEvent::None);
            sub_steps = result.Get().mSubSteps;
            worst = std::max(worst, std::abs(solver.TotalEnergy() - initial) / initial);
            highest_kinetic = std::max(highest_kinetic, solver.KineticEnergy());
        }
        WARN(ToString(model) << ": symplectic Euler, " << sub_steps
                             << " sub-steps per 1 ms step, initial energy " << initial
                             << " J, largest relative energy error over 1000 steps " << worst
                             << ", largest kinetic energy " << highest_kinetic << " J");
        CHECK(worst < 0.01);
        CHECK(highest_kinetic > 0.9 * initial); // it really swings through its rest shape
    }
}

TEST_CASE("Energy: implicit Euler's energy decays monotonically", "[fem]")
{
    for (EElasticModel model : {EElasticModel::CorotatedLinear, EElasticModel::StVenantKirchhoff})
        for (double step_time : {1.0 / 60.0, 1.0 / 600.0})
        {
            // Tight solves, so that what is measured is the integrator, not the solver tolerances.
            TetSolverSettings settings;
            settings.mIntegrator = EIntegrator::ImplicitEuler;
            settings.mCgRelativeTolerance = 1.0e-10;
            settings.mImplicitTolerance = 1.0e-12;
            settings.mImplicitMaxIterations = 20;
            TetSolver solver = MakeReleasedCantilever(model, settings);
            const double initial = solver.TotalEnergy();
            double previous = initial;
            double largest_rise = -1.0;
            for (int step = 0; step < 120; ++step)
            {
                Result<TetStepResult> result = solver.Step(step_time);
                REQUIRE(result.IsValid());
                REQUIRE(!HasEvent(result.Get().mEvents, ETetStepEvent::Diverged));
                const double energy = solver.TotalEnergy();
                largest_rise = std::max(largest_rise, (energy - previous) / initial);
                previous = energy;
            }
            WARN(ToString(model) << ": implicit Euler at " << step_time << " s, energy " << initial
                                 << " J -> " << previous << " J after 120 steps; largest step-to-step change "
                                 << largest_rise << " of the initial");
            CHECK(largest_rise <= 1.0e-9);
            CHECK(previous < initial);
        }
}
