// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/SplitMix64.h>
#include <crumple/fem/TetGrid.h>
#include <crumple/fem/TetSolver.h>

#include "AllocationCounter.h"
#include "RandomHammer.h"
#include <SkipTest.h>

#include <BrittleMaterial.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

using namespace crumple;
using namespace crumple::fem;

namespace
{

constexpr double cGravity = 9.81;

// A 0.2 m cube of the default material (1 GPa, 1,000 kg/m^3), 2 x 2 x 2 cells, its lowest face at inBottom,
// free, under gravity along -z, over the ground z = 0 with inFriction.
TetSolver MakeBlock(double inBottom, double inFriction, double inMassDamping = 0.0)
{
    TetGridSettings grid;
    grid.mOrigin = Vec3(-0.1, -0.1, inBottom);
    grid.mSize = Vec3(0.2, 0.2, 0.2);
    grid.mCellCount = {2, 2, 2};
    FemMaterialSettings material;
    material.mMassDamping = inMassDamping;
    TetSolverSettings settings;
    settings.mGravity = Vec3(0.0, 0.0, -cGravity);
    settings.mGround.mEnabled = true;
    settings.mGround.mNormal = Vec3(0.0, 0.0, 1.0);
    settings.mGround.mOffset = 0.0;
    settings.mGround.mFriction = inFriction;
    Result<TetSolver> solver = TetSolver::Create(TetGrid(grid).Get(), material, settings);
    REQUIRE(solver.IsValid());
    return std::move(solver).Get();
}

double TotalMass(const TetSolver& inSolver)
{
    double mass = 0.0;
    for (double m : inSolver.GetMasses())
        mass += m;
    return mass;
}

// Mass-weighted mean of inValues (the centre of mass of positions, the momentum over mass of velocities).
Vec3 MassMean(const TetSolver& inSolver, const std::vector<Vec3>& inValues)
{
    Vec3 sum = Vec3::Zero();
    for (std::size_t node = 0; node < inValues.size(); ++node)
        sum += inSolver.GetMasses()[node] * inValues[node];
    return sum / TotalMass(inSolver);
}

double LowestZ(const TetSolver& inSolver)
{
    double lowest = std::numeric_limits<double>::infinity();
    for (const Vec3& position : inSolver.GetPositions())
        lowest = std::min(lowest, position.z());
    return lowest;
}

// A bar 1 m x 0.1 m x 0.1 m of inYoungsModulus (Pa) and steel's density, 10 x 1 x 1 cells, resting on the
// ground z = 0 with inFriction under gravity, sent sliding at inSlide (m/s, along the ground) with its top
// nodes pushed down at inPush (m/s; negative: lifted). inHeldPropSolve: solved as a held prop's solver is
// (the factor refreshed after 6 iterations and by cost).
TetSolver MakeSlidingBar(double inYoungsModulus, double inFriction, const Vec3& inSlide, double inPush,
                         bool inHeldPropSolve = false)
{
    TetGridSettings grid;
    grid.mSize = Vec3(1.0, 0.1, 0.1);
    grid.mCellCount = {10, 1, 1};
    FemMaterialSettings material;
    material.mYoungsModulus = inYoungsModulus;
    material.mDensity = 7850.0;
    TetSolverSettings settings;
    settings.mGravity = Vec3(0.0, 0.0, -cGravity);
    settings.mGround = GroundPlane{true, Vec3::UnitZ(), 0.0, inFriction};
    if (inHeldPropSolve)
    {
        settings.mFactorRefreshIterations = 6;
        settings.mFactorRefreshByCost = true;
    }
    Result<TetSolver> created = TetSolver::Create(TetGrid(grid).Get(), material, settings);
    REQUIRE(created.IsValid());
    TetSolver bar = std::move(created).Get();
    std::vector<Vec3> velocities(bar.GetVelocities().size());
    for (std::size_t node = 0; node < velocities.size(); ++node)
        velocities[node] = inSlide + Vec3(0.0, 0.0, bar.GetPositions()[node].z() > 0.05 ? -inPush : 0.0);
    REQUIRE(bar.SetVelocities(velocities).IsValid());
    return bar;
}

} // namespace

