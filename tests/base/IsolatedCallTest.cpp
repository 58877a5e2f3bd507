// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/base/IsolatedCall.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <csignal>
#include <limits>
#include <cstdlib>
#include <thread>

using namespace crumple;

TEST_CASE("Isolated work returns its bytes and its errors", "[base]")
{
    const std::vector<std::byte> payload{std::byte{1}, std::byte{2}, std::byte{250}};
    const Result<std::vector<std::byte>> bytes = RunIsolated([&] { return Result<std::vector<std::byte>>(payload); }, 10.0, "test");
    REQUIRE(bytes.IsValid());
    CHECK(bytes.Get() == payload);

    const Result<std::vector<std::byte>> empty =
        RunIsolated([] { return Result<std::vector<std::byte>>(std::vector<std::byte>{}); }, 10.0, "test");
    REQUIRE(empty.IsValid());
    CHECK(empty.Get().empty());

    const Result<std::vector<std::byte>> refused = RunIsolated(
        []() -> Result<std::vector<std::byte>> { return MakeError(EError::DegenerateGeometry, "no triangle"); }, 10.0, "test");
    REQUIRE(refused.HasError());
    CHECK(refused.GetError().mCode == EError::DegenerateGeometry);
    CHECK(refused.GetError().mMessage == "no triangle");

    // A timeout outside (0, 1e6] s is refused before anything runs.
    bool ran = false;
    // (1e20 s would have become a CPU limit of 1 s)
    for (double timeout : {0.0, -1.0, std::nan(""), std::numeric_limits<double>::infinity(), 1.0e20})
    {
        const Result<std::vector<std::byte>> bad = RunIsolated(
            [&] {
                ran = true;
                return Result<std::vector<std::byte>>(payload);
            },
            timeout, "test");
        REQUIRE(bad.HasError());
        CHECK(bad.GetError().mCode == EError::InvalidArgument);
    }
    CHECK_FALSE(ran);

    // A large answer (8 MB) comes through the pipe whole.
    const std::vector<std::byte> large(8u << 20, std::byte{7});
    const Result<std::vector<std::byte>> big = RunIsolated([&] { return Result<std::vector<std::byte>>(large); }, 30.0, "test");
    REQUIRE(big.IsValid());
    CHECK(big.Get() == large);
}

TEST_CASE("A crashing, aborting or hanging isolated work fails the call, and the caller lives on", "[base]")
{
    const Result<std::vector<std::byte>> crashed = RunIsolated(
        []() -> Result<std::vector<std::byte>> {
            std::raise(SIGSEGV);
            return std::vector<std::byte>{};
        },
        10.0, "mesh.ply");
    REQUIRE(crashed.HasError());
    CHECK(crashed.GetError().mCode == EError::CorruptData);
    CHECK(crashed.GetError().mMessage.find("mesh.ply: the parser crashed on it") == 0);

    const Result<std::vector<std::byte>> aborted = RunIsolated(
        []() -> Result<std::vector<std::byte>> {
            std::abort();
        },
        10.0, "mesh.off");
    REQUIRE(aborted.HasError());
    CHECK(aborted.GetError().mCode == EError::CorruptData);

    const Result<std::vector<std::byte>> hung = RunIsolated(
        []() -> Result<std::vector<std::byte>> {
            for (;;)
                std::this_thread::sleep_for(std::chrono::milliseconds(10));
        },
        0.3, "slow.ply");
    REQUIRE(hung.HasError());
    CHECK(hung.GetError().mMessage.find("took longer than") != std::string::npos);
}
