// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// What the crash tool's pictures show: Campbell's band as the crash data gives it, and the dent colour
// scale crumple-crash and crumple-replay share.
#include "ScenePainter.h"

#include "PlotCanvas.h"

#include <crumple/crash/Calibration.h>
#include <crumple/crash/TimeHistory.h>

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace crumple;

TEST_CASE("Campbell's band is the crash data's: least and most crush at 16-56 km/h within 2 mm", "[crash]")
{
    const std::filesystem::path csv = std::filesystem::path(CRUMPLE_SOURCE_DIR) / "../shared/data/crash/campbell_oracle.csv";
    const crash::CampbellBand band;
    // Without the shared data, the numbers SOURCES.md gives: b0 2.2-4.5 m/s, b1 18-30 1/s.
    CHECK(band.mMost.mNoDamageSpeed == Approx(2.2).margin(0.01));
    CHECK(band.mLeast.mNoDamageSpeed == Approx(4.44).margin(0.01));
    CHECK(band.mMost.mSlope == Approx(18.0).margin(0.05));
    CHECK(band.mLeast.mSlope == Approx(30.1).margin(0.05));
    std::ifstream file(csv);
    if (!file)
        return;
    std::string header, row;
    std::getline(file, header);
    int rows = 0;
    while (std::getline(file, row))
    {
        // The last 15 fields: min, nominal and max crush at 16, 32, 40, 48 and 56 km/h.
        std::vector<double> fields;
        std::stringstream stream(row.substr(row.rfind('"') + 2));
        for (std::string field; std::getline(stream, field, ',');)
            fields.push_back(std::stod(field));
        REQUIRE(fields.size() >= 15);
        const std::size_t first = fields.size() - 15;
        const double speeds[] = {16.0, 32.0, 40.0, 48.0, 56.0};
        for (int s = 0; s < 5; ++s)
        {
            INFO(row << " at " << speeds[s] << " km/h");
            CHECK(std::abs(band.mLeast.Crush(speeds[s] / 3.6) - fields[first + 3 * s]) <= 0.002);
            CHECK(std::abs(band.mMost.Crush(speeds[s] / 3.6) - fields[first + 3 * s + 2]) <= 0.002);
        }
        ++rows;
    }
    CHECK(rows == 4);
}

TEST_CASE("The dent colour scale is the deepest dent rounded up to 1, 2, 2.5 or 5 times ten to a power", "[crash]")
{
    CHECK(samples::DentColorScale(0.4882) == Approx(0.5));
    CHECK(samples::DentColorScale(0.12) == Approx(0.2));
    CHECK(samples::DentColorScale(0.25) == Approx(0.25));
    CHECK(samples::DentColorScale(0.21) == Approx(0.25));
    CHECK(samples::DentColorScale(2.6) == Approx(5.0));
    CHECK(samples::DentColorScale(0.0) == Approx(0.01));
    CHECK(samples::DentColorScale(std::nan("")) == Approx(0.01));
}

TEST_CASE("Time-history plots: three PNGs with round grid steps, too short a history is refused", "[crash]")
{
    CHECK(crash::NiceStep(300.0, 8) == Approx(50.0));
    CHECK(crash::NiceStep(0.7, 5) == Approx(0.2));
    CHECK(crash::NiceStep(12.0, 5) == Approx(2.5));
    crash::TimeHistory history;
    for (int step = 0; step <= 120; ++step)
    {
        crash::TimeHistoryRow row;
        row.mTime = step / 120.0;
        row.mVelocity = step < 30 ? 15.0 : 0.0;
        row.mAcceleration = step == 30 ? -15.0 * 120.0 : 0.0;
        row.mKineticEnergy = 0.5 * 1200.0 * row.mVelocity * row.mVelocity;
        row.mEnergyAbsorbed = 0.5 * 1200.0 * 225.0 - row.mKineticEnergy;
        history.mRows.push_back(row);
    }
    const std::filesystem::path folder = std::filesystem::temp_directory_path() / "crumple-charts-test";
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    REQUIRE(crash::WriteTimeHistoryPlots(folder, history));
    for (const char* name : {"deceleration.png", "velocity.png", "energy.png"})
        CHECK(std::filesystem::file_size(folder / name) > 1000);
    history.mRows.resize(1);
    CHECK(crash::WriteTimeHistoryPlots(folder, history).HasError());
    std::filesystem::remove_all(folder);
}
