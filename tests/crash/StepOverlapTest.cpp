// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// The step-overlap warning against closed forms: how far the car closes per engine step against how far it
// overlaps its target across its path, for each target type; and a run in both engines that shows why it
// matters (a 5 % offset wall at 1/120 s is slid past, at 1/1000 s it crushes the car).
#include <crumple/crash/CrashRun.h>
#include <crumple/crash/StepOverlap.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

using namespace crumple;
using namespace crumple::crash;

namespace
{

// The scenario reader's default box car (4.2 x 1.8 x 1.4 m) at 64 km/h, stepped at 1/120 s.
CrashScenario Car(ETarget inTarget)
{
    CrashScenario scenario;
    scenario.mName = "step overlap";
    scenario.mVehicle.mMass = 1200.0;
    scenario.mImpact.mSpeed = 64.0 / 3.6;
    scenario.mTimeStep = 1.0 / 120.0;
    scenario.mTarget.mType = inTarget;
    return scenario;
}

const Vec3 cHalf(2.1, 0.9, 0.7);

} // namespace

TEST_CASE("Step overlap: an offset wall's covered share against the closing per step", "[crash]")
{
    CrashScenario scenario = Car(ETarget::OffsetWall);
    scenario.mTarget.mOverlapPercent = 5.0;
    StepOverlap step = MeasureStepOverlap(scenario, cHalf);
    CHECK(step.mOverlap == Approx(0.05 * 1.8));
    CHECK(step.mClosingPerStep == Approx(64.0 / 3.6 / 120.0));
    CHECK(step.IsTooCoarse());
    const std::string warning = StepOverlapWarning(scenario, step);
    INFO(warning);
    CHECK(warning.find("0.148 m") != std::string::npos);
    CHECK(warning.find("0.09 m") != std::string::npos);
    // The step it advises closes half the overlap.
    CHECK(warning.find("time_step_s 0.0025 s or less") != std::string::npos);

    scenario.mTimeStep = 0.001;
    CHECK_FALSE(MeasureStepOverlap(scenario, cHalf).IsTooCoarse());
    CHECK(StepOverlapWarning(scenario, MeasureStepOverlap(scenario, cHalf)).empty());
    // The 40 % offset test at the default step overlaps 0.72 m.
    scenario.mTimeStep = 1.0 / 120.0;
    scenario.mTarget.mOverlapPercent = 40.0;
    CHECK(MeasureStepOverlap(scenario, cHalf).mOverlap == Approx(0.72));
    CHECK_FALSE(MeasureStepOverlap(scenario, cHalf).IsTooCoarse());
}

TEST_CASE("Step overlap: a pole, centred, at the car's edge, and broadside", "[crash]")
{
    CrashScenario scenario = Car(ETarget::Pole);
    scenario.mTarget.mPoleRadius = 0.127;
    CHECK(MeasureStepOverlap(scenario, cHalf).mOverlap == Approx(0.9 + 0.127));
    // Its centre 0.85 m to the side: the car's left edge passes 0.05 m beside it, 0.177 m of overlap; 0.95 m:
    // 0.077 m, less than the 0.148 m the car closes per step.
    scenario.mImpact.mOffset = -0.85;
    CHECK(MeasureStepOverlap(scenario, cHalf).mOverlap == Approx(0.177));
    CHECK_FALSE(MeasureStepOverlap(scenario, cHalf).IsTooCoarse());
    scenario.mImpact.mOffset = -0.95;
    CHECK(MeasureStepOverlap(scenario, cHalf).mOverlap == Approx(0.077));
    CHECK(MeasureStepOverlap(scenario, cHalf).IsTooCoarse());
    // Past the pole: nothing to warn of.
    scenario.mImpact.mOffset = -1.2;
    CHECK(MeasureStepOverlap(scenario, cHalf).mOverlap < 0.0);
    CHECK_FALSE(MeasureStepOverlap(scenario, cHalf).IsTooCoarse());
    // Broadside (a side-pole test): the car's length is across the path.
    scenario.mImpact.mOffset = 0.0;
    scenario.mImpact.mHeadingDegrees = 90.0;
    CHECK(MeasureStepOverlap(scenario, cHalf).mOverlap == Approx(2.1 + 0.127));
}

