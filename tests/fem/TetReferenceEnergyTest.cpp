// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// The divergence test's reference energy (TetSolverSettings::mDivergenceEnergyRatio) after an input change: a
// hit's impulse takes the elastic energy from the last step's force pass (the positions have not moved), new
// positions measure it again. A stale value would flag a sound step as diverged. (New anchors measure it
// again too, conservatively: a stale value there only loosens the test, which no step shows.)
#include "AnchorGridLayer.h"

#include <crumple/fem/TetGrid.h>
#include <crumple/fem/TetSolver.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <vector>

using namespace crumple;
using namespace crumple::fem;

namespace
{

// A 1 m steel bar of 10 x 2 x 2 cells, its x = 0 face anchored, without gravity, after one implicit step at
// rest (so its last force pass, with the energy of these positions, is cached).
TetSolver BarAtRest()
{
    TetGridSettings grid;
    grid.mSize = Vec3(1.0, 0.1, 0.1);
    grid.mCellCount = {10, 2, 2};
    FemMaterialSettings steel;
    steel.mYoungsModulus = 2.0e11;
    steel.mDensity = 7850.0;
    TetSolverSettings settings;
    settings.mGravity = Vec3::Zero();
    TetSolver bar = TetSolver::Create(TetGrid(grid).Get(), steel, settings).Get();
    test::AnchorGridLayer(bar, grid.mCellCount, 0);
    REQUIRE(bar.ApplyImpulse(TetGridNode(grid.mCellCount, 10, 1, 1), Vec3(0.0, 0.0, 1.0e-6)).IsValid());
    REQUIRE(bar.Step(1.0 / 60.0).IsValid());
    return bar;
}

bool DivergedOrSplit(const TetStepResult& inResult)
{
    return HasEvent(inResult.mEvents, ETetStepEvent::Diverged) ||
           HasEvent(inResult.mEvents, ETetStepEvent::Split);
}

} // namespace

TEST_CASE("Reference energy: new positions are measured again, not taken from the last step's pass", "[fem]")
{
    // Stretched by 0.1 % along the bar: 1 kJ of strain energy (E eps^2 V / 2), which the released bar's step
    // gives up. Against the last pass's energy at rest (zero) the step's energy would look like energy from
    // nowhere, and the step would be thrown away as diverged.
    TetSolver bar = BarAtRest();
    std::vector<Vec3> stretched = bar.GetPositions();
    for (Vec3& position : stretched)
        position.x() *= 1.001;
    REQUIRE(bar.SetPositions(stretched).IsValid());
    const TetStepResult result = bar.Step(1.0 / 60.0).Get();
    CHECK_FALSE(DivergedOrSplit(result));
    // The step kept what it did: the tip came back by most of its 1 mm stretch.
    double tip_stretch = 0.0;
    for (std::size_t node = 0; node < stretched.size(); ++node)
        tip_stretch =
            std::max(tip_stretch, bar.GetPositions()[node].x() - bar.GetMesh().GetRestPositions()[node].x());
    CHECK(tip_stretch < 0.5e-3);
}

TEST_CASE("Reference energy: the steps after hits take the last pass's energy and are kept", "[fem]")
{
    // A bar swinging back from a stretch, struck in its middle before each of five steps: each hit's
    // reference energy is the kinetic energy after the impulse plus the elastic energy of the last step's
    // pass; the steps are sound and none is thrown away.
    TetSolver bar = BarAtRest();
    std::vector<Vec3> stretched = bar.GetPositions();
    for (Vec3& position : stretched)
        position.x() *= 1.001;
    REQUIRE(bar.SetPositions(stretched).IsValid());
    REQUIRE(bar.Step(1.0 / 60.0).IsValid());
    for (int step = 0; step < 5; ++step)
    {
        REQUIRE(bar.ApplyImpulse(TetGridNode({10, 2, 2}, 5, 1, 1), Vec3(0.0, 0.0, 50.0)).IsValid());
        const TetStepResult hit = bar.Step(1.0 / 60.0).Get();
        CHECK_FALSE(DivergedOrSplit(hit));
        CHECK(hit.mKineticEnergy > 0.0);
    }
}
