// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <array>

namespace crumple::ffd
{

/// Uniform cubic B-spline basis weights for the four controls i..i+3 that influence a point with
/// lattice coordinate u = i + t (Hughes & Kaufman 1992 direct manipulation; D4MD, Ribeiro et al., eq. 1):
///   w0 = (1-t)^3/6, w1 = (3t^3 - 6t^2 + 4)/6, w2 = (-3t^3 + 3t^2 + 3t + 1)/6, w3 = t^3/6.
/// They sum to one (partition of unity) and reproduce linear functions: sum_k w_k (k - 1) = t.
/// @param[in] inT  local parameter in [0, 1]
/// @return {w0, w1, w2, w3}
inline std::array<double, 4> CubicBSplineWeights(double inT)
{
    // Horner forms of the four cubic pieces; written out so that the operation order is fixed. Inline: it
    // runs three times per vertex of every dent.
    const double t = inT;
    const double t2 = t * t;
    const double t3 = t2 * t;
    const double s = 1.0 - t;
    constexpr double cSixth = 1.0 / 6.0;
    return {s * s * s * cSixth, (3.0 * t3 - 6.0 * t2 + 4.0) * cSixth, (-3.0 * t3 + 3.0 * t2 + 3.0 * t + 1.0) * cSixth,
            t3 * cSixth};
}

} // namespace crumple::ffd
