// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/crash/Calibration.h>
#include <crumple/crash/CrashRun.h>

#include "PlotCanvas.h"

#include <crumple/base/FileBytes.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cstdio>
#include <span>

namespace crumple::crash
{

namespace
{

constexpr double cKmhPerMs = 3.6;

Status WriteText(const std::filesystem::path& inPath, const std::string& inText)
{
    return WriteFileAtomically(inPath, std::as_bytes(std::span(inText.data(), inText.size())), "crumple-crash");
}

} // namespace

Result<std::vector<CampbellPoint>> RunCampbellSpeeds(const CrashScenario& inScenario, const CampbellLine& inLine,
                                                     const std::vector<double>& inSpeeds)
{
    std::vector<CampbellPoint> points;
    for (double speed : inSpeeds)
    {
        CrashScenario scenario = inScenario;
        scenario.mImpact.mSpeed = speed;
        Result<CrashOutcome> outcome = RunCrash(scenario, CrashRunOptions{});
        if (outcome.HasError())
            return outcome.GetError();
        points.push_back({speed, inLine.Crush(speed), outcome.Get().mResidualCrush[static_cast<int>(EZone::Front)],
                          outcome.Get().mTotalImpulse});
    }
    return points;
}

Result<VehicleSpec> CalibrateToCampbell(const CrashScenario& inScenario, const CampbellLine& inLine,
                                        const std::vector<double>& inSpeeds, int inIterations,
                                        std::vector<CampbellPoint>& outPoints)
{
    if (inSpeeds.empty() || !(inLine.mSlope > 0.0) || !(inLine.mNoDamageSpeed >= 0.0) || inIterations < 1)
        return MakeError(EError::InvalidArgument, "CalibrateToCampbell: needs speeds, b1 > 0, b0 >= 0, iterations >= 1");
    const double deepest = inLine.Crush(*std::max_element(inSpeeds.begin(), inSpeeds.end()));
    CrashScenario scenario = inScenario;
    VehicleSpec& vehicle = scenario.mVehicle;
    vehicle.mMaterial.mModel = plugin::ECrushModel::ImpulseFactor; // the fit is of the factor and the threshold
    vehicle.mMaterial.mMaxInstantDeformation = std::max(1.5 * deepest, vehicle.mMaterial.mMinDeformation);
    vehicle.mMaxTotalDeformation = 1.5 * deepest;
    double correction = 1.0; // simulated crush over requested dent depth
    for (int iteration = 0; iteration <= inIterations; ++iteration)
    {
        Result<std::vector<CampbellPoint>> points = RunCampbellSpeeds(scenario, inLine, inSpeeds);
        if (points.HasError())
            return points.GetError();
        outPoints = points.Get();
        if (iteration == inIterations)
            break;

        // Impulse per unit speed, J = k v, least squares through the origin.
        double jv = 0.0, vv = 0.0;
        for (const CampbellPoint& point : outPoints)
        {
            jv += point.mImpulse * point.mSpeed;
            vv += point.mSpeed * point.mSpeed;
        }
        const double k = jv / vv;

        // How the surface followed the requested depths f (J - J0) in this run (least squares ratio).
        if (iteration > 0)
        {
            double cd = 0.0, dd = 0.0;
            for (const CampbellPoint& point : outPoints)
            {
                const double requested = vehicle.mMaterial.mDeformationFactor *
                                         std::max(0.0, point.mImpulse - vehicle.mMaterial.mImpulseThreshold);
                cd += point.mCrush * requested;
                dd += requested * requested;
            }
            if (dd > 0.0 && cd > 0.0)
                correction = cd / dd;
        }
        vehicle.mMaterial.mImpulseThreshold = k * inLine.mNoDamageSpeed;
        vehicle.mMaterial.mDeformationFactor = 1.0 / (inLine.mSlope * k * correction);
    }
    return vehicle;
}

Status WritePresetFile(const std::filesystem::path& inPath, const std::string& inName, const std::string& inSource,
                       const CampbellLine& inLine, const VehicleSpec& inVehicle)
{
    nlohmann::json preset;
    preset["preset"] = inName;
    preset["source"] = inSource;
    preset["campbell_b0_m_s"] = inLine.mNoDamageSpeed;
    preset["campbell_b1_per_s"] = inLine.mSlope;
    preset["mass_kg"] = inVehicle.mMass;
    preset["material"] = {{"crush_model", "impulse_factor"},
                          {"deformation_factor_m_per_N_s", inVehicle.mMaterial.mDeformationFactor},
                          {"impulse_threshold_N_s", inVehicle.mMaterial.mImpulseThreshold},
                          {"min_deformation_m", inVehicle.mMaterial.mMinDeformation},
                          {"max_deformation_m", inVehicle.mMaterial.mMaxInstantDeformation},
                          {"max_total_deformation_m", inVehicle.mMaxTotalDeformation}};
    return WriteText(inPath, preset.dump(2) + "\n");
}

Status WriteCampbellCsv(const std::filesystem::path& inPath, const std::vector<CampbellPoint>& inPoints)
{
    std::string text = "speed_km_h,model_crush_m,simulated_crush_m,relative_error,impulse_N_s\n";
    char line[160];
    for (const CampbellPoint& point : inPoints)
    {
        std::snprintf(line, sizeof(line), "%.3f,%.6f,%.6f,%.6f,%.3f\n", point.mSpeed * cKmhPerMs, point.mModel,
                      point.mCrush, point.RelativeError(), point.mImpulse);
        text += line;
    }
    return WriteText(inPath, text);
}

Status WriteCampbellPlot(const std::filesystem::path& inPath, const CampbellLine& inLine,
                         const std::vector<CampbellPoint>& inPoints)
{
    // Speed 0-70 km/h, crush 0 to the next 0.1 m above the data.
    CrushSpeedChart chart;
    for (const CampbellPoint& point : inPoints)
        chart.mTop = std::max({chart.mTop, point.mCrush, point.mModel});
    chart.mTop = std::ceil(chart.mTop * 10.0 + 0.5) / 10.0;
    const double right_kmh = chart.mRightKmh;
    PlotCanvas canvas = chart.Draw();
    auto x_of = [&](double inKmh) { return chart.X(inKmh); };
    auto y_of = [&](double inCrush) { return chart.Y(inCrush); };
    const std::array<std::uint8_t, 3> blue{30, 80, 200}, red{210, 30, 30};
    // The model: zero up to b0, then the line.
    const double b0_kmh = inLine.mNoDamageSpeed * cKmhPerMs;
    canvas.Line(x_of(0.0), y_of(0.0), x_of(b0_kmh), y_of(0.0), 3, blue);
    canvas.Line(x_of(b0_kmh), y_of(0.0), x_of(right_kmh), y_of(inLine.Crush(right_kmh / cKmhPerMs)), 3, blue);
    for (const CampbellPoint& point : inPoints)
        canvas.Disc(x_of(point.mSpeed * cKmhPerMs), y_of(point.mCrush), 6.0, red);
    CrushSpeedChart::AddLegend(canvas, 1, blue, "the line calibrated to");
    CrushSpeedChart::AddLegend(canvas, 2, red, "simulated");
    return canvas.Save(inPath);
}

} // namespace crumple::crash
