// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// TetStepper: the step policy both tetrahedral backends share, driven through a scripted backend that records
// what the policy asked of it.
#include <crumple/fem/TetStepper.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

using namespace crumple;
using namespace crumple::fem;

namespace
{

// A backend whose attempts diverge while fewer than mPiecesNeeded pieces are asked for, with a scripted
// kinetic energy; every call is logged.
struct ScriptedBackend final : TetStepBackend
{
    int mSubSteps = 3;             // what SubStepsFor answers (explicit) or 1 (implicit)
    bool mExplicit = true;
    int mPiecesNeeded = 1;         // attempts with fewer pieces diverge
    double mKinetic = 1.0;         // J after a successful attempt
    int mBrokenLinks = 0, mPlastic = 0;
    bool mRefuseSave = false;
    bool mAtRest = false;
    std::vector<std::string> mCalls;
    std::vector<int> mPieces;      // of each attempt

    Result<int> SubStepsFor(double) const override { return mExplicit ? mSubSteps : 1; }
    bool IsExplicit() const override { return mExplicit; }
    Status SaveStepStart() override
    {
        mCalls.push_back("save");
        if (mRefuseSave)
            return MakeError(EError::InvalidArgument, "no device");
        return Status::Ok();
    }
    void RestoreStepStart() override { mCalls.push_back("restore"); }
    TetStepAttempt Attempt(double, int inPieces, TetStepResult& ioResult) override
    {
        mCalls.push_back("attempt");
        mPieces.push_back(inPieces);
        ++ioResult.mNewtonIterations; // statistics of every attempt count
        TetStepAttempt attempt;
        attempt.mDiverged = inPieces < mPiecesNeeded;
        attempt.mKineticEnergy = mKinetic;
        attempt.mEnergy = 2.0 * mKinetic;
        attempt.mBrokenLinks = mBrokenLinks;
        attempt.mPlasticElements = mPlastic;
        return attempt;
    }
    void DescribeRestored(TetStepResult& ioResult) const override { ioResult.mEnergy = -1.0; }
    bool IsAtRestUnloaded() const override { return mAtRest; }
    double FreeMass() const override { return 2.0; } // sleep below 1/2 * 2 kg * (1e-3 m/s)^2 = 1e-6 J
    void FallAsleep() override { mCalls.push_back("asleep"); }
};

TetSolverSettings Settings()
{
    TetSolverSettings settings;
    settings.mMaxStepSplits = 3;
    settings.mMaxSubSteps = 20;
    settings.mSleepSpeed = 1.0e-3;
    settings.mSleepStepCount = 3;
    return settings;
}

} // namespace

