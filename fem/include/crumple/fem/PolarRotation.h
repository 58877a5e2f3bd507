// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Math.h>

namespace crumple::fem
{

/// The rotation R of the polar decomposition F = R S (S symmetric), as the rotation that maximises tr(R^T F)
/// (Mueller, Bender, Chentanez & Macklin, "A robust method to extract the rotational part of deformations",
/// MIG 2016), iterated on the rotation group. Their step omega = sum_i r_i x f_i / (|sum_i r_i . f_i| + 1e-9)
/// converges only linearly (by a factor ~1/3 per iteration near F = R); where the Hessian tr(B) I - sym(B),
/// B = R^T F, is positive definite this uses the Newton step instead (quadratic convergence: one or two
/// iterations from the previous step's rotation) and falls back to theirs elsewhere. It always returns a unit
/// quaternion, also for inverted (det F < 0) or degenerate F, where it is the closest rotation the iteration
/// reaches; it is smooth in time when warm-started with the previous rotation, and deterministic (a fixed
/// sequence of operations).
/// @param[in] inF              deformation gradient, 3 by 3, finite
/// @param[in] inWarmStart      initial guess (the element's previous rotation, or identity)
/// @param[in] inMaxIterations  at most this many updates (>= 1); from identity, a random rotation with 50 %
///                             stretch converges to 1e-15 in under 10
/// @return R as a unit quaternion
CRUMPLE_API Quat PolarRotation(const Mat3& inF, const Quat& inWarmStart, int inMaxIterations = 40);

/// PolarRotation, and R as a matrix in outRotation: the returned quaternion's toRotationMatrix(), bit for
/// bit, taken from the last iteration where that ended without an update (most calls from a warm start), so
/// an element pass that needs both does not turn the quaternion into a matrix twice.
CRUMPLE_API Quat PolarRotation(const Mat3& inF, const Quat& inWarmStart, Mat3& outRotation,
                               int inMaxIterations = 40);

} // namespace crumple::fem
