// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// Plasticity in the solver: a free bar pulled past yield keeps the stretch of its plastic strain cap, one
// pulled below yield springs back; a cantilever bent past yield stays bent.
#include <crumple/fem/PlasticFlow.h>
#include <crumple/fem/TetGrid.h>
#include <crumple/fem/TetSolver.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <vector>

using namespace crumple;
using namespace crumple::fem;

namespace
{

constexpr double cLength = 1.0;   // m
constexpr double cSide = 0.1;     // m
constexpr double cYield = 1.0e5;  // Pa
constexpr double cCap = 0.02;     // equivalent plastic strain
constexpr double cStep = 1.0 / 60.0;

FemMaterialSettings SoftMetal(EElasticModel inModel)
{
    FemMaterialSettings material;
    material.mYoungsModulus = 1.0e8;
    material.mPoissonRatio = 0.3;
    material.mDensity = 1000.0;
    material.mMassDamping = 5.0;
    material.mYieldStress = cYield;
    material.mMaxPlasticStrain = cCap;
    material.mModel = inModel;
    return material;
}

struct Bar
{
    TetSolver mSolver;
    std::vector<int> mLow;  // nodes of the face x = 0
    std::vector<int> mHigh; // nodes of the face x = L
};

Bar MakeBar(EElasticModel inModel)
{
    TetGridSettings grid;
    grid.mSize = Vec3(cLength, cSide, cSide);
    grid.mCellCount = {10, 1, 1};
    TetSolverSettings settings;
    settings.mGravity = Vec3::Zero();
    settings.mSleepSpeed = 0.0; // never asleep: "stays as it is" must be the material's doing
    Bar bar{TetSolver::Create(TetGrid(grid).Get(), SoftMetal(inModel), settings).Get(), {}, {}};
    for (int k = 0; k <= 1; ++k)
        for (int j = 0; j <= 1; ++j)
        {
            bar.mLow.push_back(TetGridNode(grid.mCellCount, 0, j, k));
            bar.mHigh.push_back(TetGridNode(grid.mCellCount, 10, j, k));
        }
    return bar;
}

// Distance between the end faces' centroids minus the rest length (m).
double Elongation(const TetSolver& inSolver, const Bar& inBar)
{
    double low = 0.0, high = 0.0;
    for (int node : inBar.mLow)
        low += inSolver.GetPositions()[node].x() / 4.0;
    for (int node : inBar.mHigh)
        high += inSolver.GetPositions()[node].x() / 4.0;
    return high - low - cLength;
}

// Equal and opposite axial forces of total inForce (N) on the two end faces.
void Pull(Bar& ioBar, double inForce)
{
    for (int node : ioBar.mLow)
        REQUIRE(ioBar.mSolver.SetExternalForce(node, Vec3(-inForce / 4.0, 0.0, 0.0)).IsValid());
    for (int node : ioBar.mHigh)
        REQUIRE(ioBar.mSolver.SetExternalForce(node, Vec3(inForce / 4.0, 0.0, 0.0)).IsValid());
}

// Ramps the pull up to inPeak, holds it, ramps it down and lets the bar settle (implicit Euler).
void LoadCycle(Bar& ioBar, double inPeak)
{
    for (int step = 1; step <= 240; ++step)
    {
        const double ramp = step <= 30 ? step / 30.0 : step <= 150 ? 1.0 : step <= 180 ? (180 - step) / 30.0 : 0.0;
        Pull(ioBar, ramp * inPeak);
        const Result<TetStepResult> result = ioBar.mSolver.Step(cStep);
        REQUIRE(result.IsValid());
        REQUIRE_FALSE(HasEvent(result.Get().mEvents, ETetStepEvent::Diverged));
    }
}

} // namespace

