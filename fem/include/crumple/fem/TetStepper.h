// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Result.h>
#include <crumple/fem/TetSolverSettings.h>
#include <crumple/fem/TetStepResult.h>

namespace crumple::fem
{

/// What one attempt at a step did (TetStepBackend::Attempt).
struct CRUMPLE_API TetStepAttempt
{
    bool mDiverged = false;     ///< Non-finite state, or an energy gain the backend counts as divergence
    int mPlasticElements = 0;   ///< Plastic flow events
    int mBrokenLinks = 0;       ///< Links broken
    double mKineticEnergy = 0.0; ///< After the attempt (J)
    double mEnergy = 0.0;       ///< Mechanical energy after the attempt (J); 0 where the backend does not measure it
};

/// A tetrahedral solver's side of a step: what it does on its own data (CPU arrays, GPU buffers). The policy
/// around it (validation, sleep, split-retry, restore, sleep counting) is TetStepper's, written once for both
/// backends (fem::TetSolver and gpu::GpuTetSolver).
class CRUMPLE_API TetStepBackend
{
public:
    virtual ~TetStepBackend() = default;
    /// Sub-steps one attempt at inDeltaTime (s, finite, > 0) takes: the stable explicit count, 1 for an
    /// implicit step; or the error that refuses the step (more than the settings allow). Changes nothing.
    virtual Result<int> SubStepsFor(double inDeltaTime) const = 0;
    /// True when the sub-steps are explicit: a split retry multiplies them, within mMaxSubSteps.
    virtual bool IsExplicit() const = 0;
    /// Keeps the state the step starts from; an error (a device that cannot be made current) refuses the step.
    virtual Status SaveStepStart() = 0;
    /// Puts back what SaveStepStart kept (connectivity, plastic shape, nodes), with the attempt's counts.
    virtual void RestoreStepStart() = 0;
    /// Integrates inDeltaTime from the current state: inPieces explicit sub-steps, or inPieces implicit steps
    /// of inDeltaTime / inPieces. Adds its solver statistics (Newton and CG iterations, residual) to ioResult:
    /// those of every attempt count.
    virtual TetStepAttempt Attempt(double inDeltaTime, int inPieces, TetStepResult& ioResult) = 0;
    /// Kinetic and mechanical energy of the restored start, for a diverged step's result (0 where a backend
    /// would need a readback to know)
    virtual void DescribeRestored(TetStepResult& ioResult) const = 0;
    /// True when a step could not move anything: no velocity, no load (external force, gravity on a free
    /// node) and no strain, compared exactly (a backend that would need a readback to know answers false)
    virtual bool IsAtRestUnloaded() const = 0;
    /// Mass of the free nodes (kg): the sleep threshold is 1/2 of it times the sleep speed squared
    virtual double FreeMass() const = 0;
    /// Sets every velocity to zero: the solver falls asleep
    virtual void FallAsleep() = 0;
};

/// The step policy both tetrahedral backends share: refuses a bad step before anything changes, does nothing
/// while asleep, falls asleep at once where a step could move nothing (a prop made at rest without gravity:
/// a held fence sleeps from its first step instead of integrating mSleepStepCount steps of nothing),
/// integrates, retries a diverged attempt from the saved start in 2, 4, ... pieces (up to mMaxStepSplits,
/// explicit ones within mMaxSubSteps), restores the start when every attempt diverged (and from then on
/// reports a step of the same length from that start as diverged at once, without trying it again, until an
/// input changes: Wake), reports the events, and puts the solver to sleep after mSleepStepCount quiet steps
/// (after 3 once it has settled: kinetic energy under 1e-8 of the sleep energy, round-off of a body in
/// equilibrium). Holds the sleep state.
class CRUMPLE_API TetStepper
{
public:
    /// One step of ioBackend by inDeltaTime (s) under inSettings; inSolverName starts error messages.
    Result<TetStepResult> Step(TetStepBackend& ioBackend, const TetSolverSettings& inSettings, double inDeltaTime,
                               const char* inSolverName);
    /// Awake, with no quiet step counted (an input changed)
    void Wake()
    {
        mSleeping = false;
        mQuietSteps = 0;
        mSettledSteps = 0;
        mGivenUp = false;
    }
    bool IsSleeping() const { return mSleeping; }

private:
    // Settled: kinetic energy under this fraction of the sleep energy for this many steps in a row
    static constexpr double cSettledEnergyFraction = 1.0e-8;
    static constexpr int cSettledStepCount = 3;

    bool mSleeping = false;
    int mQuietSteps = 0;
    int mSettledSteps = 0; ///< Consecutive steps settled (see cSettledEnergyFraction)
    bool mGivenUp = false; ///< The last step diverged in every attempt and no input changed since
    double mGivenUpDeltaTime = 0.0; ///< Its length (s): a step of another length is tried
};

} // namespace crumple::fem
