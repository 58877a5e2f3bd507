// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/TetStepper.h>

#include <crumple/base/TimeStep.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace crumple::fem
{

Result<TetStepResult> TetStepper::Step(TetStepBackend& ioBackend, const TetSolverSettings& inSettings, double inDeltaTime,
                                       const char* inSolverName)
{
    // intent: every refusal before anything changes
    if (Status valid = CheckTimeStep(inDeltaTime, std::string(inSolverName) + "::Step"); !valid)
        return valid.GetError();
    // The settings the solvers' Create validated, checked again here: this class is exported, and the
    // retry's shifts and counts need them in range.
    if (inSettings.mMaxStepSplits < 0 || inSettings.mMaxStepSplits > 16 || inSettings.mMaxSubSteps < 1 ||
        inSettings.mSleepStepCount < 1 || !(inSettings.mSleepSpeed >= 0.0) || !std::isfinite(inSettings.mSleepSpeed))
        return MakeError(EError::InvalidArgument, std::string(inSolverName) +
                                                      "::Step: settings out of range (mMaxStepSplits in [0, 16], mMaxSubSteps "
                                                      "and mSleepStepCount >= 1, mSleepSpeed finite and >= 0)");
    Result<int> sub_steps = ioBackend.SubStepsFor(inDeltaTime);
    if (!sub_steps)
        return sub_steps.GetError();
    if (sub_steps.Get() < 1)
        return MakeError(EError::InvalidArgument, std::string(inSolverName) + "::Step: the backend asked for no sub-step");

    TetStepResult result;
    if (mSleeping)
    {
        result.mEvents = ETetStepEvent::Sleeping;
        return result;
    }
    // Sleep is on (mSleepSpeed > 0) and nothing could move: asleep now, not after mSleepStepCount steps.
    if (inSettings.mSleepSpeed > 0.0 && ioBackend.IsAtRestUnloaded())
    {
        ioBackend.FallAsleep();
        mSleeping = true;
        mQuietSteps = 0;
        mSettledSteps = 0;
        result.mEvents = ETetStepEvent::Sleeping | ETetStepEvent::FellAsleep;
        return result;
    }
    // A step given up is not tried again from the same start: with no input changed since (Wake) and the same
    // step length, every attempt would diverge as before (a held fence pressed into the ground by a car spent
    // 0.4 s of its task on each of 30 such steps, 32 pieces and 133 Newton iterations every time).
    if (mGivenUp && inDeltaTime == mGivenUpDeltaTime)
    {
        result.mEvents = ETetStepEvent::Diverged;
        ioBackend.DescribeRestored(result);
        return result;
    }
    if (Status saved = ioBackend.SaveStepStart(); !saved)
        return saved.GetError();

    // Integrate; on divergence retry from the saved start with the step split into 2, 4, ... parts.
    TetStepAttempt attempt;
    attempt.mDiverged = true;
    const bool explicit_steps = ioBackend.IsExplicit();
    for (int split = 0; split <= inSettings.mMaxStepSplits && attempt.mDiverged; ++split)
    {
        const long long pieces = (explicit_steps ? static_cast<long long>(sub_steps.Get()) : 1LL) << split;
        if (explicit_steps && pieces > inSettings.mMaxSubSteps)
            break; // no retry within the sub-step budget
        if (split > 0)
        {
            result.mEvents = result.mEvents | ETetStepEvent::Split;
            ioBackend.RestoreStepStart();
        }
        result.mSubSteps = static_cast<int>(pieces);
        attempt = ioBackend.Attempt(inDeltaTime, result.mSubSteps, result);
    }
    if (attempt.mDiverged)
    {
        ioBackend.RestoreStepStart();
        mQuietSteps = 0;
        mSettledSteps = 0;
        result.mEvents = result.mEvents | ETetStepEvent::Diverged;
        ioBackend.DescribeRestored(result);
        mGivenUp = true;
        mGivenUpDeltaTime = inDeltaTime;
        return result;
    }
    mGivenUp = false;
    result.mKineticEnergy = attempt.mKineticEnergy;
    result.mEnergy = attempt.mEnergy;
    result.mPlasticElements = attempt.mPlasticElements;
    result.mBrokenLinks = attempt.mBrokenLinks;
    if (attempt.mPlasticElements > 0)
        result.mEvents = result.mEvents | ETetStepEvent::Yielded;
    if (attempt.mBrokenLinks > 0)
        result.mEvents = result.mEvents | ETetStepEvent::Fractured;

    // Sleep after mSleepStepCount quiet steps: slow, and nothing cracked (a fresh crack may free a piece that
    // has yet to move).
    const double sleep_energy = 0.5 * ioBackend.FreeMass() * inSettings.mSleepSpeed * inSettings.mSleepSpeed;
    mQuietSteps = attempt.mKineticEnergy < sleep_energy && attempt.mBrokenLinks == 0 ? mQuietSteps + 1 : 0;
    // A settled body sleeps sooner: the quiet steps guard against the instant of an oscillation when its
    // kinetic energy passes near zero, but kinetic energy that stays under cSettledEnergyFraction of the sleep
    // energy for cSettledStepCount steps in a row is no such instant (an oscillation of the sleep energy would
    // need a period of more than pi / sqrt(cSettledEnergyFraction) steps, 3e4 here); it is a body in
    // equilibrium (strained against its anchors), whose velocities are round-off.
    mSettledSteps = attempt.mKineticEnergy < cSettledEnergyFraction * sleep_energy && attempt.mBrokenLinks == 0
                        ? mSettledSteps + 1
                        : 0;
    if (mQuietSteps >= inSettings.mSleepStepCount || mSettledSteps >= std::min(cSettledStepCount, inSettings.mSleepStepCount))
    {
        ioBackend.FallAsleep();
        mSleeping = true;
        result.mEvents = result.mEvents | ETetStepEvent::FellAsleep;
    }
    return result;
}

} // namespace crumple::fem
