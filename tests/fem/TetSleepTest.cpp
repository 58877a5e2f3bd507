// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/TetGrid.h>
#include <crumple/fem/TetSolver.h>

#include <catch2/catch.hpp>

using namespace crumple;
using namespace crumple::fem;

namespace
{

// A 0.6 x 0.2 x 0.1 m plate of the default material (1 GPa), anchored along x = 0, sagging under gravity.
TetSolver MakeShelf(EIntegrator inIntegrator, double inMassDamping, TetSolverSettings inSettings = {})
{
    TetGridSettings grid;
    grid.mSize = Vec3(0.6, 0.2, 0.1);
    grid.mCellCount = {6, 2, 1};
    FemMaterialSettings material;
    material.mMassDamping = inMassDamping;
    inSettings.mIntegrator = inIntegrator;
    TetSolver solver = TetSolver::Create(TetGrid(grid).Get(), material, inSettings).Get();
    for (int k = 0; k <= 1; ++k)
        for (int j = 0; j <= 2; ++j)
            REQUIRE(solver.SetNodeFixed(TetGridNode(grid.mCellCount, 0, j, k), true).IsValid());
    return solver;
}

// Mass of the free nodes (kg): the sleep energy is half of it times the sleep speed squared.
double FreeMass(const TetSolver& inSolver)
{
    double mass = 0.0;
    for (std::size_t node = 0; node < inSolver.GetMasses().size(); ++node)
        mass += inSolver.GetInverseMasses()[node] > 0.0 ? inSolver.GetMasses()[node] : 0.0;
    return mass;
}

} // namespace

TEST_CASE("Sleep: a settled solver does no element work until an impulse wakes it", "[fem]")
{
    // Implicit Euler damps by itself; symplectic Euler needs material damping to come to rest.
    struct Case
    {
        EIntegrator mIntegrator;
        double mMassDamping;
        double mStepTime;
        int mMaxSteps;
    };
    for (const Case& c : {Case{EIntegrator::ImplicitEuler, 0.0, 1.0 / 60.0, 600},
                          Case{EIntegrator::SymplecticEuler, 20.0, 1.0 / 240.0, 2400}})
    {
        TetSolver solver = MakeShelf(c.mIntegrator, c.mMassDamping);

        // Settle: it must fall asleep, with zero velocities.
        int steps = 0;
        bool asleep = false;
        for (; steps < c.mMaxSteps && !asleep; ++steps)
        {
            Result<TetStepResult> result = solver.Step(c.mStepTime);
            REQUIRE(result.IsValid());
            asleep = HasEvent(result.Get().mEvents, ETetStepEvent::FellAsleep);
        }
        WARN(ToString(c.mIntegrator) << ": asleep after " << steps << " steps of " << c.mStepTime << " s");
        REQUIRE(asleep);
        REQUIRE(solver.IsSleeping());
        for (const Vec3& velocity : solver.GetVelocities())
            CHECK(velocity == Vec3::Zero());

        // Asleep: no element work at all, nothing moves.
        const std::uint64_t work = solver.GetElementWorkCount();
        const std::vector<Vec3> positions = solver.GetPositions();
        for (int step = 0; step < 100; ++step)
        {
            Result<TetStepResult> result = solver.Step(c.mStepTime);
            REQUIRE(result.IsValid());
            CHECK(result.Get().mEvents == ETetStepEvent::Sleeping);
        }
        CHECK(solver.GetElementWorkCount() == work);
        CHECK(solver.GetPositions() == positions);

        // An impulse wakes it; the next step works and moves the body.
        const int tip = solver.GetMesh().GetNodeCount() - 1;
        REQUIRE(solver.ApplyImpulse(tip, Vec3(0.0, 0.0, 0.5)).IsValid());
        CHECK(!solver.IsSleeping());
        Result<TetStepResult> woken = solver.Step(c.mStepTime);
        REQUIRE(woken.IsValid());
        CHECK(!HasEvent(woken.Get().mEvents, ETetStepEvent::Sleeping));
        CHECK(solver.GetElementWorkCount() > work);
        CHECK(solver.GetPositions()[tip] != positions[tip]);
    }
}

