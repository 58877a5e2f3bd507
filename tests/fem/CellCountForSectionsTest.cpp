// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/CellCountForSections.h>

#include <catch2/catch.hpp>

#include <string>

using namespace crumple;
using namespace crumple::fem;

TEST_CASE("CellCountForSections divides the average section size into the wall", "[fem]")
{
    ProceduralEdgeSettings settings;
    settings.mAverageSectionWidth = 0.25;
    settings.mAverageSectionHeight = 0.3;

    // 2 m / 0.25 = 8 along x (width), 1.2 m / 0.3 = 4 along y (height), one cell across the 0.1 m thickness.
    Result<std::array<int, 3>> count = CellCountForSections(Vec3(2.0, 1.2, 0.1), settings);
    REQUIRE(count.IsValid());
    CHECK(count.Get() == std::array<int, 3>{{8, 4, 1}});

    // Width along z (3 m / 0.25 = 12), height along y (1 m / 0.3 = 3.33 -> 3), thickness x with two layers.
    count = CellCountForSections(Vec3(0.1, 1.0, 3.0), settings, 2);
    REQUIRE(count.IsValid());
    CHECK(count.Get() == std::array<int, 3>{{2, 3, 12}});

    // Rounding to the nearest count: 0.9 m / 0.25 = 3.6 -> 4; smaller than a section -> 1.
    count = CellCountForSections(Vec3(0.9, 0.1, 0.05), settings);
    REQUIRE(count.IsValid());
    CHECK(count.Get() == std::array<int, 3>{{4, 1, 1}});
}

TEST_CASE("CellCountForSections refuses invalid input", "[fem]")
{
    ProceduralEdgeSettings settings;
    Result<std::array<int, 3>> count = CellCountForSections(Vec3(2.0, -1.0, 0.1), settings);
    REQUIRE(count.HasError());
    CHECK(count.GetError().mMessage.find("size") != std::string::npos);
    count = CellCountForSections(Vec3(2.0, 1.0, 0.1), settings, 0);
    REQUIRE(count.HasError());
    CHECK(count.GetError().mMessage.find("inThicknessCells") != std::string::npos);
    settings.mAverageSectionWidth = -0.25;
    count = CellCountForSections(Vec3(2.0, 1.0, 0.1), settings);
    REQUIRE(count.HasError());
    CHECK(count.GetError().mMessage.find("mAverageSectionWidth") != std::string::npos);
    settings = {};
    settings.mAverageSectionWidth = 1e-5;
    settings.mVerticalEdgeAmplitude = 0.0;
    count = CellCountForSections(Vec3(200.0, 100.0, 0.1), settings);
    REQUIRE(count.HasError());
    CHECK(count.GetError().mMessage.find("2^22") != std::string::npos);
}
