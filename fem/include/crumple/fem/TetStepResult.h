// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <cstdint>

namespace crumple::fem
{

/// What happened during a TetSolver::Step(), as bit flags (Jolt's EPhysicsUpdateError). Each says what to do.
enum class ETetStepEvent : std::uint32_t
{
    None = 0,
    /// Error: the step produced a NaN/Inf or an energy blow-up (TetSolverSettings::mDivergenceEnergyRatio).
    /// The state was restored to the start of the step, so the next Step() would do the same: reduce the time
    /// step, use the implicit integrator, apply smaller impulses or more damping.
    Diverged = 1u << 0,
    /// Warning: conjugate gradient reached mCgMaxIterations above mCgRelativeTolerance, or Newton reached
    /// mImplicitMaxIterations above mImplicitTolerance; the step was kept. Raise the limits or accept a less
    /// accurate step.
    SolverNotConverged = 1u << 1,
    /// Information: the solver was asleep, or found that nothing could move it and fell asleep (then with
    /// FellAsleep), and did nothing.
    Sleeping = 1u << 2,
    /// Information: this step put the solver to sleep; velocities are now zero.
    FellAsleep = 1u << 3,
    /// Information: an attempt diverged and the step was retried from its start in more pieces (mSubSteps
    /// says how many the accepted attempt used); without Diverged the retry succeeded.
    Split = 1u << 4,
    /// Information: elements flowed plastically this step (mPlasticElements counts the flow events); their
    /// rest shape changed.
    Yielded = 1u << 5,
    /// Information: links broke this step (mBrokenLinks says how many); nodes were duplicated, so node count
    /// and GetElementNodes() changed. Call ComputeFragments() for the pieces.
    Fractured = 1u << 6,
};

/// Bitwise or of two event sets.
constexpr ETetStepEvent operator|(ETetStepEvent inA, ETetStepEvent inB)
{
    return static_cast<ETetStepEvent>(static_cast<std::uint32_t>(inA) | static_cast<std::uint32_t>(inB));
}

/// Bitwise and of two event sets.
constexpr ETetStepEvent operator&(ETetStepEvent inA, ETetStepEvent inB)
{
    return static_cast<ETetStepEvent>(static_cast<std::uint32_t>(inA) & static_cast<std::uint32_t>(inB));
}

/// True when inEvents contains inEvent.
constexpr bool HasEvent(ETetStepEvent inEvents, ETetStepEvent inEvent)
{
    return (inEvents & inEvent) != ETetStepEvent::None;
}

/// Outcome of one TetSolver::Step().
struct CRUMPLE_API TetStepResult
{
    ETetStepEvent mEvents = ETetStepEvent::None; ///< What happened, bit flags
    int mSubSteps = 0;            ///< Sub-steps of the last attempt (symplectic: stable sub-steps;
                                  ///< implicit: pieces after splitting, 1 normally; 0 when asleep)
    int mNewtonIterations = 0;    ///< Linear solves (implicit Euler)
    int mLineSearchHalvings = 0;  ///< Newton updates halved by the line search (implicit Euler, no ground)
    int mSolverIterations = 0;    ///< Conjugate-gradient iterations, all solves together (implicit Euler)
    double mSolverResidual = 0.0; ///< Largest final relative CG residual |r| / |b| (implicit Euler)
    double mKineticEnergy = 0.0;  ///< Kinetic energy after the step (J)
    double mEnergy = 0.0;         ///< Mechanical energy H after the step (J), see mDivergenceEnergyRatio;
                                  ///< leaves out the (constant) elastic energy of elements whose corners
                                  ///< are all anchored, which TetSolver::ElasticEnergy() includes
    int mPlasticElements = 0;     ///< Plastic flow events: elements that flowed, summed over the sub-steps
    int mBrokenLinks = 0;         ///< Links broken during the step
};

/// Outcome of TetSolver::SolveStatic().
struct CRUMPLE_API TetStaticResult
{
    int mIterations = 0;            ///< Outer (re-linearisation) iterations
    int mSolverIterations = 0;      ///< Conjugate-gradient iterations, all outer iterations together
    double mRelativeResidual = 0.0; ///< Final |f_elastic + f_ext| / |f_ext| over the free nodes
};

} // namespace crumple::fem
