// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/WallAxes.h>

#include <catch2/catch.hpp>

using namespace crumple;
using namespace crumple::fem;

TEST_CASE("WallAxes orders width, height and thickness by extent, ties by axis", "[fem]")
{
    CHECK(WallAxes(Vec3(4.0, 2.5, 0.2)) == std::array<int, 3>{{0, 1, 2}});
    CHECK(WallAxes(Vec3(0.2, 2.5, 4.0)) == std::array<int, 3>{{2, 1, 0}});
    CHECK(WallAxes(Vec3(3.0, 0.1, 1.0)) == std::array<int, 3>{{0, 2, 1}});
    CHECK(WallAxes(Vec3(1.0, 1.0, 1.0)) == std::array<int, 3>{{0, 1, 2}});
    CHECK(WallAxes(Vec3(0.5, 2.0, 2.0)) == std::array<int, 3>{{1, 2, 0}});
}
