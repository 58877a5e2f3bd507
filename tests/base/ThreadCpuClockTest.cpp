// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// ThreadCpuSeconds counts the calling thread's work, not its waits.
#include <crumple/base/ThreadCpuClock.h>

#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>
#include <thread>

using namespace crumple;

TEST_CASE("ThreadCpuSeconds grows with the thread's work and not while it sleeps", "[base]")
{
    const double start = ThreadCpuSeconds();
    REQUIRE(std::isfinite(start));
    // Work: until the clock has moved 20 ms (bounded, so a broken clock fails instead of hanging).
    volatile double sink = 0.0;
    const auto wall_start = std::chrono::steady_clock::now();
    while (ThreadCpuSeconds() - start < 0.02 && std::chrono::steady_clock::now() - wall_start < std::chrono::seconds(10))
        for (int i = 0; i < 10000; ++i)
            sink = sink + std::sqrt(static_cast<double>(i));
    const double worked = ThreadCpuSeconds();
    CHECK(worked - start >= 0.02);
    // A 200 ms sleep uses next to no CPU time.
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    const double slept = ThreadCpuSeconds() - worked;
    CHECK(slept >= 0.0);
    CHECK(slept < 0.05);
}