TEST_CASE("A bar pulled past yield keeps a permanent stretch of its plastic strain cap", "[fem]")
{
    // Uniaxial stress F / A = 2 sigma_y: the bar flows until the equivalent plastic strain reaches the cap
    // (uniaxial plastic strain e diag(1, -1/2, -1/2) has equivalent strain e), then unloads elastically to a
    // residual elongation of cap x L, whatever the elasticity model.
    const EElasticModel model = GENERATE(EElasticModel::CorotatedLinear, EElasticModel::StVenantKirchhoff);
    CAPTURE(ToString(model));
    Bar bar = MakeBar(model);
    LoadCycle(bar, 2.0 * cYield * cSide * cSide);

    const double residual = Elongation(bar.mSolver, bar);
    CHECK(residual == Approx(cCap * cLength).epsilon(0.02));
    for (const Mat3& plastic : bar.mSolver.GetPlasticStrains())
    {
        CHECK(EquivalentPlasticStrain(plastic) == Approx(cCap).epsilon(0.05));
        CHECK(std::abs(plastic.trace()) < 1e-12); // plastic flow keeps the volume
    }
    // Unloaded and at rest, it stays as it is.
    for (int step = 0; step < 60; ++step)
        REQUIRE(bar.mSolver.Step(cStep).IsValid());
    CHECK(Elongation(bar.mSolver, bar) == Approx(residual).epsilon(1e-6));
}

TEST_CASE("A bar pulled below yield springs back and accumulates no plastic strain", "[fem]")
{
    Bar bar = MakeBar(EElasticModel::CorotatedLinear);
    LoadCycle(bar, 0.5 * cYield * cSide * cSide);
    CHECK(std::abs(Elongation(bar.mSolver, bar)) < 1e-7);
    for (const Mat3& plastic : bar.mSolver.GetPlasticStrains())
        CHECK(plastic == Mat3::Zero());
}

TEST_CASE("A cantilever barrier bent past yield stays bent, an elastic one straightens", "[fem]")
{
    // Root bending stress of a tip load P: M c / I = 6 P L / a^3 for a square section of side a.
    TetGridSettings grid;
    grid.mSize = Vec3(cLength, cSide, cSide);
    grid.mCellCount = {10, 1, 1};
    const double yield_load = cYield * cSide * cSide * cSide / (6.0 * cLength); // N

    auto residual_deflection = [&](double inYieldStress)
    {
        FemMaterialSettings material = SoftMetal(EElasticModel::CorotatedLinear);
        material.mYieldStress = inYieldStress;
        material.mMaxPlasticStrain = 0.5;
        TetSolverSettings settings;
        settings.mGravity = Vec3::Zero();
        TetSolver solver = TetSolver::Create(TetGrid(grid).Get(), material, settings).Get();
        std::vector<int> tip;
        for (int k = 0; k <= 1; ++k)
            for (int j = 0; j <= 1; ++j)
            {
                REQUIRE(solver.SetNodeFixed(TetGridNode(grid.mCellCount, 0, j, k), true).IsValid());
                tip.push_back(TetGridNode(grid.mCellCount, 10, j, k));
            }
        for (int step = 1; step <= 240; ++step)
        {
            const double ramp = step <= 30 ? step / 30.0 : step <= 150 ? 1.0 : step <= 180 ? (180 - step) / 30.0 : 0.0;
            for (int node : tip)
                REQUIRE(solver.SetExternalForce(node, Vec3(0.0, 0.0, -3.0 * yield_load * ramp / 4.0)).IsValid());
            REQUIRE(solver.Step(cStep).IsValid());
        }
        double deflection = 0.0;
        for (int node : tip)
            deflection += (solver.GetNodeRestPositions()[node] - solver.GetPositions()[node]).z() / 4.0;
        return deflection;
    };

    const double plastic = residual_deflection(cYield);
    const double elastic = residual_deflection(std::numeric_limits<double>::infinity());
    INFO("residual tip deflection: plastic " << plastic << " m, elastic " << elastic << " m");
    CHECK(plastic > 0.01);              // visibly bent: over 1 cm on a 1 m barrier
    CHECK(std::abs(elastic) < 1.0e-6);  // springs back
}