TEST_CASE("Sleep: a body settled in equilibrium sleeps three steps after it settles, an oscillation never does",
          "[fem]")
{
    // mSleepStepCount out of reach: only the settled rule (kinetic energy under 1e-8 of the sleep energy
    // three steps in a row) can put these to sleep.
    TetSolverSettings patient;
    patient.mSleepStepCount = 1000000;

    // The shelf sags under gravity and comes to rest strained against its anchors: it sleeps in the third
    // step in a row whose kinetic energy is round-off.
    {
        TetSolver shelf = MakeShelf(EIntegrator::ImplicitEuler, 0.0, patient);
        const double sleep_energy = 0.5 * FreeMass(shelf) * patient.mSleepSpeed * patient.mSleepSpeed;
        int settled = 0;
        bool asleep = false;
        int steps = 0;
        for (; steps < 2000 && !asleep; ++steps)
        {
            const TetStepResult result = shelf.Step(1.0 / 60.0).Get();
            asleep = HasEvent(result.mEvents, ETetStepEvent::FellAsleep);
            settled = result.mKineticEnergy < 1.0e-8 * sleep_energy ? settled + 1 : 0;
            if (!asleep)
                CHECK(settled < 3);
        }
        WARN("settled shelf asleep after " << steps << " steps");
        REQUIRE(asleep);
        CHECK(settled == 3);
        for (const Vec3& velocity : shelf.GetVelocities())
            CHECK(velocity == Vec3::Zero());
    }

    // The same shelf plucked and undamped (symplectic Euler) swings with the same energy forever; its
    // kinetic energy passes through zero twice a period but never stays there.
    {
        TetSolverSettings weightless = patient;
        weightless.mGravity = Vec3::Zero();
        TetSolver swinging = MakeShelf(EIntegrator::SymplecticEuler, 0.0, weightless);
        REQUIRE(swinging.ApplyImpulse(swinging.GetMesh().GetNodeCount() - 1, Vec3(0.0, 0.0, 1.0e-3)).IsValid());
        for (int step = 0; step < 600; ++step)
            REQUIRE_FALSE(HasEvent(swinging.Step(1.0 / 240.0).Get().mEvents, ETetStepEvent::FellAsleep));
        CHECK_FALSE(swinging.IsSleeping());
    }
}

TEST_CASE("Sleep: a free-falling body never sleeps, mSleepSpeed 0 disables sleep", "[fem]")
{
    TetGridSettings grid;
    grid.mCellCount = {2, 1, 1};
    const TetMesh mesh = TetGrid(grid).Get();

    TetSolver falling = TetSolver::Create(mesh, FemMaterialSettings(), TetSolverSettings()).Get();
    TetSolverSettings no_sleep;
    no_sleep.mSleepSpeed = 0.0;
    no_sleep.mGravity = Vec3::Zero();
    TetSolver resting = TetSolver::Create(mesh, FemMaterialSettings(), no_sleep).Get();
    for (int step = 0; step < 120; ++step)
    {
        REQUIRE(falling.Step(1.0 / 60.0).IsValid());
        REQUIRE(resting.Step(1.0 / 60.0).IsValid());
    }
    CHECK(!falling.IsSleeping());
    CHECK(!resting.IsSleeping());
}

TEST_CASE("Sleep: a solver that nothing could move sleeps from its first step, and wakes when something does",
          "[fem]")
{
    // Without gravity, unstrained and still, a step would do nothing: no element work is spent on it.
    TetGridSettings grid;
    grid.mSize = Vec3(0.6, 0.2, 0.1);
    grid.mCellCount = {6, 2, 1};
    TetSolverSettings weightless;
    weightless.mGravity = Vec3::Zero();
    TetSolver solver = TetSolver::Create(TetGrid(grid).Get(), FemMaterialSettings(), weightless).Get();
    REQUIRE(solver.SetNodeFixed(0, true).IsValid());
    const TetStepResult first = solver.Step(1.0 / 60.0).Get();
    CHECK(HasEvent(first.mEvents, ETetStepEvent::FellAsleep));
    CHECK(HasEvent(first.mEvents, ETetStepEvent::Sleeping));
    CHECK(solver.IsSleeping());
    CHECK(solver.GetElementWorkCount() == 0u);
    CHECK(solver.GetPositions() == TetGrid(grid).Get().GetRestPositions());

    // An impulse moves it: awake, it integrates (and sleeps again only after mSleepStepCount quiet steps).
    REQUIRE(solver.ApplyImpulse(20, Vec3(0.0, 0.0, 0.01)).IsValid());
    const TetStepResult struck = solver.Step(1.0 / 60.0).Get();
    CHECK_FALSE(HasEvent(struck.mEvents, ETetStepEvent::Sleeping));
    CHECK(solver.GetElementWorkCount() > 0u);

    // A load or a strain moves it too: neither sleeps at its first step.
    TetSolver pushed = TetSolver::Create(TetGrid(grid).Get(), FemMaterialSettings(), weightless).Get();
    REQUIRE(pushed.SetNodeFixed(0, true).IsValid());
    REQUIRE(pushed.SetExternalForce(20, Vec3(0.0, 0.0, 1.0)).IsValid());
    CHECK_FALSE(HasEvent(pushed.Step(1.0 / 60.0).Get().mEvents, ETetStepEvent::Sleeping));
    TetSolver stretched = TetSolver::Create(TetGrid(grid).Get(), FemMaterialSettings(), weightless).Get();
    std::vector<Vec3> moved = stretched.GetPositions();
    moved[20].x() += 1.0e-3;
    REQUIRE(stretched.SetPositions(moved).IsValid());
    CHECK_FALSE(HasEvent(stretched.Step(1.0 / 60.0).Get().mEvents, ETetStepEvent::Sleeping));

    // With gravity the same solver sags: it does not sleep at its first step.
    TetSolver heavy = TetSolver::Create(TetGrid(grid).Get(), FemMaterialSettings(), TetSolverSettings()).Get();
    REQUIRE(heavy.SetNodeFixed(0, true).IsValid());
    CHECK_FALSE(HasEvent(heavy.Step(1.0 / 60.0).Get().mEvents, ETetStepEvent::Sleeping));
    CHECK(heavy.GetElementWorkCount() > 0u);
}
