// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/crash/TimeHistory.h>

#include <crumple/base/FileBytes.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <cstdio>
#include <numbers>
#include <string>

namespace crumple::crash
{

namespace
{

// One pass of J211's recursive filter; the coefficients are those of the standard (appendix C).
std::vector<double> FilterPass(const std::vector<double>& inX, double inStep, double inCfc)
{
    const double wd = 2.0 * std::numbers::pi * inCfc * 2.0775;
    const double wa = std::sin(wd * inStep / 2.0) / std::cos(wd * inStep / 2.0);
    const double denominator = 1.0 + std::numbers::sqrt2 * wa + wa * wa;
    const double a0 = wa * wa / denominator, a1 = 2.0 * a0, a2 = a0;
    const double b1 = -2.0 * (wa * wa - 1.0) / denominator;
    const double b2 = (-1.0 + std::numbers::sqrt2 * wa - wa * wa) / denominator;
    std::vector<double> y(inX.size());
    for (std::size_t t = 0; t < inX.size(); ++t)
    {
        // The signal is taken as constant before its first sample (no start-up transient from zero).
        const double x1 = t >= 1 ? inX[t - 1] : inX[0], x2 = t >= 2 ? inX[t - 2] : inX[0];
        const double y1 = t >= 1 ? y[t - 1] : inX[0], y2 = t >= 2 ? y[t - 2] : inX[0];
        y[t] = a0 * inX[t] + a1 * x1 + a2 * x2 + b1 * y1 + b2 * y2;
    }
    return y;
}

} // namespace

Result<std::vector<double>> CfcFilter(std::span<const double> inSamples, double inStep, double inCfc)
{
    if (!(inStep > 0.0) || !(inCfc > 0.0) || !std::isfinite(inStep) || !std::isfinite(inCfc))
        return MakeError(EError::InvalidArgument, "CfcFilter: the step and the class must be finite and > 0");
    if (1.0 / inStep < 10.0 * inCfc)
        return MakeError(EError::InvalidArgument, "CfcFilter: " + std::to_string(1.0 / inStep) +
                                                      " samples per second are too few for CFC " + std::to_string(inCfc) +
                                                      " (SAE J211 needs at least 10 x the class)");
    for (double sample : inSamples)
        if (!std::isfinite(sample))
            return MakeError(EError::NonFinite, "CfcFilter: a sample is not finite");
    std::vector<double> forward = FilterPass({inSamples.begin(), inSamples.end()}, inStep, inCfc);
    std::vector<double> reversed(forward.rbegin(), forward.rend());
    std::vector<double> backward = FilterPass(reversed, inStep, inCfc);
    return std::vector<double>(backward.rbegin(), backward.rend());
}

TimeHistory MakeTimeHistory(const CrashOutcome& inOutcome)
{
    TimeHistory history;
    const std::vector<CarSample>& samples = inOutcome.mHistory;
    if (samples.size() < 2)
        return history;
    const double speed = inOutcome.mStartVelocity.norm();
    const Vec3 direction = speed > 0.0 ? Vec3(inOutcome.mStartVelocity / speed) : Vec3::UnitX();
    const double kinetic0 = 0.5 * inOutcome.mMass * samples.front().mVelocity.squaredNorm();
    history.mStep = samples[1].mTime - samples[0].mTime;
    std::vector<double> acceleration;
    for (std::size_t i = 0; i < samples.size(); ++i)
    {
        TimeHistoryRow row;
        row.mTime = samples[i].mTime;
        row.mDisplacement = direction.dot(samples[i].mPosition - samples.front().mPosition);
        row.mVelocity = direction.dot(samples[i].mVelocity);
        row.mAcceleration = i == 0 ? 0.0 : (row.mVelocity - history.mRows.back().mVelocity) / history.mStep;
        row.mKineticEnergy = 0.5 * inOutcome.mMass * samples[i].mVelocity.squaredNorm();
        row.mEnergyAbsorbed = kinetic0 - row.mKineticEnergy;
        if (history.mTimeToZeroVelocity < 0.0 && row.mVelocity <= 0.0)
            history.mTimeToZeroVelocity = row.mTime;
        acceleration.push_back(row.mAcceleration);
        history.mRows.push_back(row);
    }
    Result<std::vector<double>> filtered = CfcFilter(acceleration, history.mStep, 60.0);
    if (filtered.IsValid())
        history.mAccelerationCfc60 = std::move(filtered.Get());
    const std::vector<double>& pulse = history.mAccelerationCfc60.empty() ? acceleration : history.mAccelerationCfc60;
    for (double a : pulse)
        history.mPeakDeceleration = std::max(history.mPeakDeceleration, -a);
    // 3 ms clip: the deceleration level that the filtered pulse exceeds for 3 ms in total, i.e. the k-th largest
    // sample with k steps making 3 ms (at least three samples, so a 1 ms step at most).
    const auto clip_steps = static_cast<std::size_t>(std::ceil(0.003 / history.mStep - 1.0e-9));
    if (!history.mAccelerationCfc60.empty() && clip_steps >= 3 && clip_steps <= history.mAccelerationCfc60.size())
    {
        std::vector<double> deceleration;
        for (double a : history.mAccelerationCfc60)
            deceleration.push_back(-a);
        std::nth_element(deceleration.begin(), deceleration.begin() + static_cast<std::ptrdiff_t>(clip_steps - 1),
                         deceleration.end(), std::greater<double>());
        history.mClip3ms = deceleration[clip_steps - 1];
    }
    double largest = 0.0;
    for (double a : acceleration)
        largest = std::max(largest, -a);
    for (double a : acceleration)
        history.mPulseSteps += largest > 0.0 && -a > 0.1 * largest ? 1 : 0;
    return history;
}

Status WriteTimeSeriesCsv(const std::filesystem::path& inPath, const TimeHistory& inHistory)
{
    std::string csv = "time_s,displacement_m,velocity_m_s,acceleration_m_s2,acceleration_cfc60_m_s2,kinetic_energy_J,"
                      "energy_absorbed_J\n";
    for (std::size_t i = 0; i < inHistory.mRows.size(); ++i)
    {
        const TimeHistoryRow& r = inHistory.mRows[i];
        char line[256];
        std::snprintf(line, sizeof(line), "%.9g,%.9g,%.9g,%.9g,", r.mTime, r.mDisplacement, r.mVelocity, r.mAcceleration);
        csv += line;
        if (!inHistory.mAccelerationCfc60.empty())
        {
            std::snprintf(line, sizeof(line), "%.9g", inHistory.mAccelerationCfc60[i]);
            csv += line;
        }
        std::snprintf(line, sizeof(line), ",%.9g,%.9g\n", r.mKineticEnergy, r.mEnergyAbsorbed);
        csv += line;
    }
    return WriteFileAtomically(inPath, std::as_bytes(std::span(csv.data(), csv.size())), "crumple-crash time series");
}

} // namespace crumple::crash
