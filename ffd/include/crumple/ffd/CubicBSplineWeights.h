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
std::array<double, 4> CubicBSplineWeights(double inT);

} // namespace crumple::ffd
