// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Result.h>

#include <string>

namespace crumple::crash
{

/// A FemBarrierCoupling scene without an engine, for tests and benchmarks: a 1575 kg box car (4.4 x 1.7 x
/// 1.4 m) floating at the height of a 0.2 x 3 x 1.6 m barrier (taller than the car, so its whole front
/// meets it), driven head-on into it; the car moves by its own velocity between the coupling's steps.
/// The car's front crushes by Campbell's mid-size line (b0 2.173 m/s, b1 24.07 1/s).
struct FloatingBarrierCrashSettings
{
    std::string mMaterial = "steel"; ///< The barrier's prop material preset
    double mSpeed = 30.0 / 3.6;      ///< Impact speed (m/s)
    double mTimeStep = 1.0 / 120.0;  ///< Step (s)
    double mDuration = 0.4;          ///< Simulated time (s)
};

/// What the run measured.
struct FloatingBarrierCrashResult
{
    double mCampbellCrush = 0.0;  ///< (v - b0) / b1 (m): the crush against a barrier that does not move
    double mDeepestCrush = 0.0;   ///< Largest distance of the car's front past the struck face (mean of the
                                  ///< front nodes the car's face covers) over the run (m)
    double mEndSpeed = 0.0;       ///< The car's velocity along x at the end (m/s)
    double mMomentumError = 0.0;  ///< |momentum the car lost - momentum the barrier took| (N s)
    double mMomentumLost = 0.0;   ///< |momentum the car lost| (N s)
    /// |momentum the car lost - the barrier's free nodes' momentum change over the collisions| (N s): the
    /// nodes' own velocities, summed m_i dv_i around each Collide, so an impulse that reached no node, the
    /// wrong node's mass or the wrong sign shows here (anchored nodes would absorb: this barrier has none)
    double mNodeMomentumError = 0.0;
    int mBrokenLinks = 0;         ///< Links the barrier broke
    double mFrontPastBarrier = 0.0; ///< The car's front x at the end minus the barrier's back face x (m)
};

/// Runs the scene.
Result<FloatingBarrierCrashResult> RunFloatingBarrierCrash(const FloatingBarrierCrashSettings& inSettings);

} // namespace crumple::crash
