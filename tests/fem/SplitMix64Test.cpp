// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/SplitMix64.h>

#include <catch2/catch.hpp>

#include <cstdint>

using namespace crumple::fem;

TEST_CASE("SplitMix64 reproduces the reference splitmix64.c stream", "[fem]")
{
    // First outputs of Vigna's splitmix64.c with the state 0 (the usual xoshiro seeding test vector).
    SplitMix64 random(0);
    CHECK(random.Next() == 0xe220a8397b1dcdafULL);
    CHECK(random.Next() == 0x6e789e6aa1b965f4ULL);
    CHECK(random.Next() == 0x06c45d188009454fULL);
    CHECK(random.Next() == 0xf88bb8a8724c81ecULL);
}

TEST_CASE("SplitMix64 doubles are the top 53 bits scaled exactly into 0 <= x < 1 and -1 <= x < 1", "[fem]")
{
    SplitMix64 random(0);
    CHECK(random.NextDouble() == static_cast<double>(0xe220a8397b1dcdafULL >> 11) / 9007199254740992.0);
    CHECK(random.NextSigned() ==
          2.0 * static_cast<double>(0x6e789e6aa1b965f4ULL >> 11) / 9007199254740992.0 - 1.0);

    // Range and mean over many draws: uniform on [-1, 1) has mean 0 and variance 1/3.
    SplitMix64 stream(12345);
    double sum = 0.0;
    double sum_squares = 0.0;
    const int count = 200000;
    for (int draw = 0; draw < count; ++draw)
    {
        const double value = stream.NextSigned();
        REQUIRE(value >= -1.0);
        REQUIRE(value < 1.0);
        sum += value;
        sum_squares += value * value;
    }
    CHECK(std::abs(sum / count) < 0.01); // standard error 0.0013
    CHECK(sum_squares / count == Approx(1.0 / 3.0).epsilon(0.01));
}