TEST_CASE(
    "Ground: a dropped block falls freely, lands without going through, gains no energy and sleeps on it",
    "[fem]")
{
    const double drop = 0.5, h = 1.0 / 120.0;
    TetSolver block = MakeBlock(drop, 0.6);
    const double mass = TotalMass(block);
    // Mechanical energy with the ground's height as zero: kinetic + elastic + M g z_com.
    const auto energy = [&]
    {
        return block.KineticEnergy() + block.ElasticEnergy() +
               mass * cGravity * MassMean(block, block.GetPositions()).z();
    };
    const double start_energy = energy();
    double last_energy = start_energy;
    int landed_step = -1, asleep_step = -1;
    for (int step = 1; step <= 600 && asleep_step < 0; ++step)
    {
        Result<TetStepResult> result = block.Step(h);
        REQUIRE(result.IsValid());
        REQUIRE_FALSE(HasEvent(result.Get().mEvents, ETetStepEvent::Diverged));
        // Never through the ground (a node put on it lands within round-off of the plane).
        REQUIRE(LowestZ(block) >= -1.0e-9);
        const double now = energy();
        CHECK(now <= last_energy + 1.0e-9 * start_energy);
        last_energy = now;
        if (landed_step < 0 && LowestZ(block) <= 1.0e-9)
            landed_step = step;
        if (landed_step < 0)
        {
            // Free fall before it lands: implicit Euler is exact for the rigid motion, v = -g t.
            CHECK(MassMean(block, block.GetVelocities()).z() == Approx(-cGravity * step * h).epsilon(1.0e-9));
        }
        if (HasEvent(result.Get().mEvents, ETetStepEvent::FellAsleep))
            asleep_step = step;
    }
    // It lands in the step in which the implicit fall z(n) = drop - g h^2 n (n + 1) / 2 reaches the ground.
    int expected_landing = 1;
    while (drop - cGravity * h * h * expected_landing * (expected_landing + 1) / 2.0 > 0.0)
        ++expected_landing;
    CHECK(landed_step == expected_landing);
    WARN("landed at step " << landed_step << ", asleep at step " << asleep_step << " of " << h << " s");
    REQUIRE(asleep_step > 0);
    CHECK(block.IsSleeping());
    // It rests on its lowest face, barely compressed by its weight (sigma = rho g z: strain under 1e-5).
    CHECK(LowestZ(block) == Approx(0.0).margin(1.0e-9));
    CHECK(MassMean(block, block.GetPositions()).z() == Approx(0.1).margin(1.0e-4));
    CHECK(MassMean(block, block.GetPositions()).head<2>().norm() < 1.0e-6);
    for (const Vec3& velocity : block.GetVelocities())
        CHECK(velocity == Vec3::Zero());
}

