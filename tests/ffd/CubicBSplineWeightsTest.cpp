// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/ffd/CubicBSplineWeights.h>

#include <catch2/catch.hpp>

using crumple::ffd::CubicBSplineWeights;

TEST_CASE("Cubic B-spline weights are a non-negative partition of unity", "[ffd]")
{
    for (int i = 0; i <= 1000; ++i)
    {
        const double t = i / 1000.0;
        const auto w = CubicBSplineWeights(t);
        CHECK(w[0] + w[1] + w[2] + w[3] == Approx(1.0).margin(1.0e-15));
        for (double wk : w)
            CHECK(wk >= 0.0);
    }
}

TEST_CASE("Cubic B-spline weights reproduce linear functions", "[ffd]")
{
    // Controls at (k - 1) give the point t: the FFD of an undeformed lattice is the identity.
    for (int i = 0; i <= 100; ++i)
    {
        const double t = i / 100.0;
        const auto w = CubicBSplineWeights(t);
        CHECK(-w[0] + w[2] + 2.0 * w[3] == Approx(t).margin(1.0e-15));
    }
}

TEST_CASE("Cubic B-spline weights match the published values at the knots", "[ffd]")
{
    const auto w0 = CubicBSplineWeights(0.0);
    const auto w1 = CubicBSplineWeights(1.0);
    CHECK(w0[0] == Approx(1.0 / 6.0));
    CHECK(w0[1] == Approx(4.0 / 6.0));
    CHECK(w0[2] == Approx(1.0 / 6.0));
    CHECK(w0[3] == 0.0);
    // C0 across a knot: weight k at t = 1 of cell i equals weight k+1 at t = 0 of cell i+1.
    CHECK(w1[0] == 0.0);
    for (int k = 0; k < 3; ++k)
        CHECK(w1[static_cast<std::size_t>(k) + 1] == Approx(w0[static_cast<std::size_t>(k)]).margin(1.0e-15));
    // t = 1/2: (1/48, 23/48, 23/48, 1/48).
    const auto half = CubicBSplineWeights(0.5);
    CHECK(half[0] == Approx(1.0 / 48.0));
    CHECK(half[1] == Approx(23.0 / 48.0));
    CHECK(half[2] == Approx(23.0 / 48.0));
    CHECK(half[3] == Approx(1.0 / 48.0));
}

TEST_CASE("Cubic B-spline weights are C1 across knots", "[ffd]")
{
    // One-sided finite differences of w_{k+1} at 0+ and w_k at 1- agree.
    const double h = 1.0e-6;
    const auto a0 = CubicBSplineWeights(0.0), a1 = CubicBSplineWeights(h);
    const auto b0 = CubicBSplineWeights(1.0 - h), b1 = CubicBSplineWeights(1.0);
    for (std::size_t k = 0; k < 3; ++k)
        CHECK((a1[k] - a0[k]) / h == Approx((b1[k + 1] - b0[k + 1]) / h).margin(1.0e-5));
}
