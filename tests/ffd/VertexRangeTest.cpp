// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/ffd/VertexRange.h>

#include <catch2/catch.hpp>

using namespace crumple::ffd;

TEST_CASE("VertexRangesFromFlags merges runs of changed vertices", "[ffd]")
{
    const std::vector<std::uint8_t> flags{0, 1, 1, 0, 0, 1, 0, 1, 1, 1};
    const std::vector<VertexRange> ranges = VertexRangesFromFlags(flags);
    REQUIRE(ranges.size() == 3);
    CHECK(ranges[0] == VertexRange{1, 3});
    CHECK(ranges[1] == VertexRange{5, 6});
    CHECK(ranges[2] == VertexRange{7, 10});
    CHECK(VertexRangesFromFlags(std::vector<std::uint8_t>(5, 0)).empty());
}
