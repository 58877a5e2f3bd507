// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/ProceduralEdgeSettings.h>

#include <catch2/catch.hpp>

#include <limits>
#include <string>

using namespace crumple;
using namespace crumple::fem;

namespace
{

// Checks that inSettings is refused with a message naming inField.
void CheckRefused(const ProceduralEdgeSettings& inSettings, const std::string& inField)
{
    const Status status = ValidateProceduralEdgeSettings(inSettings);
    REQUIRE(status.HasError());
    INFO(status.GetError().mMessage);
    CHECK(status.GetError().mMessage.find("ProceduralEdgeSettings." + inField) != std::string::npos);
}

} // namespace

TEST_CASE("ProceduralEdgeSettings defaults are valid", "[fem]")
{
    CHECK(ValidateProceduralEdgeSettings(ProceduralEdgeSettings{}).IsValid());
}

TEST_CASE("ProceduralEdgeSettings refuses non-finite and out-of-range fields by name", "[fem]")
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    ProceduralEdgeSettings settings;

    settings = {};
    settings.mAverageSectionWidth = nan;
    CheckRefused(settings, "mAverageSectionWidth");
    CHECK(ValidateProceduralEdgeSettings(settings).GetError().mCode == EError::NonFinite);
    settings = {};
    settings.mAverageSectionHeight = -0.1;
    CheckRefused(settings, "mAverageSectionHeight");
    settings = {};
    settings.mAverageSectionWidth = 0.0;
    CheckRefused(settings, "mAverageSectionWidth");
    settings = {};
    settings.mRandomSectionWidth = 0.45;
    CheckRefused(settings, "mRandomSectionWidth");
    settings = {};
    settings.mRandomSectionHeight = -0.01;
    CheckRefused(settings, "mRandomSectionHeight");
    settings = {};
    settings.mHorizontalEdgeFrequency = -1.0;
    CheckRefused(settings, "mHorizontalEdgeFrequency");
    settings = {};
    settings.mVerticalEdgeFrequency = inf;
    CheckRefused(settings, "mVerticalEdgeFrequency");
    settings = {};
    settings.mHorizontalEdgeAmplitude = -1e-3;
    CheckRefused(settings, "mHorizontalEdgeAmplitude");
    settings = {};
    settings.mVerticalEdgeAmplitude = nan;
    CheckRefused(settings, "mVerticalEdgeAmplitude");
}

TEST_CASE("ProceduralEdgeSettings bounds the amplitudes by 0.4 of the smallest section size", "[fem]")
{
    // Height 0.2 m, random height 0.25: the smallest section is 0.1 m tall, so A_h <= 0.04 m.
    ProceduralEdgeSettings settings;
    settings.mAverageSectionHeight = 0.2;
    settings.mRandomSectionHeight = 0.25;
    settings.mHorizontalEdgeAmplitude = 0.0399;
    CHECK(ValidateProceduralEdgeSettings(settings).IsValid());
    settings.mHorizontalEdgeAmplitude = 0.0401;
    CheckRefused(settings, "mHorizontalEdgeAmplitude");

    // Width 0.5 m, random width 0.1: A_v <= 0.4 x 0.8 x 0.5 = 0.16 m; the height does not matter for it.
    settings = {};
    settings.mAverageSectionWidth = 0.5;
    settings.mRandomSectionWidth = 0.1;
    settings.mVerticalEdgeAmplitude = 0.159;
    CHECK(ValidateProceduralEdgeSettings(settings).IsValid());
    settings.mVerticalEdgeAmplitude = 0.161;
    CheckRefused(settings, "mVerticalEdgeAmplitude");

    // Against actual cell sizes: a 0.05 m tall cell with random height 0.15 admits 0.4 x 0.7 x 0.05 = 0.014
    // m.
    settings = {};
    settings.mHorizontalEdgeAmplitude = 0.0139;
    CHECK(ValidateEdgeAmplitudes(settings, 1.0, 0.05).IsValid());
    settings.mHorizontalEdgeAmplitude = 0.0141;
    const Status status = ValidateEdgeAmplitudes(settings, 1.0, 0.05);
    REQUIRE(status.HasError());
    CHECK(status.GetError().mMessage.find("mHorizontalEdgeAmplitude") != std::string::npos);
}