TEST_CASE("TetStepper refuses a bad step before its backend changes anything", "[fem]")
{
    TetStepper stepper;
    ScriptedBackend backend;
    for (const double bad : {0.0, -0.01, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
    {
        const Result<TetStepResult> step = stepper.Step(backend, Settings(), bad, "Scripted");
        REQUIRE_FALSE(step.IsValid());
        CHECK(step.GetError().mMessage.rfind("Scripted::Step: time step", 0) == 0);
    }
    TetSolverSettings bad = Settings();
    bad.mMaxStepSplits = 40; // 2^40 pieces: refused, not shifted past an int
    CHECK(stepper.Step(backend, bad, 0.01, "Scripted").GetError().mCode == EError::InvalidArgument);
    bad = Settings();
    bad.mSleepStepCount = 0;
    CHECK(stepper.Step(backend, bad, 0.01, "Scripted").GetError().mCode == EError::InvalidArgument);
    CHECK(backend.mCalls.empty());
    backend.mRefuseSave = true;
    CHECK(stepper.Step(backend, Settings(), 0.01, "Scripted").GetError().mMessage == "no device");
    CHECK(backend.mCalls == std::vector<std::string>{"save"});
}

TEST_CASE("TetStepper does not try a given-up step again from the same start until an input changes", "[fem]")
{
    TetStepper stepper;
    ScriptedBackend backend;
    backend.mExplicit = false;
    backend.mPiecesNeeded = 100; // every attempt diverges
    TetStepResult result = stepper.Step(backend, Settings(), 0.01, "Scripted").Get();
    REQUIRE(HasEvent(result.mEvents, ETetStepEvent::Diverged));
    REQUIRE(backend.mPieces == std::vector<int>{1, 2, 4, 8});
    // The same step from the same start: reported diverged at once, no attempt, nothing saved or restored.
    const std::size_t calls = backend.mCalls.size();
    for (int step = 0; step < 3; ++step)
    {
        result = stepper.Step(backend, Settings(), 0.01, "Scripted").Get();
        CHECK(result.mEvents == ETetStepEvent::Diverged);
        CHECK(result.mNewtonIterations == 0);
        CHECK(result.mEnergy == -1.0); // the restored start's, from the backend
    }
    CHECK(backend.mCalls.size() == calls);
    // A step of another length is tried; so is the same one once an input changed.
    REQUIRE(stepper.Step(backend, Settings(), 0.005, "Scripted").IsValid());
    CHECK(backend.mPieces.size() == 8);
    REQUIRE(stepper.Step(backend, Settings(), 0.005, "Scripted").IsValid());
    CHECK(backend.mPieces.size() == 8);
    stepper.Wake();
    backend.mPiecesNeeded = 2;
    result = stepper.Step(backend, Settings(), 0.005, "Scripted").Get();
    CHECK_FALSE(HasEvent(result.mEvents, ETetStepEvent::Diverged));
    CHECK(backend.mPieces.size() == 10);
    // After a step that went through, a diverged one is tried in full again.
    backend.mPiecesNeeded = 100;
    REQUIRE(stepper.Step(backend, Settings(), 0.005, "Scripted").IsValid());
    CHECK(backend.mPieces.size() == 14);
}

TEST_CASE("TetStepper retries a diverged step in 2, 4, ... pieces from its saved start", "[fem]")
{
    SECTION("explicit: the sub-steps double, within the sub-step budget")
    {
        TetStepper stepper;
        ScriptedBackend backend;
        backend.mPiecesNeeded = 12; // 3 and 6 diverge, 12 does not
        const TetStepResult result = stepper.Step(backend, Settings(), 0.01, "Scripted").Get();
        CHECK(backend.mPieces == std::vector<int>{3, 6, 12});
        CHECK(backend.mCalls == std::vector<std::string>{"save", "attempt", "restore", "attempt", "restore", "attempt"});
        CHECK(result.mSubSteps == 12);
        CHECK(result.mNewtonIterations == 3);
        CHECK(HasEvent(result.mEvents, ETetStepEvent::Split));
        CHECK_FALSE(HasEvent(result.mEvents, ETetStepEvent::Diverged));
        CHECK(result.mKineticEnergy == 1.0);
        CHECK(result.mEnergy == 2.0);
    }
    SECTION("explicit: past the budget (24 > 20 sub-steps) the step is given up and restored")
    {
        TetStepper stepper;
        ScriptedBackend backend;
        backend.mPiecesNeeded = 24;
        backend.mBrokenLinks = 5;
        const TetStepResult result = stepper.Step(backend, Settings(), 0.01, "Scripted").Get();
        CHECK(backend.mPieces == std::vector<int>{3, 6, 12});
        CHECK(backend.mCalls.back() == "restore");
        CHECK(HasEvent(result.mEvents, ETetStepEvent::Diverged));
        CHECK_FALSE(HasEvent(result.mEvents, ETetStepEvent::Fractured)); // a restored step broke nothing
        CHECK(result.mBrokenLinks == 0);
        CHECK(result.mEnergy == -1.0); // the restored start's, from the backend
    }
    SECTION("implicit: 1, 2, 4, 8 pieces (mMaxStepSplits 3), then given up")
    {
        TetStepper stepper;
        ScriptedBackend backend;
        backend.mExplicit = false;
        backend.mPiecesNeeded = 100;
        const TetStepResult result = stepper.Step(backend, Settings(), 0.01, "Scripted").Get();
        CHECK(backend.mPieces == std::vector<int>{1, 2, 4, 8});
        CHECK(HasEvent(result.mEvents, ETetStepEvent::Diverged));
        CHECK(HasEvent(result.mEvents, ETetStepEvent::Split));
    }
}

TEST_CASE("TetStepper reports cracks and flow, and puts a quiet solver to sleep until it is woken", "[fem]")
{
    TetStepper stepper;
    ScriptedBackend backend;
    backend.mBrokenLinks = 2;
    backend.mPlastic = 7;
    const TetStepResult loud = stepper.Step(backend, Settings(), 0.01, "Scripted").Get();
    CHECK(HasEvent(loud.mEvents, ETetStepEvent::Fractured));
    CHECK(HasEvent(loud.mEvents, ETetStepEvent::Yielded));
    CHECK(loud.mBrokenLinks == 2);
    CHECK(loud.mPlasticElements == 7);

    // Three quiet steps (mSleepStepCount) put it to sleep; a fast or a cracking one in between starts the count
    // again.
    backend.mBrokenLinks = backend.mPlastic = 0;
    backend.mKinetic = 0.5e-6;
    CHECK_FALSE(HasEvent(stepper.Step(backend, Settings(), 0.01, "Scripted").Get().mEvents, ETetStepEvent::FellAsleep));
    CHECK_FALSE(HasEvent(stepper.Step(backend, Settings(), 0.01, "Scripted").Get().mEvents, ETetStepEvent::FellAsleep));
    backend.mKinetic = 2.0e-6;
    CHECK_FALSE(HasEvent(stepper.Step(backend, Settings(), 0.01, "Scripted").Get().mEvents, ETetStepEvent::FellAsleep));
    backend.mKinetic = 0.5e-6;
    CHECK_FALSE(HasEvent(stepper.Step(backend, Settings(), 0.01, "Scripted").Get().mEvents, ETetStepEvent::FellAsleep));
    backend.mBrokenLinks = 1; // slow, but cracking: not quiet
    CHECK_FALSE(HasEvent(stepper.Step(backend, Settings(), 0.01, "Scripted").Get().mEvents, ETetStepEvent::FellAsleep));
    backend.mBrokenLinks = 0;
    for (int step = 0; step < 2; ++step)
        CHECK_FALSE(HasEvent(stepper.Step(backend, Settings(), 0.01, "Scripted").Get().mEvents, ETetStepEvent::FellAsleep));
    CHECK(HasEvent(stepper.Step(backend, Settings(), 0.01, "Scripted").Get().mEvents, ETetStepEvent::FellAsleep));
    CHECK(stepper.IsSleeping());
    CHECK(backend.mCalls.back() == "asleep");

    // Asleep, a step asks nothing of the backend.
    const std::size_t calls = backend.mCalls.size();
    const TetStepResult asleep = stepper.Step(backend, Settings(), 0.01, "Scripted").Get();
    CHECK(asleep.mEvents == ETetStepEvent::Sleeping);
    CHECK(backend.mCalls.size() == calls);
    stepper.Wake();
    CHECK_FALSE(stepper.IsSleeping());
    CHECK(stepper.Step(backend, Settings(), 0.01, "Scripted").Get().mEvents == ETetStepEvent::None);
    CHECK(backend.mCalls.size() == calls + 2);
}

TEST_CASE("TetStepper puts a solver that nothing could move to sleep at once, where sleep is on", "[fem]")
{
    TetStepper stepper;
    ScriptedBackend backend;
    backend.mAtRest = true;
    TetSolverSettings no_sleep = Settings();
    no_sleep.mSleepSpeed = 0.0;
    CHECK(stepper.Step(backend, no_sleep, 0.01, "Scripted").Get().mEvents == ETetStepEvent::None);
    CHECK_FALSE(stepper.IsSleeping());
    const TetStepResult result = stepper.Step(backend, Settings(), 0.01, "Scripted").Get();
    CHECK(result.mEvents == (ETetStepEvent::Sleeping | ETetStepEvent::FellAsleep));
    CHECK(result.mSubSteps == 0);
    CHECK(stepper.IsSleeping());
    CHECK(backend.mCalls.back() == "asleep");
    CHECK(std::count(backend.mCalls.begin(), backend.mCalls.end(), "attempt") == 1); // only the no-sleep step's
}

TEST_CASE("TetStepper puts a settled solver to sleep after three settled steps, not mSleepStepCount, a crack, a "
          "divergence or a wake-up starts the count again",
          "[fem]")
{
    // Sleep energy 1e-6 J (Settings, FreeMass); settled below 1e-8 of it. mSleepStepCount 30, so only the
    // settled rule can end these runs early.
    TetSolverSettings settings = Settings();
    settings.mSleepStepCount = 30;
    const double settled = 0.5e-14, quiet = 0.5e-6;
    const auto falls_asleep = [&](TetStepper& ioStepper, ScriptedBackend& ioBackend)
    { return HasEvent(ioStepper.Step(ioBackend, settings, 0.01, "Scripted").Get().mEvents, ETetStepEvent::FellAsleep); };

    // Two settled steps, then each section.
    TetStepper stepper;
    ScriptedBackend backend;
    backend.mKinetic = settled;
    CHECK_FALSE(falls_asleep(stepper, backend));
    CHECK_FALSE(falls_asleep(stepper, backend));

    SECTION("a crack, a quiet but unsettled step, or a divergence in between reset the count")
    {
        backend.mBrokenLinks = 1;
        CHECK_FALSE(falls_asleep(stepper, backend));
        backend.mBrokenLinks = 0;
        CHECK_FALSE(falls_asleep(stepper, backend));
        backend.mKinetic = quiet; // quiet (under the sleep energy) is not settled
        CHECK_FALSE(falls_asleep(stepper, backend));
        backend.mKinetic = settled;
        CHECK_FALSE(falls_asleep(stepper, backend));
        backend.mPiecesNeeded = 1000; // every split diverges: restored
        CHECK(HasEvent(stepper.Step(backend, settings, 0.01, "Scripted").Get().mEvents, ETetStepEvent::Diverged));
        backend.mPiecesNeeded = 1;
        stepper.Wake(); // an input changed: without one the stepper would not try the given-up step again
        CHECK_FALSE(falls_asleep(stepper, backend));
        CHECK_FALSE(falls_asleep(stepper, backend));
        CHECK(falls_asleep(stepper, backend));
        CHECK(stepper.IsSleeping());
    }
    SECTION("a wake-up starts the count again")
    {
        stepper.Wake();
        CHECK_FALSE(falls_asleep(stepper, backend));
        CHECK_FALSE(falls_asleep(stepper, backend));
        CHECK(falls_asleep(stepper, backend));
    }
    SECTION("otherwise the third settled step sleeps")
    {
        CHECK(falls_asleep(stepper, backend));
    }
}

TEST_CASE("TetStepper: with mSleepStepCount below three, the settled rule never waits longer than the quiet one", "[fem]")
{
    TetSolverSettings settings = Settings();
    settings.mSleepStepCount = 2;
    TetStepper stepper;
    ScriptedBackend backend;
    backend.mKinetic = 0.5e-14;
    CHECK_FALSE(HasEvent(stepper.Step(backend, settings, 0.01, "Scripted").Get().mEvents, ETetStepEvent::FellAsleep));
    CHECK(HasEvent(stepper.Step(backend, settings, 0.01, "Scripted").Get().mEvents, ETetStepEvent::FellAsleep));
}
