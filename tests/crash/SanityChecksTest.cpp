// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// The impulse_momentum sanity check on outcomes made by hand: what an engine can do that no shipped scene
// does any more (ODE's Dantzig step once stopped a 1,000 km/h car inside the wall without a contact reaching
// Crumple; its quick step lets it through, which no_tunnelling catches).
#include <crumple/crash/SanityChecks.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace crumple;
using namespace crumple::crash;

namespace
{

SanityResult Find(const std::vector<SanityResult>& inResults, const std::string& inName)
{
    const auto found = std::find_if(inResults.begin(), inResults.end(), [&](const SanityResult& r) { return r.mName == inName; });
    REQUIRE(found != inResults.end());
    return *found;
}

// A 1,200 kg car that drove 0.3 s at 15 m/s along x and ended at inEndSpeed, without any collision.
CrashOutcome NoCollision(double inEndSpeed)
{
    CrashOutcome outcome;
    outcome.mMass = 1200.0;
    outcome.mStartVelocity = Vec3(15.0, 0.0, 0.0);
    outcome.mEndVelocity = Vec3(inEndSpeed, 0.0, 0.0);
    for (int step = 0; step <= 36; ++step)
        outcome.mHistory.push_back(CarSample{step / 120.0, Vec3(15.0 * step / 120.0, 0.0, 0.7), step == 36 ? outcome.mEndVelocity : outcome.mStartVelocity});
    return outcome;
}

} // namespace

TEST_CASE("Sanity: a car the engine stopped with no collision reaching Crumple fails impulse_momentum, and names it", "[crash]")
{
    CrashScenario scenario;
    scenario.mImpulseTolerance = 0.05;
    const SanityResult stopped = Find(CheckSanity(scenario, NoCollision(3.0)), "impulse_momentum");
    INFO(stopped.mDetail);
    CHECK_FALSE(stopped.mPassed);
    CHECK(stopped.mValue == Approx(0.8));
    CHECK(stopped.mDetail.find("no collision reached Crumple") != std::string::npos);
    // Rolling resistance's share of a run, under the tolerance, passes.
    const SanityResult rolled = Find(CheckSanity(scenario, NoCollision(14.9)), "impulse_momentum");
    CHECK(rolled.mPassed);
}
