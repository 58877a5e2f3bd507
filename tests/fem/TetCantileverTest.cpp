// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// The steel cantilever of the FEM issue: 1 m x 0.1 m x 0.1 m, E = 200 GPa, nu = 0.3, rho = 7850 kg/m^3,
// clamped at x = 0 (every node of that face anchored), 1 kN downwards at the tip spread over the tip face by
// area.
#include "CantileverScene.h"

#include <crumple/fem/TetSolver.h>

#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>

using namespace crumple;
using namespace crumple::fem;
using common::CantileverScene;

namespace
{

constexpr double cLoad = 1000.0;
constexpr double cPi = 3.14159265358979323846;

/// The cantilever (tests/common/CantileverScene.h) with its defaults: steel, 1 kN at the tip.
const common::CantileverSettings cBeam;

/// A cantilever of inLengthCells x inSectionCells x inSectionCells five-tet cells, undamped, no gravity, tip
/// load set.
CantileverScene MakeCantilever(int inLengthCells, int inSectionCells, EIntegrator inIntegrator)
{
    common::CantileverSettings settings = cBeam;
    settings.mLengthCells = inLengthCells;
    settings.mSectionCells = inSectionCells;
    settings.mSolver.mIntegrator = inIntegrator;
    Result<CantileverScene> beam = CantileverScene::Create(settings);
    REQUIRE(beam.IsValid());
    return std::move(beam).Get();
}

/// The FE model's first eigenfrequency (Hz, lumped mass) by inverse iteration from the static tip-load shape,
/// each iteration a SolveStatic under the load M u; the Rayleigh quotient of the last iterate.
double InverseIterationFrequency(CantileverScene& ioBeam, int inIterations)
{
    TetSolver& solver = ioBeam.GetSolver();
    const std::vector<Vec3>& rest = solver.GetMesh().GetRestPositions();
    const std::vector<double>& mass = solver.GetMasses();
    const int node_count = solver.GetMesh().GetNodeCount();
    std::vector<Vec3> u(rest.size());
    for (int node = 0; node < node_count; ++node)
        u[node] = solver.GetPositions()[node] - rest[node];

    double omega_squared = 0.0;
    for (int iteration = 0; iteration < inIterations; ++iteration)
    {
        // Load s M u, scaled to about 1 kN so that the response stays small and linear.
        double mass_norm = 0.0;
        for (int node = 0; node < node_count; ++node)
            mass_norm += mass[node] * u[node].norm();
        const double scale = cLoad / mass_norm;
        for (int node = 0; node < node_count; ++node)
            REQUIRE(solver.SetExternalForce(node, scale * mass[node] * u[node]).IsValid());
        REQUIRE(solver.SetPositions(rest).IsValid());
        REQUIRE(solver.SolveStatic().IsValid());

        // K u' = s M u: omega^2 ~ u'^T K u' / u'^T M u' = s u'^T M u / u'^T M u'.
        double cross = 0.0, self = 0.0;
        for (int node = 0; node < node_count; ++node)
        {
            const Vec3 next = solver.GetPositions()[node] - rest[node];
            cross += mass[node] * next.dot(u[node]);
            self += mass[node] * next.squaredNorm();
            u[node] = next;
        }
        omega_squared = scale * cross / self;
    }
    return std::sqrt(omega_squared) / (2.0 * cPi);
}

/// First frequency (Hz) from a free vibration: release the static tip-load shape, integrate undamped with
/// symplectic Euler and time two full periods of the tip between upward zero crossings (linear
/// interpolation).
double FreeVibrationFrequency(CantileverScene& ioBeam, double inFrameTime, int inFrames)
{
    TetSolver& solver = ioBeam.GetSolver();
    solver.ClearExternalForces();
    std::vector<double> crossings;
    double previous = ioBeam.TipDeflection();
    for (int frame = 1; frame <= inFrames && crossings.size() < 3; ++frame)
    {
        Result<TetStepResult> step = solver.Step(inFrameTime);
        REQUIRE(step.IsValid());
        REQUIRE(step.Get().mEvents == ETetStepEvent::None);
        const double deflection = ioBeam.TipDeflection();
        if (previous > 0.0 && deflection <= 0.0) // tip moving up through rest
            crossings.push_back((frame - 1 + previous / (previous - deflection)) * inFrameTime);
        previous = deflection;
    }
    REQUIRE(crossings.size() == 3);
    return 2.0 / (crossings[2] - crossings[0]);
}

} // namespace

