// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Math.h>

#include <functional>
#include <span>
#include <vector>

namespace crumple::fem
{

/// A symmetric positive (semi-)definite operator on #N 3-vectors: outY = A inX.
using LinearOperator3 = std::function<void(std::span<const Vec3> inX, std::span<Vec3> outY)>;

/// Outcome of ConjugateGradient.
struct ConjugateGradientResult
{
    int mIterations = 0;            ///< Iterations done
    double mRelativeResidual = 0.0; ///< |b - A x|_P / |b|_P at the end, |r|_P = sqrt(r^T P r); 0 when b = 0
    bool mConverged = false;        ///< mRelativeResidual <= the tolerance
    bool mPredictedLong = false;    ///< Stopped early: its rate so far said it would take more than
                                    ///< inLongIterations iterations
};

/// The vectors ConjugateGradient works in, kept by the caller so that repeated solves allocate nothing once
/// sized.
struct ConjugateGradientScratch
{
    std::vector<Vec3> mR, mZ, mP, mAp;
};

/// Preconditioned conjugate gradient (Shewchuk, "An introduction to the conjugate gradient method without the
/// agonizing pain", B3) for A x = b, matrix-free. It stops when the residual in the preconditioner's norm,
/// sqrt(r^T P r), falls below inTolerance x sqrt(b^T P b): with P ~ A^-1 that measures the energy of the
/// remaining error, so soft modes with small residuals (a stiff body's translation) are not hidden under
/// large stiff ones. Degrees of freedom that P, A, b and the initial value keep at zero stay zero (anchored
/// nodes). Serial dot products in node order: deterministic.
/// @param[in]     inOperator        A, symmetric positive definite on the free degrees of freedom
/// @param[in]     inPreconditioner  P ~ A^-1, symmetric positive definite on the free degrees of freedom
/// @param[in]     inRhs             b, #N
/// @param[in]     inTolerance       relative residual to stop at
/// @param[in]     inMaxIterations   at most this many iterations
/// @param[in,out] ioSolution        initial guess in, solution out, #N
/// @param[in,out] ioScratch         work vectors, resized to #N
/// @param[in]     inLongIterations  0, or: stop (mPredictedLong) once, from the second iteration on, the last
///                                  iteration's rate says the solve would need more iterations than this in
///                                  all, k + ln(tolerance / r_k) / ln(r_k / r_k-1) after k iterations (or
///                                  the residual did not fall), so that a caller with a better
///                                  preconditioner to build (a refreshed factor) builds it without first
///                                  spending the iterations the poor one would waste
ConjugateGradientResult ConjugateGradient(const LinearOperator3& inOperator,
                                          const LinearOperator3& inPreconditioner,
                                          std::span<const Vec3> inRhs, double inTolerance,
                                          int inMaxIterations, std::span<Vec3> ioSolution,
                                          ConjugateGradientScratch& ioScratch, int inLongIterations = 0);

} // namespace crumple::fem