TEST_CASE("Ground: a block sliding on it decelerates by mu g and stops where Coulomb's law says", "[fem]")
{
    const double h = 1.0 / 240.0, friction = 0.5, speed = 2.0;
    // Rest it on the ground first, then send it sliding along x.
    TetSolver block = MakeBlock(0.0, friction, 2.0);
    for (int step = 0; step < 240 && !block.IsSleeping(); ++step)
        REQUIRE(block.Step(h).IsValid());
    REQUIRE(block.IsSleeping());
    std::vector<Vec3> velocities(block.GetVelocities().size(), Vec3(speed, 0.0, 0.0));
    REQUIRE(block.SetVelocities(velocities).IsValid());
    const Vec3 start = MassMean(block, block.GetPositions());

    // Until it stops, each step's friction takes mu M g h of momentum (the normal impulses carry the weight),
    // after the solve's mass damping: v(n) = v(n-1) / (1 + alpha h) - mu g h. The step's position is the
    // solve's, before friction: x(n) = x(n-1) + h v(n-1) / (1 + alpha h).
    const double damping = 2.0;
    double expected_speed = speed, expected_travel = 0.0;
    int expected_stop = 0;
    for (int step = 1; expected_speed > 0.0; ++step)
    {
        expected_travel += h * expected_speed / (1.0 + damping * h);
        expected_speed = std::max(0.0, expected_speed / (1.0 + damping * h) - friction * cGravity * h);
        expected_stop = step;
    }
    double worst_speed_error = 0.0;
    int stop = 0;
    expected_speed = speed;
    for (int step = 1; step <= 240; ++step)
    {
        REQUIRE(block.Step(h).IsValid());
        const double v = MassMean(block, block.GetVelocities()).x();
        expected_speed = std::max(0.0, expected_speed / (1.0 + damping * h) - friction * cGravity * h);
        // intent: compared while it slides fast; slower, the front and back edges take turns leaving the
        // ground (friction pitches the block) and the shear friction put in it rings when it stops, which the
        // travel and stop below bound
        if (expected_speed >= 0.5 * speed)
            worst_speed_error = std::max(worst_speed_error, std::abs(v - expected_speed));
        if (stop == 0 && v < 0.01 * speed)
            stop = step;
    }
    const double travelled = MassMean(block, block.GetPositions()).x() - start.x();
    WARN("slid " << travelled << " m (Coulomb: " << expected_travel << " m), below 1 % of its speed at step "
                 << stop << " (Coulomb: stopped at " << expected_stop << "), worst speed error "
                 << worst_speed_error << " m/s");
    CHECK(worst_speed_error < 0.001 * speed);
    CHECK(travelled == Approx(expected_travel).epsilon(0.01));
    CHECK(std::abs(stop - expected_stop) <= 3);
    CHECK(LowestZ(block) >= -1.0e-9);
}

TEST_CASE("Ground: a steel bar driven along it and into it gains no energy and slows by Coulomb's law",
          "[fem]")
{
    // A steel bar (200 GPa, 7,850 kg/m^3) 1 m x 0.1 m x 0.1 m resting on the ground, sent sliding along its
    // length at 12 m/s with its top pushed down at 6 m/s (a car's bumper driving a fence rail into the
    // ground). Friction that moved each held node back after the solve pulled it against its neighbours by
    // its whole slowing over the step: kilojoules of strain in a stiff body, steps split and diverged.
    const double h = 1.0 / 240.0, friction = 0.6;
    TetSolver bar = MakeSlidingBar(2.0e11, friction, Vec3(12.0, 0.0, 0.0), 6.0);
    const Vec3 start_velocity = MassMean(bar, bar.GetVelocities());
    const double mass = TotalMass(bar);
    const auto energy = [&]
    {
        return bar.KineticEnergy() + bar.ElasticEnergy() +
               mass * cGravity * MassMean(bar, bar.GetPositions()).z();
    };
    const double start_energy = energy();
    double last_energy = start_energy, largest_gain = 0.0;
    int split = 0, diverged = 0;
    const int steps = 120;
    for (int step = 0; step < steps; ++step)
    {
        const Result<TetStepResult> result = bar.Step(h);
        REQUIRE(result.IsValid());
        split += HasEvent(result.Get().mEvents, ETetStepEvent::Split) ? 1 : 0;
        diverged += HasEvent(result.Get().mEvents, ETetStepEvent::Diverged) ? 1 : 0;
        REQUIRE(LowestZ(bar) >= -1.0e-9);
        const double now = energy();
        largest_gain = std::max(largest_gain, now - last_energy);
        last_energy = now;
    }
    const Vec3 end_velocity = MassMean(bar, bar.GetVelocities());
    // Coulomb: the friction impulse is at most mu times the normal one, M (v_z,end - v_z,start + g t).
    const double normal_per_mass = end_velocity.z() - start_velocity.z() + cGravity * steps * h;
    const double slowed = start_velocity.x() - end_velocity.x();
    WARN("start energy " << start_energy << " J, largest gain in a step " << largest_gain << " J; slowed by "
                         << slowed << " m/s, Coulomb's bound " << friction * normal_per_mass << " m/s; "
                         << split << " steps split, " << diverged << " diverged");
    CHECK(diverged == 0);
    CHECK(split == 0);
    // Friction and the inelastic ground only take energy.
    CHECK(largest_gain <= 1.0e-9 * start_energy);
    // intent: 0.1 %: the ground's impulses are read from the last Newton iterate's residual, which the solve
    // leaves within its tolerance (TetSolverSettings::mImplicitTolerance, 1e-3), not from the momentum change
    CHECK(slowed <= 1.001 * friction * normal_per_mass);
    CHECK(slowed >= friction * cGravity * steps * h); // at least the weight's friction
}

