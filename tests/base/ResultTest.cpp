// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/base/Result.h>

#include <catch2/catch.hpp>

#include <memory>

using namespace crumple;

TEST_CASE("Result holds a value or an error", "[base]")
{
    Result<int> value = 7;
    REQUIRE(value.IsValid());
    CHECK_FALSE(value.HasError());
    CHECK(value.Get() == 7);

    Result<int> error = MakeError(EError::NonFinite, "x is NaN");
    REQUIRE(error.HasError());
    CHECK(error.GetError().mCode == EError::NonFinite);
    CHECK(error.GetError().mMessage == "x is NaN");
}

TEST_CASE("Result moves move-only values out", "[base]")
{
    Result<std::unique_ptr<int>> result = std::make_unique<int>(3);
    std::unique_ptr<int> taken = std::move(result).Get();
    REQUIRE(taken != nullptr);
    CHECK(*taken == 3);
}

TEST_CASE("Status reports success and failure", "[base]")
{
    CHECK(Status::Ok().IsValid());
    const Status failed = MakeError(EError::OutOfRange, "no such body");
    CHECK(failed.HasError());
    CHECK(std::string(ToString(failed.GetError().mCode)) == "out of range");
}
