// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// The links an implicit step opens are those of its converged solution: a wooden fence rail pushed hard at
// game steps cracks as a solve converged to round-off says, not as far as the Newton test happened to stop.
#include "PushedRail.h"

#include <crumple/fem/TetSolver.h>

#include <catch2/catch.hpp>

#include <cstdint>
#include <limits>
#include <vector>

using namespace crumple;
using namespace crumple::fem;

namespace
{

// The pushed rail (scenes/PushedRail.h) with inImpulse (N s) per push step; returns the broken links.
std::vector<std::uint8_t> PushRail(const TetSolverSettings& inSettings, double inImpulse)
{
    TetSolver solver = common::MakePushedRailSolver(inSettings).Get();
    const std::vector<int> struck = common::PushedRailNodes(solver.GetPositions());
    REQUIRE(struck.size() > 10u);
    for (int step = 0; step < common::cPushedRailSteps; ++step)
    {
        REQUIRE(common::PushRailBeforeStep(solver, struck, step, inImpulse).IsValid());
        REQUIRE(solver.Step(common::cPushedRailStep).IsValid());
    }
    return solver.GetBrokenLinks();
}

int Differing(const std::vector<std::uint8_t>& inA, const std::vector<std::uint8_t>& inB)
{
    REQUIRE(inA.size() == inB.size());
    int differing = 0;
    for (std::size_t link = 0; link < inA.size(); ++link)
        differing += inA[link] != inB[link] ? 1 : 0;
    return differing;
}

} // namespace

TEST_CASE("Fracture: the links an implicit step opens are those of its converged solution", "[fem]")
{
    // The Newton test relative to the step's kinetic energy stops early in a hit (the pushed nodes' energy is
    // large), and where a link whose stress lies near the strength cracks then depends on where it stopped.
    // The crack-safe bound (mCrackStressTolerance, default 0.5) goes on until no group's stress can be off by
    // more than half the strength. Measured (links broken in the reference; how many links differ from it):
    // 200 N s: 254; default 0, energy test alone 12. 300 N s: 455; default 2 (two steps stopped at the
    // Newton limit of 4), energy test alone 87. Bound: 1 % of the reference's links. At 600 N s and more the
    // rail shatters (1,800 links) and even 40 Newton iterations do not converge every step: no reference.
    TetSolverSettings reference;
    reference.mGravity = Vec3::Zero();
    reference.mImplicitTolerance = 1.0e-12;
    reference.mImplicitMaxIterations = 40;
    reference.mCgRelativeTolerance = 1.0e-10;
    reference.mCrackStressTolerance = std::numeric_limits<double>::infinity();
    TetSolverSettings defaults;
    defaults.mGravity = Vec3::Zero();
    TetSolverSettings energy_test_only = defaults;
    energy_test_only.mCrackStressTolerance = std::numeric_limits<double>::infinity();
    for (double impulse : {200.0, 300.0})
    {
        const std::vector<std::uint8_t> converged = PushRail(reference, impulse);
        int cracked = 0;
        for (std::uint8_t broken : converged)
            cracked += broken;
        const int with_bound = Differing(PushRail(defaults, impulse), converged);
        const int without = Differing(PushRail(energy_test_only, impulse), converged);
        INFO(impulse << " N s: " << cracked << " links cracked converged; the default differs in "
                     << with_bound << ", the energy test alone in " << without);
        REQUIRE(cracked > 100); // the push cracks the rail: the comparison is not vacuous
        CHECK(with_bound <= cracked / 100);
        CHECK(without > cracked / 100); // the case needs the bound
    }
}