namespace
{

// What a seeded sweep of bars thrown at the ground did (RandomBarsSweep).
struct BarSweep
{
    int mCases = 0, mSteps = 0, mSplitSteps = 0, mDivergedSteps = 0;
    double mWorstGain = 0.0;    ///< Largest energy gained in a step, of the start energy
    double mWorstCoulomb = 0.0; ///< Largest tangential slowing over mu times the net normal impulse per mass
};

// Seeded sweep of the steel bar case: stiffness 1e6-2e11 Pa, friction 0-1, a slide of up to 15 m/s in a
// random direction along the ground, the top pushed down at up to 10 m/s or lifted at up to 2 m/s, step
// 1/240-1/30 s, 40 steps each; inHeldPropSolve: solved as a held prop's solver is (refreshed).
BarSweep RandomBarsSweep(bool inHeldPropSolve)
{
    SplitMix64 random(20261207u);
    BarSweep sweep;
    for (int run = 0; run < 24; ++run)
    {
        const double young = std::pow(10.0, 6.0 + random.NextDouble() * std::log10(2.0e5));
        const double friction = random.NextDouble();
        const double speed = 15.0 * random.NextDouble(), heading = 6.283185307179586 * random.NextDouble();
        const double push = -2.0 + 12.0 * random.NextDouble();
        const double h = 1.0 / (30.0 + 210.0 * random.NextDouble());
        TetSolver bar = MakeSlidingBar(
            young, friction, speed * Vec3(std::cos(heading), std::sin(heading), 0.0), push, inHeldPropSolve);
        const double mass = TotalMass(bar);
        const auto energy = [&]
        {
            return bar.KineticEnergy() + bar.ElasticEnergy() +
                   mass * cGravity * MassMean(bar, bar.GetPositions()).z();
        };
        const Vec3 start_velocity = MassMean(bar, bar.GetVelocities());
        const double start_energy = energy();
        double last_energy = start_energy;
        for (int step = 0; step < 40; ++step)
        {
            const Result<TetStepResult> result = bar.Step(h);
            REQUIRE(result.IsValid());
            ++sweep.mSteps;
            sweep.mSplitSteps += HasEvent(result.Get().mEvents, ETetStepEvent::Split) ? 1 : 0;
            sweep.mDivergedSteps += HasEvent(result.Get().mEvents, ETetStepEvent::Diverged) ? 1 : 0;
            REQUIRE(std::all_of(bar.GetPositions().begin(), bar.GetPositions().end(),
                                [](const Vec3& inX) { return inX.allFinite(); }));
            REQUIRE(LowestZ(bar) >= -1.0e-9);
            const double now = energy();
            sweep.mWorstGain = std::max(sweep.mWorstGain, (now - last_energy) / start_energy);
            last_energy = now;
        }
        const Vec3 end_velocity = MassMean(bar, bar.GetVelocities());
        const double normal_per_mass = end_velocity.z() - start_velocity.z() + cGravity * 40 * h;
        const double slowed = (start_velocity - end_velocity).head<2>().norm();
        if (friction * normal_per_mass > 0.0)
            sweep.mWorstCoulomb = std::max(sweep.mWorstCoulomb, slowed / (friction * normal_per_mass));
        ++sweep.mCases;
    }
    return sweep;
}

} // namespace