TEST_CASE("Cantilever: static tip deflection converges towards Timoshenko beam theory", "[fem]")
{
    // Linear tetrahedra lock in bending, so the coarse meshes are too stiff; the error falls by about 3x per
    // halving.
    const double reference = common::TimoshenkoDeflection(cBeam); // 2.0156e-4 m
    const int sections[] = {1, 2, 4, 8};
    double previous_error = 1.0;
    for (int section : sections)
    {
        const auto start = std::chrono::steady_clock::now();
        CantileverScene beam = MakeCantilever(10 * section, section, EIntegrator::ImplicitEuler);
        Result<TetStaticResult> result = beam.GetSolver().SolveStatic();
        REQUIRE(result.IsValid());
        const double deflection = beam.TipDeflection();
        const double error = (deflection - reference) / reference;
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        WARN("cantilever " << 10 * section << "x" << section << "x" << section << " cells ("
                           << beam.GetSolver().GetMesh().GetTetCount() << " tets): tip deflection "
                           << deflection << " m, Timoshenko " << reference << " m, error " << 100.0 * error
                           << " % (" << result.Get().mSolverIterations << " CG iterations, " << seconds
                           << " s)");
        CHECK(error < 0.0);                      // stiffer than the beam, never softer
        CHECK(std::abs(error) < previous_error); // converging
        previous_error = std::abs(error);
    }
    // Documented bound for the finest mesh (80 x 8 x 8 cells, 25,600 tets): within 5 % (measured 3.7 %).
    CHECK(previous_error < 0.05);
}

TEST_CASE("Cantilever: first bending frequency against Euler-Bernoulli", "[fem]")
{
    // The FE model's frequency on the finest mesh by inverse iteration (static solves), against the analytic
    // value.
    CantileverScene fine = MakeCantilever(80, 8, EIntegrator::ImplicitEuler);
    REQUIRE(fine.GetSolver().SolveStatic().IsValid());
    const double f_fine = InverseIterationFrequency(fine, 2);
    const double f_bernoulli = common::EulerBernoulliFrequency(cBeam); // 81.5 Hz
    const double f_shear = common::ShearCorrectedFrequency(cBeam);     // 81.0 Hz
    const double error = (f_fine - f_bernoulli) / f_bernoulli;
    WARN("cantilever 80x8x8 first frequency "
         << f_fine << " Hz; Euler-Bernoulli " << f_bernoulli << " Hz (error " << 100.0 * error
         << " %), shear-corrected " << f_shear << " Hz (error " << 100.0 * (f_fine - f_shear) / f_shear
         << " %)");
    CHECK(std::abs(error) < 0.05);

    // The dynamics agree with the stiffness: the free vibration of the 20 x 2 x 2 mesh under symplectic Euler
    // has the frequency the inverse iteration finds for that mesh.
    CantileverScene coarse = MakeCantilever(20, 2, EIntegrator::SymplecticEuler);
    REQUIRE(coarse.GetSolver().SolveStatic().IsValid());
    const std::vector<Vec3> released = coarse.GetSolver().GetPositions();
    CantileverScene coarse_modal = MakeCantilever(20, 2, EIntegrator::ImplicitEuler);
    REQUIRE(coarse_modal.GetSolver().SolveStatic().IsValid());
    const double f_modal = InverseIterationFrequency(coarse_modal, 3);
    REQUIRE(coarse.GetSolver().SetPositions(released).IsValid());
    const double f_dynamic = FreeVibrationFrequency(coarse, 1.0e-4, 400);
    WARN("cantilever 20x2x2: free-vibration frequency " << f_dynamic << " Hz, inverse iteration " << f_modal
                                                        << " Hz, Euler-Bernoulli " << f_bernoulli << " Hz");
    CHECK(f_dynamic == Approx(f_modal).epsilon(0.01));
}

TEST_CASE("Cantilever: free vibration of the 40 x 4 x 4 mesh", "[fem][slow][soak][.]")
{
    // Symplectic Euler over two periods (~23 ms) at the stable sub-step of 0.025 m steel cells (0.78 us):
    // ~30,000 sub-steps of 3,200 elements, about 15-22 s, hence hidden ([.]) and tagged [soak]: the bench job
    // runs it (CTest label soak, scripts/bench.sh), or test_fem "[soak]".
    CantileverScene beam = MakeCantilever(40, 4, EIntegrator::SymplecticEuler);
    REQUIRE(beam.GetSolver().SolveStatic().IsValid());
    const double f_dynamic = FreeVibrationFrequency(beam, 1.0e-4, 400);
    const double f_bernoulli = common::EulerBernoulliFrequency(cBeam);
    WARN("cantilever 40x4x4: free-vibration frequency "
         << f_dynamic << " Hz, Euler-Bernoulli " << f_bernoulli << " Hz (error "
         << 100.0 * (f_dynamic - f_bernoulli) / f_bernoulli << " %)");
    CHECK(std::abs(f_dynamic - f_bernoulli) / f_bernoulli < 0.08);
}
