// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Result.h>
#include <crumple/crash/CrashRun.h>

#include <filesystem>
#include <limits>
#include <span>
#include <vector>

namespace crumple::crash
{

/// SAE J211/1 channel frequency class filter (appendix C): a two-pole Butterworth low-pass run forward and
/// then backward over the samples, so that it shifts no phase. CFC 60 is flat to 60 Hz and 3 dB down at
/// 100 Hz; crash tests filter vehicle acceleration with it (CFC 180 for the 3 ms clip of occupant load).
/// The class is meaningful only when the sample rate is at least 10 times the class (J211's minimum for
/// CFC 60 is 600 samples per second; the 2.0775 pre-warp puts the corner past Nyquist below that).
/// @param[in] inSamples  equally spaced samples
/// @param[in] inStep     time between samples (s), > 0
/// @param[in] inCfc      the class (Hz), e.g. 60 or 180, > 0
/// @return the filtered samples; an error when the sample rate is below 10 x inCfc or the input is not finite
Result<std::vector<double>> CfcFilter(std::span<const double> inSamples, double inStep, double inCfc);

/// One row of a run's time history (world frame, along the car's initial direction of travel).
struct TimeHistoryRow
{
    double mTime = 0.0;            ///< s
    double mDisplacement = 0.0;    ///< Car centre's travel since the start along the initial direction (m)
    double mVelocity = 0.0;        ///< Car velocity along the initial direction (m/s)
    double mAcceleration = 0.0;    ///< Its backward difference (m/s^2), unfiltered
    double mKineticEnergy = 0.0;   ///< 1/2 m |v|^2 (J)
    double mEnergyAbsorbed = 0.0;  ///< Kinetic energy lost since the start (J)
};

/// A run's time history and the crash-pulse figures taken from it.
struct TimeHistory
{
    std::vector<TimeHistoryRow> mRows;
    /// The acceleration filtered at CFC 60 (m/s^2), one per row; empty when the engine step is too coarse
    /// for the class (see CfcFilter; a 1/120 s step samples at 120 Hz)
    std::vector<double> mAccelerationCfc60;
    double mPeakDeceleration = 0.0;     ///< Largest deceleration along the travel (m/s^2), CFC 60 when filtered
    double mTimeToZeroVelocity = -1.0;  ///< First time the velocity along the travel reaches 0 (s); < 0: never
    /// The 3 ms clip of the CFC 60 pulse (m/s^2): the highest deceleration exceeded for 3 ms in total (FMVSS 208's
    /// measure, here of the vehicle pulse); NaN when the pulse is not filtered or the step exceeds 1 ms
    double mClip3ms = std::numeric_limits<double>::quiet_NaN();
    double mStep = 0.0;                 ///< Sample step (s)
    /// Steps whose unfiltered deceleration exceeds a tenth of the largest: how long the engine took to stop
    /// the car's rigid collision box. The crush is a dent on the body, not compliance in the engine, so a
    /// rigid wall stops the box within a step or two at any step size: the pulse is the engine's, not a
    /// crushing car's (a real 56 km/h pulse lasts 60-100 ms)
    int mPulseSteps = 0;
};

/// The time history of a run from its per-step car samples (CrashOutcome::mHistory).
TimeHistory MakeTimeHistory(const CrashOutcome& inOutcome);

/// Writes timeseries.csv: time_s, displacement_m, velocity_m_s, acceleration_m_s2, acceleration_cfc60_m_s2
/// (empty without the filter), kinetic_energy_J, energy_absorbed_J.
Status WriteTimeSeriesCsv(const std::filesystem::path& inPath, const TimeHistory& inHistory);

/// Plots of the history into inFolder, time in ms on x, axes titled with units: deceleration.png (in g,
/// unfiltered and CFC 60 when filtered), velocity.png (km/h), energy.png (kinetic and absorbed, kJ).
Status WriteTimeHistoryPlots(const std::filesystem::path& inFolder, const TimeHistory& inHistory);

} // namespace crumple::crash
