// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// SeamTwins (white box): each vertex's lowest index at the same position (==, so 0.0 and -0.0 are one),
// against a scan of every pair, on seeded sets full of duplicates, signed zeros and near misses.
#include "SeamTwins.h"
#include "DrawVec3.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

using namespace crumple;
using namespace crumple::ffd;

TEST_CASE("SeamTwins equals a scan of every pair: duplicates, signed zeros, neighbours one ulp apart",
          "[ffd]")
{
    std::mt19937_64 random(77);
    for (int trial = 0; trial < 20; ++trial)
    {
        std::uniform_int_distribution<int> coordinate(-3, 3), choice(0, 9);
        std::vector<Vec3> positions;
        const int count = 50 + 40 * trial;
        for (int v = 0; v < count; ++v)
        {
            Vec3 p = 0.25 * common::DrawVec3([&] { return coordinate(random); });
            const int kind = choice(random);
            if (kind == 0)
                p.x() = p.x() == 0.0 ? -0.0 : p.x(); // a signed zero, equal by ==
            else if (kind == 1)
                p.y() = std::nextafter(p.y(), 1.0); // one ulp away: another position
            else if (kind == 2 && !positions.empty())
                p = positions[static_cast<std::size_t>(random() % positions.size())]; // an exact copy
            positions.push_back(p);
        }
        const std::vector<std::uint32_t> twins = SeamTwins(positions);
        REQUIRE(twins.size() == positions.size());
        for (std::size_t v = 0; v < positions.size(); ++v)
        {
            std::uint32_t lowest = static_cast<std::uint32_t>(v);
            for (std::size_t w = 0; w < v; ++w)
                if (positions[w] == positions[v])
                {
                    lowest = static_cast<std::uint32_t>(w);
                    break;
                }
            INFO("trial " << trial << ", vertex " << v);
            CHECK(twins[v] == lowest);
        }
    }
    CHECK(SeamTwins({}).empty());
}
