// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Result.h>
#include <crumple/crash/CrashScenario.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

namespace crumple::crash
{

/// Campbell's linear crush model (SAE 740565): a full-frontal rigid-barrier impact at speed v leaves a
/// residual crush C = (v - b0) / b1, none below the no-damage speed b0.
struct CampbellLine
{
    double mNoDamageSpeed = 2.17; ///< b0 (m/s), >= 0
    double mSlope = 24.07;        ///< b1 (1/s), > 0

    /// C(v) (m)
    double Crush(double inSpeed) const { return inSpeed > mNoDamageSpeed ? (inSpeed - mNoDamageSpeed) / mSlope : 0.0; }
};

/// The band of Campbell lines the crash data spans (shared/data/crash/campbell_oracle.csv, the same for every
/// class: 0-0.125 m at 16 km/h to 0.369-0.742 m at 56 km/h, i.e. b0 2.2-4.5 m/s with b1 18-30 1/s,
/// SOURCES.md): the least crush at a speed is on mLeast, the most on mMost. Plots draw it (CrushSpeedChart).
struct CampbellBand
{
    CampbellLine mLeast{16.0 / 3.6, 1.0 / (0.369 / (40.0 / 3.6))};         ///< 0 at 16 km/h, 0.369 m at 56 km/h
    CampbellLine mMost{(16.0 - 0.125 / (0.617 / 40.0)) / 3.6, 40.0 / 3.6 / 0.617}; ///< 0.125 m at 16, 0.742 m at 56 km/h
};

/// One speed of a calibration or check: the model's crush and the simulated one.
struct CampbellPoint
{
    double mSpeed = 0.0;   ///< m/s
    double mModel = 0.0;   ///< Campbell's crush (m)
    double mCrush = 0.0;   ///< Simulated residual crush of the front zone (m)
    double mImpulse = 0.0; ///< Simulated total impulse (N s)

    /// |simulated - model| / model
    double RelativeError() const { return std::abs(mCrush - mModel) / mModel; }
};

/// Runs inScenario (a full-frontal rigid-wall crash) at each speed and measures the front crush.
Result<std::vector<CampbellPoint>> RunCampbellSpeeds(const CrashScenario& inScenario, const CampbellLine& inLine,
                                                     const std::vector<double>& inSpeeds);

/// Fits the vehicle's damage material so that inScenario, run at inSpeeds (m/s), reproduces inLine: the
/// impulse threshold is k b0 and the deformation factor 1 / (b1 k), with k the fitted impulse per unit speed
/// (J = k v through the origin), then the factor is corrected by the simulated crush over the requested dent
/// depth (the FFD surface does not follow a dent exactly), inIterations times. The instantaneous and total
/// deformation bounds are set to 1.5 x the model's largest crush so they never clip the line.
/// @return the scenario's vehicle with the fitted material; ioPoints gets the final run's points
Result<VehicleSpec> CalibrateToCampbell(const CrashScenario& inScenario, const CampbellLine& inLine,
                                        const std::vector<double>& inSpeeds, int inIterations,
                                        std::vector<CampbellPoint>& outPoints);

/// Writes a material preset file (read through a scenario's "material": {"preset_file": ...}).
Status WritePresetFile(const std::filesystem::path& inPath, const std::string& inName, const std::string& inSource,
                       const CampbellLine& inLine, const VehicleSpec& inVehicle);

/// Writes calibration.csv (speed_km_h, model_crush_m, simulated_crush_m, relative_error, impulse_N_s).
Status WriteCampbellCsv(const std::filesystem::path& inPath, const std::vector<CampbellPoint>& inPoints);

/// A PNG plot of residual crush against impact speed: the model's line and the simulated points.
Status WriteCampbellPlot(const std::filesystem::path& inPath, const CampbellLine& inLine,
                         const std::vector<CampbellPoint>& inPoints);

} // namespace crumple::crash
