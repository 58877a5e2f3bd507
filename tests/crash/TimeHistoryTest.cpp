// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// The SAE J211 CFC filter against its defining response, and the time history of a known motion.
#include <crumple/crash/TimeHistory.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

using namespace crumple;
using namespace crumple::crash;

namespace
{

// Steady-state amplitude of a sine of inHz after the filter, sampled at 10 kHz over 1 s (the middle half,
// away from the ends).
double Gain(double inHz, double inCfc)
{
    const double step = 1.0e-4;
    std::vector<double> x;
    for (int i = 0; i < 10000; ++i)
        x.push_back(std::sin(2.0 * std::numbers::pi * inHz * i * step));
    const Result<std::vector<double>> y = CfcFilter(x, step, inCfc);
    REQUIRE(y.IsValid());
    double peak = 0.0;
    for (std::size_t i = 2500; i < 7500; ++i)
        peak = std::max(peak, std::abs(y.Get()[i]));
    return peak;
}

} // namespace

TEST_CASE("CFC 60 passes 10 Hz, is 3 dB down at 100 Hz and stops 1 kHz", "[crash]")
{
    // SAE J211/1: CFC 60 is flat (+0.5/-1 dB) to 60 Hz with its -3 dB point at 100 Hz.
    CHECK(Gain(10.0, 60.0) == Approx(1.0).margin(0.01));
    CHECK(20.0 * std::log10(Gain(60.0, 60.0)) >= -1.0);
    CHECK(20.0 * std::log10(Gain(100.0, 60.0)) == Approx(-3.0).margin(0.5));
    CHECK(Gain(1000.0, 60.0) < 0.01);
    // CFC 180: -3 dB at 300 Hz.
    CHECK(20.0 * std::log10(Gain(300.0, 180.0)) == Approx(-3.0).margin(0.5));
}

TEST_CASE("CFC filtering keeps a constant and refuses a step too coarse for its class", "[crash]")
{
    const std::vector<double> constant(200, -9.81);
    const Result<std::vector<double>> y = CfcFilter(constant, 1.0e-3, 60.0);
    REQUIRE(y.IsValid());
    for (double v : y.Get())
        CHECK(v == Approx(-9.81).epsilon(1.0e-12));
    CHECK(CfcFilter(constant, 1.0 / 120.0, 60.0).HasError()); // 120 Hz sampling: below 10 x 60
    CHECK(CfcFilter(std::vector<double>{1.0, std::nan("")}, 1.0e-3, 60.0).HasError());
}

TEST_CASE("A car braking at a constant rate has that deceleration and stops when v0 / a says", "[crash]")
{
    CrashOutcome outcome;
    outcome.mMass = 1000.0;
    const double v0 = 20.0, a = 100.0, step = 1.0e-3; // stops at 0.2 s
    outcome.mStartVelocity = Vec3(v0, 0.0, 0.0);
    for (int i = 0; i <= 300; ++i)
    {
        const double t = i * step, v = std::max(0.0, v0 - a * t);
        const double x = t < v0 / a ? v0 * t - 0.5 * a * t * t : v0 * v0 / (2.0 * a);
        outcome.mHistory.push_back({t, Vec3(x, 0.0, 0.0), Vec3(v, 0.0, 0.0)});
    }
    const TimeHistory history = MakeTimeHistory(outcome);
    REQUIRE(history.mRows.size() == 301);
    REQUIRE_FALSE(history.mAccelerationCfc60.empty()); // 1 kHz sampling: CFC 60 applies
    CHECK(history.mTimeToZeroVelocity == Approx(0.2).margin(step));
    // The filtered pulse's plateau is the braking rate; at its ends a two-pole Butterworth overshoots a step
    // by at most 4.3 % (its step response), and the peak reported is that of the filtered pulse.
    CHECK(-history.mAccelerationCfc60[100] == Approx(a).epsilon(1.0e-3));
    CHECK(history.mPeakDeceleration >= a);
    CHECK(history.mPeakDeceleration <= 1.0432 * a);
    CHECK(history.mRows[100].mAcceleration == Approx(-a).epsilon(1.0e-9));
    // A 200 ms plateau: its 3 ms clip is the plateau (the overshoot at the ends lasts under 3 ms above it).
    CHECK(history.mClip3ms >= a);
    CHECK(history.mClip3ms <= 1.0432 * a);
    CHECK(history.mRows.back().mEnergyAbsorbed == Approx(0.5 * 1000.0 * v0 * v0).epsilon(1.0e-12));
    CHECK(history.mRows.back().mDisplacement == Approx(v0 * v0 / (2.0 * a)).epsilon(1.0e-12));
}