TEST_CASE(
    "Ground: bars of random stiffness thrown at it at random never gain energy and keep Coulomb's bound",
    "[fem]")
{
    // The ground and friction only take energy, and over the run the tangential slowing stays within mu times
    // the net normal impulse per unit mass (0.1 %: the Newton tolerance). The same bars twice: with the rest
    // factor, and solved as a held prop's solver is (refreshed). (A factor of the ground's filtered system,
    // tried and reverted, made the second sweep gain energy: README, known limits.)
    for (const bool held_prop_solve : {false, true})
    {
        const BarSweep sweep = RandomBarsSweep(held_prop_solve);
        WARN((held_prop_solve ? "held prop's solve: " : "rest factor: ")
             << sweep.mCases << " bars, " << sweep.mSteps << " steps: " << sweep.mSplitSteps << " split, "
             << sweep.mDivergedSteps << " diverged; largest energy gain in a step " << sweep.mWorstGain
             << " of the start energy; largest slowing over Coulomb's bound " << sweep.mWorstCoulomb);
        CHECK(sweep.mDivergedSteps == 0);
        CHECK(sweep.mWorstGain <= 1.0e-9);
        CHECK(sweep.mWorstCoulomb <= 1.001);
    }
}

TEST_CASE("Ground: it never pulls, a block lifted by a force larger than its weight leaves it", "[fem]")
{
    const double h = 1.0 / 240.0;
    TetSolver block = MakeBlock(0.0, 0.6);
    for (int step = 0; step < 240 && !block.IsSleeping(); ++step)
        REQUIRE(block.Step(h).IsValid());
    REQUIRE(block.IsSleeping());
    // Twice its weight upwards, spread over the nodes by mass: it accelerates up at g.
    for (int node = 0; node < block.GetNodeCount(); ++node)
        REQUIRE(
            block.SetExternalForce(node, Vec3(0.0, 0.0, 2.0 * block.GetMasses()[node] * cGravity)).IsValid());
    const double start = MassMean(block, block.GetPositions()).z();
    const int steps = 24;
    for (int step = 0; step < steps; ++step)
        REQUIRE(block.Step(h).IsValid());
    // z(n) = z0 + g h^2 n (n + 1) / 2 for implicit Euler from rest; every node has left the ground.
    const double risen = MassMean(block, block.GetPositions()).z() - start;
    CHECK(risen == Approx(cGravity * h * h * steps * (steps + 1) / 2.0).epsilon(1.0e-3));
    CHECK(LowestZ(block) > 1.0e-3);
}

TEST_CASE("Ground: nodes set into it at rest are not held, so a buried part moves as without a ground",
          "[fem]")
{
    TetGridSettings grid;
    grid.mOrigin = Vec3(-0.1, -0.1, -0.3);
    grid.mSize = Vec3(0.2, 0.2, 0.2);
    grid.mCellCount = {2, 2, 2};
    TetSolverSettings settings;
    settings.mGravity = Vec3(0.0, 0.0, -cGravity);
    TetSolverSettings grounded = settings;
    grounded.mGround.mEnabled = true;
    Result<TetSolver> free = TetSolver::Create(TetGrid(grid).Get(), {}, settings);
    Result<TetSolver> buried = TetSolver::Create(TetGrid(grid).Get(), {}, grounded);
    REQUIRE(free.IsValid());
    REQUIRE(buried.IsValid());
    std::vector<Vec3> up(free.Get().GetVelocities().size(), Vec3(0.3, 0.0, 1.0));
    REQUIRE(free.Get().SetVelocities(up).IsValid());
    REQUIRE(buried.Get().SetVelocities(up).IsValid());
    for (int step = 0; step < 60; ++step)
    {
        REQUIRE(free.Get().Step(1.0 / 60.0).IsValid());
        REQUIRE(buried.Get().Step(1.0 / 60.0).IsValid());
    }
    // It rose through the ground and fell back through it: bit for bit the motion without one.
    CHECK(free.Get().GetPositions() == buried.Get().GetPositions());
    CHECK(free.Get().GetVelocities() == buried.Get().GetVelocities());
}

