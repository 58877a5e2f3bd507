// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// The account that decides when a refreshing solver refreshes its factor by cost (FactorRefreshLedger): rent
// or buy, with refreshes that bought nothing making the next one wait longer.
#include <crumple/fem/FactorRefreshLedger.h>

#include <catch2/catch.hpp>

using namespace crumple::fem;

namespace
{

// The racing fence's refresh in iterations (TetFactoredPreconditioner::GetRefreshCostInIterations: 5.66).
constexpr double cCost = 5.66;

} // namespace

TEST_CASE("FactorRefreshLedger: the iterations beyond two per solve add up to a refresh", "[fem]")
{
    FactorRefreshLedger ledger;
    ledger.FramesSet(false);
    // The first solve after the frames were set is at their own linearisation: free, however long.
    ledger.CountSolve(40);
    CHECK(ledger.GetExcess() == 0);
    // Solves within the base cost nothing.
    ledger.CountSolve(1);
    ledger.CountSolve(2);
    CHECK(ledger.GetExcess() == 0);
    CHECK_FALSE(ledger.ShouldRefresh(cCost));
    // Five iterations a solve cost three each: 3 < 5.66, 6 >= 5.66.
    ledger.CountSolve(5);
    CHECK(ledger.GetExcess() == 3);
    CHECK_FALSE(ledger.ShouldRefresh(cCost));
    ledger.CountSolve(5);
    CHECK(ledger.GetExcess() == 6);
    CHECK(ledger.ShouldRefresh(cCost));
    // New frames start a new account.
    ledger.FramesSet(false);
    CHECK(ledger.GetExcess() == 0);
    CHECK_FALSE(ledger.ShouldRefresh(cCost));
}

TEST_CASE(
    "FactorRefreshLedger: a refresh that bought nothing doubles the wait, up to eight refreshes' worth, "
    "and one that paid brings it back",
    "[fem]")
{
    FactorRefreshLedger ledger;
    ledger.FramesSet(false);
    // Pieces turning fast: every solve takes 4 (2 beyond the base) whatever the frames.
    const auto run_until_refresh = [&ledger](int inIterations)
    {
        int solves = 0;
        ledger.CountSolve(1); // the refreshed solve itself
        while (!ledger.ShouldRefresh(cCost) && solves < 1000)
        {
            ledger.CountSolve(inIterations);
            ++solves;
        }
        ledger.FramesSet(true);
        return solves;
    };
    CHECK(run_until_refresh(4) == 3); // 6 >= 5.66: the first refresh, judged by the solve after it
    CHECK(ledger.GetMultiplier() == 1);
    CHECK(run_until_refresh(4) == 6); // 4 cost as much as before: 11.32 to reach, 12 after six solves
    CHECK(ledger.GetMultiplier() == 2);
    CHECK(run_until_refresh(4) == 12); // 22.64: twelve
    CHECK(ledger.GetMultiplier() == 4);
    CHECK(run_until_refresh(4) == 23); // 45.28: 46 after 23
    CHECK(ledger.GetMultiplier() == 8);
    CHECK(run_until_refresh(4) == 23); // capped at eight
    CHECK(ledger.GetMultiplier() == 8);
    // A settling prop: after the refresh its solves take 3 (1 beyond the base) against 4 before: it paid.
    ledger.CountSolve(1);
    ledger.CountSolve(3);
    CHECK(ledger.GetMultiplier() == 1);
    CHECK(ledger.GetExcess() == 1);
}

TEST_CASE("FactorRefreshLedger: frames set by anything else are not judged", "[fem]")
{
    FactorRefreshLedger ledger;
    ledger.FramesSet(false);
    ledger.CountSolve(1);
    for (int solve = 0; solve < 8; ++solve)
        ledger.CountSolve(6);
    REQUIRE(ledger.ShouldRefresh(cCost));
    ledger.FramesSet(true);
    ledger.CountSolve(1);
    ledger.CountSolve(6); // bought nothing
    REQUIRE(ledger.GetMultiplier() == 2);
    // A crack or a long solve sets the frames: the solve after it does not judge the last refresh by cost.
    ledger.FramesSet(false);
    ledger.CountSolve(1);
    ledger.CountSolve(2);
    CHECK(ledger.GetMultiplier() == 2);
}
