// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// The steel cantilever of the FEM issue: 1 m x 0.1 m x 0.1 m, E = 200 GPa, nu = 0.3, rho = 7850 kg/m^3,
// clamped at x = 0 (every node of that face anchored), 1 kN downwards at the tip spread over the tip face by
// area.
#include <crumple/fem/TetGrid.h>
#include <crumple/fem/TetSolver.h>

#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>

using namespace crumple;
using namespace crumple::fem;

namespace
{

constexpr double cLength = 1.0;
constexpr double cSide = 0.1;
constexpr double cYoung = 200.0e9;
constexpr double cPoisson = 0.3;
constexpr double cDensity = 7850.0;
constexpr double cLoad = 1000.0;
constexpr double cPi = 3.14159265358979323846;

/// Timoshenko tip deflection PL^3 / (3EI) + PL / (kappa G A), kappa = 5/6 (m).
double TimoshenkoDeflection()
{
    const double inertia = cSide * cSide * cSide * cSide / 12.0;
    const double shear = cYoung / (2.0 * (1.0 + cPoisson));
    return cLoad * cLength * cLength * cLength / (3.0 * cYoung * inertia) +
           cLoad * cLength / (5.0 / 6.0 * shear * cSide * cSide);
}

/// Euler-Bernoulli first bending frequency (1.8751^2 / 2 pi) sqrt(EI / (rho A L^4)) (Hz).
double EulerBernoulliFrequency()
{
    const double inertia = cSide * cSide * cSide * cSide / 12.0;
    const double beta = 1.875104069;
    return beta * beta / (2.0 * cPi) *
           std::sqrt(cYoung * inertia / (cDensity * cSide * cSide * cLength * cLength * cLength * cLength));
}

/// Dunkerley combination of the Euler-Bernoulli frequency with that of a pure shear cantilever,
/// 1/f^2 = 1/f_EB^2 + 1/f_s^2, f_s = sqrt(kappa G / rho) / (4 L): an estimate of the Timoshenko frequency
/// (Hz).
double ShearCorrectedFrequency()
{
    const double shear = cYoung / (2.0 * (1.0 + cPoisson));
    const double f_shear = std::sqrt(5.0 / 6.0 * shear / cDensity) / (4.0 * cLength);
    const double f_bending = EulerBernoulliFrequency();
    return 1.0 / std::sqrt(1.0 / (f_bending * f_bending) + 1.0 / (f_shear * f_shear));
}

struct Cantilever
{
    TetSolver mSolver;
    std::vector<int> mTip;        // tip-face nodes
    std::vector<double> mWeights; // their area weights, summing to 1
};

/// A cantilever of inLengthCells x inSectionCells x inSectionCells five-tet cells, undamped, no gravity, tip
/// load set.
Cantilever MakeCantilever(int inLengthCells, int inSectionCells, EIntegrator inIntegrator)
{
    TetGridSettings grid;
    grid.mSize = Vec3(cLength, cSide, cSide);
    grid.mCellCount = {inLengthCells, inSectionCells, inSectionCells};
    FemMaterialSettings steel;
    steel.mYoungsModulus = cYoung;
    steel.mPoissonRatio = cPoisson;
    steel.mDensity = cDensity;
    TetSolverSettings settings;
    settings.mIntegrator = inIntegrator;
    settings.mGravity = Vec3::Zero();
    settings.mMaxSubSteps = 1000000;
    settings.mSleepSpeed = 0.0;
    Cantilever beam{TetSolver::Create(TetGrid(grid).Get(), steel, settings).Get(), {}, {}};

    // Clamp x = 0; the tip load by trapezoidal area weights over the tip face.
    const int n = inSectionCells;
    for (int k = 0; k <= n; ++k)
        for (int j = 0; j <= n; ++j)
        {
            REQUIRE(beam.mSolver.SetNodeFixed(TetGridNode(grid.mCellCount, 0, j, k), true).IsValid());
            beam.mTip.push_back(TetGridNode(grid.mCellCount, inLengthCells, j, k));
            beam.mWeights.push_back((j == 0 || j == n ? 0.5 : 1.0) * (k == 0 || k == n ? 0.5 : 1.0) /
                                    (n * n));
        }
    for (std::size_t i = 0; i < beam.mTip.size(); ++i)
        REQUIRE(
            beam.mSolver.SetExternalForce(beam.mTip[i], Vec3(0.0, 0.0, -cLoad * beam.mWeights[i])).IsValid());
    return beam;
}

/// Area-weighted mean vertical displacement of the tip face (m, positive down).
double TipDeflection(const Cantilever& inBeam)
{
    double deflection = 0.0;
    for (std::size_t i = 0; i < inBeam.mTip.size(); ++i)
    {
        const int node = inBeam.mTip[i];
        deflection -= inBeam.mWeights[i] * (inBeam.mSolver.GetPositions()[node].z() -
                                            inBeam.mSolver.GetMesh().GetRestPositions()[node].z());
    }
    return deflection;
}

/// The FE model's first eigenfrequency (Hz, lumped mass) by inverse iteration from the static tip-load shape,
/// each iteration a SolveStatic under the load M u; the Rayleigh quotient of the last iterate.
double InverseIterationFrequency(Cantilever& ioBeam, int inIterations)
{
    TetSolver& solver = ioBeam.mSolver;
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
double FreeVibrationFrequency(Cantilever& ioBeam, double inFrameTime, int inFrames)
{
    TetSolver& solver = ioBeam.mSolver;
    solver.ClearExternalForces();
    std::vector<double> crossings;
    double previous = TipDeflection(ioBeam);
    for (int frame = 1; frame <= inFrames && crossings.size() < 3; ++frame)
    {
        Result<TetStepResult> step = solver.Step(inFrameTime);
        REQUIRE(step.IsValid());
        REQUIRE(step.Get().mEvents == ETetStepEvent::None);
        const double deflection = TipDeflection(ioBeam);
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
    const double reference = TimoshenkoDeflection(); // 2.0156e-4 m
    const int sections[] = {1, 2, 4, 8};
    double previous_error = 1.0;
    for (int section : sections)
    {
        const auto start = std::chrono::steady_clock::now();
        Cantilever beam = MakeCantilever(10 * section, section, EIntegrator::ImplicitEuler);
        Result<TetStaticResult> result = beam.mSolver.SolveStatic();
        REQUIRE(result.IsValid());
        const double deflection = TipDeflection(beam);
        const double error = (deflection - reference) / reference;
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        WARN("cantilever " << 10 * section << "x" << section << "x" << section << " cells ("
                           << beam.mSolver.GetMesh().GetTetCount() << " tets): tip deflection " << deflection
                           << " m, Timoshenko " << reference << " m, error " << 100.0 * error << " % ("
                           << result.Get().mSolverIterations << " CG iterations, " << seconds << " s)");
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
    Cantilever fine = MakeCantilever(80, 8, EIntegrator::ImplicitEuler);
    REQUIRE(fine.mSolver.SolveStatic().IsValid());
    const double f_fine = InverseIterationFrequency(fine, 2);
    const double f_bernoulli = EulerBernoulliFrequency(); // 81.5 Hz
    const double f_shear = ShearCorrectedFrequency();     // 81.0 Hz
    const double error = (f_fine - f_bernoulli) / f_bernoulli;
    WARN("cantilever 80x8x8 first frequency "
         << f_fine << " Hz; Euler-Bernoulli " << f_bernoulli << " Hz (error " << 100.0 * error
         << " %), shear-corrected " << f_shear << " Hz (error " << 100.0 * (f_fine - f_shear) / f_shear
         << " %)");
    CHECK(std::abs(error) < 0.05);

    // The dynamics agree with the stiffness: the free vibration of the 20 x 2 x 2 mesh under symplectic Euler
    // has the frequency the inverse iteration finds for that mesh.
    Cantilever coarse = MakeCantilever(20, 2, EIntegrator::SymplecticEuler);
    REQUIRE(coarse.mSolver.SolveStatic().IsValid());
    const std::vector<Vec3> released = coarse.mSolver.GetPositions();
    Cantilever coarse_modal = MakeCantilever(20, 2, EIntegrator::ImplicitEuler);
    REQUIRE(coarse_modal.mSolver.SolveStatic().IsValid());
    const double f_modal = InverseIterationFrequency(coarse_modal, 3);
    REQUIRE(coarse.mSolver.SetPositions(released).IsValid());
    const double f_dynamic = FreeVibrationFrequency(coarse, 1.0e-4, 400);
    WARN("cantilever 20x2x2: free-vibration frequency " << f_dynamic << " Hz, inverse iteration " << f_modal
                                                        << " Hz, Euler-Bernoulli " << f_bernoulli << " Hz");
    CHECK(f_dynamic == Approx(f_modal).epsilon(0.01));
}

TEST_CASE("Cantilever: free vibration of the 40 x 4 x 4 mesh", "[fem][slow][.]")
{
    // Symplectic Euler over two periods (~23 ms) at the stable sub-step of 0.025 m steel cells (0.78 us):
    // ~30,000 sub-steps of 3,200 elements, about 15 s, hence hidden ([.]) and tagged [slow]: run it with
    // test_fem "[slow]".
    Cantilever beam = MakeCantilever(40, 4, EIntegrator::SymplecticEuler);
    REQUIRE(beam.mSolver.SolveStatic().IsValid());
    const double f_dynamic = FreeVibrationFrequency(beam, 1.0e-4, 400);
    const double f_bernoulli = EulerBernoulliFrequency();
    WARN("cantilever 40x4x4: free-vibration frequency "
         << f_dynamic << " Hz, Euler-Bernoulli " << f_bernoulli << " Hz (error "
         << 100.0 * (f_dynamic - f_bernoulli) / f_bernoulli << " %)");
    CHECK(std::abs(f_dynamic - f_bernoulli) / f_bernoulli < 0.08);
}