TEST_CASE("Ground: a copy made while resting on it continues bit for bit", "[fem]")
{
    TetSolver block = MakeBlock(0.05, 0.6);
    for (int step = 0; step < 20; ++step)
        REQUIRE(block.Step(1.0 / 120.0).IsValid());
    REQUIRE(LowestZ(block) <= 1.0e-9); // landed
    TetSolver copy = block;
    std::vector<Vec3> push(block.GetVelocities().size(), Vec3(1.0, 0.5, 0.0));
    REQUIRE(block.SetVelocities(push).IsValid());
    REQUIRE(copy.SetVelocities(push).IsValid());
    for (int step = 0; step < 30; ++step)
    {
        REQUIRE(block.Step(1.0 / 120.0).IsValid());
        REQUIRE(copy.Step(1.0 / 120.0).IsValid());
    }
    CHECK(block.GetPositions() == copy.GetPositions());
    CHECK(block.GetVelocities() == copy.GetVelocities());
}

TEST_CASE("Ground: a bad ground is refused with its reason", "[fem]")
{
    TetGridSettings grid;
    const TetMesh mesh = TetGrid(grid).Get();
    struct Case
    {
        const char* mName;
        GroundPlane mGround;
        EIntegrator mIntegrator;
        const char* mReason;
    };
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const Case cases[] = {
        {"zero normal", {true, Vec3::Zero(), 0.0, 0.5}, EIntegrator::ImplicitEuler, "unit vector"},
        {"long normal", {true, Vec3(0.0, 0.0, 2.0), 0.0, 0.5}, EIntegrator::ImplicitEuler, "unit vector"},
        {"NaN normal", {true, Vec3(nan, 0.0, 1.0), 0.0, 0.5}, EIntegrator::ImplicitEuler, "unit vector"},
        {"NaN offset", {true, Vec3::UnitZ(), nan, 0.5}, EIntegrator::ImplicitEuler, "mOffset"},
        {"huge offset", {true, Vec3::UnitZ(), 1.0e200, 0.5}, EIntegrator::ImplicitEuler, "mOffset"},
        {"negative friction", {true, Vec3::UnitZ(), 0.0, -0.1}, EIntegrator::ImplicitEuler, "mFriction"},
        {"infinite friction",
         {true, Vec3::UnitZ(), 0.0, std::numeric_limits<double>::infinity()},
         EIntegrator::ImplicitEuler,
         "mFriction"},
        {"symplectic", {true, Vec3::UnitZ(), 0.0, 0.5}, EIntegrator::SymplecticEuler, "ImplicitEuler"},
    };
    for (const Case& c : cases)
    {
        INFO(c.mName);
        TetSolverSettings settings;
        settings.mIntegrator = c.mIntegrator;
        settings.mGround = c.mGround;
        Result<TetSolver> solver = TetSolver::Create(mesh, {}, settings);
        REQUIRE(solver.HasError());
        CHECK_THAT(solver.GetError().mMessage, Catch::Contains(c.mReason));
    }
    // Switched off, its fields are not read.
    TetSolverSettings off;
    off.mGround = {false, Vec3::Zero(), nan, -1.0};
    CHECK(TetSolver::Create(mesh, {}, off).IsValid());
}

