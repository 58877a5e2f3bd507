// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// A lattice too coarse to keep the car's occupant cell (plugin::FitOccupantCell) is warned of, refused by
// --strict, and the warning is true: such a car's full-wall crush moves its roof, the default lattice's not.
#include <crumple/crash/CrashRun.h>

#include <catch2/catch.hpp>

using namespace crumple;
using namespace crumple::crash;

namespace
{

// The scenario reader's default box car (4.2 m long: crush zones of 1.05 m) into a full wall at 56 km/h.
CrashScenario WallCrash()
{
    CrashScenario scenario;
    scenario.mName = "occupant cell";
    scenario.mVehicle.mMass = 1200.0;
    scenario.mImpact.mSpeed = 56.0 / 3.6;
    scenario.mDuration = 0.3;
    return scenario;
}

double Zone(const CrashOutcome& inOutcome, EZone inZone)
{
    return inOutcome.mResidualCrush[static_cast<std::size_t>(inZone)];
}

} // namespace

TEST_CASE("Occupant cell: a lattice too coarse to keep it is warned of and refused by --strict, and it moves "
          "the roof",
          "[crash]")
{
    CrashScenario coarse = WallCrash();
    coarse.mVehicle.mControlCount = {8, 8, 8}; // 0.84 m along the length, more than a quarter of 1.05 m
    const Result<CrashOutcome> warned = RunCrash(coarse, CrashRunOptions{});
    REQUIRE(warned.IsValid());
    REQUIRE(warned.Get().mWarnings.size() == 1);
    INFO(warned.Get().mWarnings[0]);
    CHECK(warned.Get().mWarnings[0].find("too coarse to keep its occupant cell") != std::string::npos);
    CHECK(warned.Get().mWarnings[0].find("control_spacing_m 0.263") != std::string::npos);
    // What it warns of: the crush reaches the roof (measured 0.297 m of a 0.447 m crush).
    CHECK(Zone(warned.Get(), EZone::Roof) > 0.25 * Zone(warned.Get(), EZone::Front));
    const Result<CrashOutcome> refused =
        RunCrash(coarse, CrashRunOptions{.mReplayFile = {}, .mStrict = true});
    REQUIRE(refused.HasError());
    CHECK(refused.GetError().mMessage.find("refused by --strict") != std::string::npos);

    // The default 0.15 m spacing keeps the cell: no warning, and the roof stays.
    const Result<CrashOutcome> fine =
        RunCrash(WallCrash(), CrashRunOptions{.mReplayFile = {}, .mStrict = true});
    REQUIRE(fine.IsValid());
    CHECK(fine.Get().mWarnings.empty());
    CHECK(Zone(fine.Get(), EZone::Front) > 0.3);
    CHECK(Zone(fine.Get(), EZone::Roof) <= 0.02 * Zone(fine.Get(), EZone::Front));
}

TEST_CASE("Occupant cell: a short body's fitted lattice is fine enough for its cell unless the scenario "
          "chose the spacing",
          "[crash]")
{
    // A 2 m car: crush zones of 0.5 m, so the default 0.15 m spacing (0.146 m fitted) loses the cell. Left to
    // the runner the fitted zone takes 0.125 m; given 0.15 m, the scenario's choice stands and is warned of.
    CrashScenario scenario = WallCrash();
    scenario.mVehicle.mBoxSize = Vec3(2.0, 1.2, 1.0);
    scenario.mVehicle.mMass = 300.0;
    const Result<CrashOutcome> fitted =
        RunCrash(scenario, CrashRunOptions{.mReplayFile = {}, .mStrict = true});
    REQUIRE(fitted.IsValid());
    CHECK(fitted.Get().mWarnings.empty());
    CHECK(Zone(fitted.Get(), EZone::Front) > 0.05);
    CHECK(Zone(fitted.Get(), EZone::Roof) <= 0.02 * Zone(fitted.Get(), EZone::Front));
    CHECK(Zone(fitted.Get(), EZone::Rear) <= 0.02 * Zone(fitted.Get(), EZone::Front));

    scenario.mVehicle.mControlSpacingGiven = true; // control_spacing_m 0.15 in the file
    const Result<CrashOutcome> chosen = RunCrash(scenario, CrashRunOptions{});
    REQUIRE(chosen.IsValid());
    REQUIRE(chosen.Get().mWarnings.size() == 1);
    CHECK(chosen.Get().mWarnings[0].find("control_spacing_m 0.125") != std::string::npos);
}