TEST_CASE("Step overlap: another car closes at the two speeds' difference along the path", "[crash]")
{
    CrashScenario scenario = Car(ETarget::Vehicle);
    scenario.mTarget.mVehicleSize = Vec3(4.4, 1.7, 1.4);
    scenario.mTarget.mVehicleHeadingDegrees = 180.0; // head-on
    scenario.mTarget.mVehicleSpeed = 64.0 / 3.6;
    scenario.mTarget.mVehicleOffset = 1.7; // 0.1 m of the two fronts overlap
    const StepOverlap head_on = MeasureStepOverlap(scenario, cHalf);
    CHECK(head_on.mClosingPerStep == Approx(2.0 * 64.0 / 3.6 / 120.0));
    CHECK(head_on.mOverlap == Approx(0.9 + 0.85 - 1.7));
    CHECK(head_on.IsTooCoarse());
    // Standing broadside in the path (a side impact): its length across, the car's speed alone.
    scenario.mTarget.mVehicleHeadingDegrees = 90.0;
    scenario.mTarget.mVehicleSpeed = 0.0;
    scenario.mTarget.mVehicleOffset = 0.0;
    const StepOverlap side = MeasureStepOverlap(scenario, cHalf);
    CHECK(side.mClosingPerStep == Approx(64.0 / 3.6 / 120.0));
    CHECK(side.mOverlap == Approx(0.9 + 2.2));
}

TEST_CASE("Step overlap: a wall across the path has no sideways way round it", "[crash]")
{
    CrashScenario scenario = Car(ETarget::RigidWall);
    scenario.mImpact.mSpeed = 1000.0;
    scenario.mTarget.mAngleDegrees = 60.0;
    const StepOverlap step = MeasureStepOverlap(scenario, cHalf);
    CHECK(step.mOverlap == std::numeric_limits<double>::infinity());
    CHECK_FALSE(step.IsTooCoarse());
}

TEST_CASE("Step overlap: a 5 % offset wall at 1/120 s is slid past in both engines, warned of and refused by "
          "--strict",
          "[crash]")
{
    for (const EEngine engine : {EEngine::Bullet, EEngine::Ode})
    {
        CAPTURE(static_cast<int>(engine));
        CrashScenario scenario = Car(ETarget::OffsetWall);
        scenario.mEngine = engine;
        scenario.mTarget.mOverlapPercent = 5.0;
        scenario.mDuration = 0.3;
        const Result<CrashOutcome> coarse = RunCrash(scenario, CrashRunOptions{});
        REQUIRE(coarse.IsValid());
        // What the warning is about: no collision reached Crumple, the car went past.
        CHECK(coarse.Get().mCollisions.empty());
        // The step's warning before the run, then the run's own: it met nothing.
        REQUIRE(coarse.Get().mWarnings.size() == 2);
        CHECK(coarse.Get().mWarnings[0].find("push it aside") != std::string::npos);
        CHECK(coarse.Get().mWarnings[1].find("the car met nothing") != std::string::npos);
        const Result<CrashOutcome> strict =
            RunCrash(scenario, CrashRunOptions{.mReplayFile = {}, .mStrict = true});
        REQUIRE(strict.HasError());
        CHECK(strict.GetError().mMessage.find("refused by --strict") != std::string::npos);
        // At the step the warning advises the car meets the wall and its front crushes.
        scenario.mTimeStep = 0.0025;
        const Result<CrashOutcome> fine =
            RunCrash(scenario, CrashRunOptions{.mReplayFile = {}, .mStrict = true});
        REQUIRE(fine.IsValid());
        CHECK(fine.Get().mWarnings.empty());
        CHECK_FALSE(fine.Get().mCollisions.empty());
        CHECK(fine.Get().mResidualCrush[static_cast<int>(EZone::Front)] > 0.3);
    }
}