TEST_CASE(
    "Ground: a brittle wall hammered at random on the ground never goes through it and never produces NaN",
    "[fem]")
{
    // The stress test's brittle wall (1 m x 0.2 m x 0.6 m, 10 GPa, anchored along its base at z = 0) under
    // gravity on the ground z = 0, hit by seeded random impulses of 1e-3 ... 1e5 N s every 3rd step of 1/240
    // ... 1/30 s: the pieces it sheds fall onto the ground.
    TetGridSettings grid;
    grid.mSize = Vec3(1.0, 0.2, 0.6);
    grid.mCellCount = {5, 1, 3};
    TetSolverSettings settings;
    settings.mGravity = Vec3(0.0, 0.0, -cGravity);
    settings.mGround = GroundPlane{true, Vec3::UnitZ(), 0.0, 0.6};
    TetSolver solver = TetSolver::Create(TetGrid(grid).Get(), common::StiffBrittleMaterial(), settings).Get();
    for (int i = 0; i <= 5; ++i)
        for (int j = 0; j <= 1; ++j)
            REQUIRE(solver.SetNodeFixed(TetGridNode(grid.mCellCount, i, j, 0), true).IsValid());
    test::RandomHammer hammer(99u);
    int fracture_steps = 0, diverged = 0, steps = 0;
    double largest_speed = 0.0;
    for (int step = 0; step < 150; ++step)
    {
        if (step % 3 == 0)
            hammer.Strike(solver);
        const std::vector<Vec3> positions = solver.GetPositions();
        const Result<TetStepResult> result = solver.Step(hammer.StepLength());
        REQUIRE(result.IsValid());
        ++steps;
        REQUIRE(std::all_of(solver.GetPositions().begin(), solver.GetPositions().end(),
                            [](const Vec3& inX) { return inX.allFinite(); }));
        REQUIRE(std::all_of(solver.GetVelocities().begin(), solver.GetVelocities().end(),
                            [](const Vec3& inV) { return inV.allFinite(); }));
        const bool restored = HasEvent(result.Get().mEvents, ETetStepEvent::Diverged);
        diverged += restored ? 1 : 0;
        if (restored)
            CHECK(solver.GetPositions() == positions);
        fracture_steps += HasEvent(result.Get().mEvents, ETetStepEvent::Fractured) ? 1 : 0;
        // Never through the ground: every free node on it or above, within round-off.
        for (std::size_t node = 0; node < solver.GetPositions().size(); ++node)
            if (solver.GetInverseMasses()[node] > 0.0)
                REQUIRE(solver.GetPositions()[node].z() >= -1.0e-9);
        for (const Vec3& velocity : solver.GetVelocities())
            largest_speed = std::max(largest_speed, velocity.norm());
    }
    WARN(steps << " steps: " << fracture_steps << " cracked, " << diverged << " diverged and restored, "
               << solver.GetBrokenLinkCount() << " links broken, " << solver.ComputeFragments().size()
               << " pieces; largest node speed " << largest_speed << " m/s");
    CHECK(fracture_steps > 0); // the hammering really cracked it
    CHECK(solver.ComputeFragments().size() > 1u);
    CHECK(largest_speed > 1.0);
    CHECK(diverged <= steps / 10);
}

TEST_CASE("Ground: a step on the ground allocates nothing once the solver has stepped", "[fem]")
{
    if (!test::AllocationCounter::IsAvailable())
        common::SkipTest(
            "allocations are not counted under AddressSanitizer (its runtime owns operator new)");
    // Landed and sliding (held nodes, friction, the filter in every solve), then a step that lands it again.
    TetSolver block = MakeBlock(0.02, 0.3);
    for (int step = 0; step < 30; ++step)
        REQUIRE(block.Step(1.0 / 240.0).IsValid());
    REQUIRE(LowestZ(block) <= 1.0e-9);
    std::vector<Vec3> sliding(block.GetVelocities().size(), Vec3(1.0, 0.0, 0.5));
    REQUIRE(block.SetVelocities(sliding).IsValid());
    std::uint64_t allocations = 0;
    {
        const test::AllocationCounter counter;
        for (int step = 0; step < 20; ++step)
            REQUIRE(block.Step(1.0 / 240.0).IsValid());
        allocations = counter.Count();
    }
    CHECK(allocations == 0);
}
