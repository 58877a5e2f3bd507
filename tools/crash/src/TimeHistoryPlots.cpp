// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "PlotCanvas.h"

#include <crumple/crash/TimeHistory.h>

#include <algorithm>
#include <initializer_list>
#include <vector>

namespace crumple::crash
{

Status WriteTimeHistoryPlots(const std::filesystem::path& inFolder, const TimeHistory& inHistory)
{
    if (inHistory.mRows.size() < 2)
        return MakeError(EError::InvalidArgument, "WriteTimeHistoryPlots: fewer than two samples");
    constexpr double cG = 9.80665;
    std::vector<double> time_ms, velocity, deceleration, filtered, kinetic, absorbed;
    for (std::size_t row = 0; row < inHistory.mRows.size(); ++row)
    {
        const TimeHistoryRow& r = inHistory.mRows[row];
        time_ms.push_back(1000.0 * r.mTime);
        velocity.push_back(3.6 * r.mVelocity);
        deceleration.push_back(-r.mAcceleration / cG);
        if (row < inHistory.mAccelerationCfc60.size())
            filtered.push_back(-inHistory.mAccelerationCfc60[row] / cG);
        kinetic.push_back(r.mKineticEnergy / 1000.0);
        absorbed.push_back(r.mEnergyAbsorbed / 1000.0);
    }
    const std::array<std::uint8_t, 3> red{210, 30, 30}, blue{30, 80, 200}, grey{150, 150, 150};
    auto range = [](const std::vector<double>& inValues, double& ioLow, double& ioHigh) {
        for (double value : inValues)
            if (std::isfinite(value))
            {
                ioLow = std::min(ioLow, value);
                ioHigh = std::max(ioHigh, value);
            }
    };

    // A chart over the run's time whose y range covers inSeries.
    auto over_time = [&](const char* inYTitle, std::initializer_list<const std::vector<double>*> inSeries) {
        LineChart chart;
        chart.mX1 = time_ms.back();
        chart.mXTitle = "time (ms)";
        chart.mYTitle = inYTitle;
        chart.mY0 = chart.mY1 = 0.0;
        for (const std::vector<double>* series : inSeries)
            range(*series, chart.mY0, chart.mY1);
        return chart;
    };

    LineChart pulse = over_time("deceleration along the travel (g)", {&deceleration});
    PlotCanvas pulse_canvas = pulse.Draw();
    pulse.Series(pulse_canvas, time_ms, deceleration, grey);
    LineChart::AddLegend(pulse_canvas, 0, grey, "unfiltered (engine steps)");
    if (!filtered.empty())
    {
        pulse.Series(pulse_canvas, time_ms, filtered, red);
        LineChart::AddLegend(pulse_canvas, 1, red, "CFC 60 (SAE J211)");
    }
    if (Status saved = pulse_canvas.Save(inFolder / "deceleration.png"); !saved)
        return saved;

    LineChart speed = over_time("velocity along the travel (km/h)", {&velocity});
    PlotCanvas speed_canvas = speed.Draw();
    speed.Series(speed_canvas, time_ms, velocity, blue);
    if (Status saved = speed_canvas.Save(inFolder / "velocity.png"); !saved)
        return saved;

    LineChart energy = over_time("energy (kJ)", {&kinetic, &absorbed});
    PlotCanvas energy_canvas = energy.Draw();
    energy.Series(energy_canvas, time_ms, kinetic, blue);
    energy.Series(energy_canvas, time_ms, absorbed, red);
    LineChart::AddLegend(energy_canvas, 0, blue, "kinetic");
    LineChart::AddLegend(energy_canvas, 1, red, "absorbed (kinetic energy lost)");
    return energy_canvas.Save(inFolder / "energy.png");
}

} // namespace crumple::crash
