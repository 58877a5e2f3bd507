// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/base/TimeStep.h>

#include <catch2/catch.hpp>

#include <limits>
#include <string>

using namespace crumple;

TEST_CASE("CheckTimeStep: a finite step > 0 s passes, zero, negative and non-finite ones are named and refused",
          "[base]")
{
    CHECK(CheckTimeStep(1.0 / 240.0, "Solver::Step").IsValid());
    CHECK(CheckTimeStep(std::numeric_limits<double>::denorm_min(), "Solver::Step").IsValid());
    for (double bad : {0.0, -1.0 / 60.0})
    {
        const Status refused = CheckTimeStep(bad, "Solver::Step");
        REQUIRE_FALSE(refused.IsValid());
        CHECK(refused.GetError().mCode == EError::InvalidArgument);
        CHECK(refused.GetError().mMessage.rfind("Solver::Step: time step ", 0) == 0);
        CHECK(refused.GetError().mMessage.find("must be finite and > 0") != std::string::npos);
    }
    for (double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                       -std::numeric_limits<double>::infinity()})
    {
        const Status refused = CheckTimeStep(bad, "Solver::Prepare");
        REQUIRE_FALSE(refused.IsValid());
        CHECK(refused.GetError().mCode == EError::NonFinite);
    }
}
