// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "ConjugateGradient.h"

#include <algorithm>
#include <cmath>

namespace crumple::fem
{

namespace
{

double Dot(std::span<const Vec3> inA, std::span<const Vec3> inB)
{
    double sum = 0.0;
    for (std::size_t i = 0; i < inA.size(); ++i)
        sum += inA[i].dot(inB[i]);
    return sum;
}

} // namespace

ConjugateGradientResult ConjugateGradient(const LinearOperator3& inOperator,
                                          const LinearOperator3& inPreconditioner,
                                          std::span<const Vec3> inRhs, double inTolerance,
                                          int inMaxIterations, std::span<Vec3> ioSolution,
                                          ConjugateGradientScratch& ioScratch, int inLongIterations)
{
    ConjugateGradientResult result;
    const std::size_t n = inRhs.size();
    ioScratch.mR.resize(n);
    ioScratch.mZ.resize(n);
    ioScratch.mP.resize(n);
    ioScratch.mAp.resize(n);
    std::vector<Vec3>& r = ioScratch.mR;
    std::vector<Vec3>& z = ioScratch.mZ;
    std::vector<Vec3>& p = ioScratch.mP;
    std::vector<Vec3>& ap = ioScratch.mAp;

    // Scale of the right-hand side in the preconditioner's norm: z = P b. With a zero initial guess r = b, and
    // this z is also the first preconditioned residual (one operator and one preconditioner application
    // saved: with a factored preconditioner a solve takes only a few iterations, so this is a third of it).
    inPreconditioner(inRhs, z);
    const double rhs_norm = std::sqrt(std::max(Dot(inRhs, z), 0.0));
    if (!(rhs_norm > 0.0))
    {
        // b = 0 (or invisible to P): x = 0 is the solution.
        for (Vec3& x : ioSolution)
            x.setZero();
        result.mConverged = true;
        return result;
    }

    // r = b - A x, z = P r, p = z.
    const bool zero_guess = std::all_of(ioSolution.begin(), ioSolution.end(),
                                        [](const Vec3& inX) { return inX.isZero(0.0); });
    if (zero_guess)
        std::copy(inRhs.begin(), inRhs.end(), r.begin());
    else
    {
        inOperator(ioSolution, ap);
        for (std::size_t i = 0; i < n; ++i)
            r[i] = inRhs[i] - ap[i];
        inPreconditioner(r, z);
    }
    p = z;
    double rz = Dot(r, z);
    double residual = std::sqrt(std::max(rz, 0.0)) / rhs_norm;

    while (residual > inTolerance && result.mIterations < inMaxIterations)
    {
        // Step along p to the minimum of the quadratic.
        inOperator(p, ap);
        const double curvature = Dot(p, ap);
        if (!(curvature > 0.0))
            break; // A is only semi-definite along p (or non-finite): no further progress possible
        const double alpha = rz / curvature;
        for (std::size_t i = 0; i < n; ++i)
        {
            ioSolution[i] += alpha * p[i];
            r[i] -= alpha * ap[i];
        }
        ++result.mIterations;

        // New conjugate direction.
        inPreconditioner(r, z);
        const double rz_new = Dot(r, z);
        const double beta = rz_new / rz;
        rz = rz_new;
        for (std::size_t i = 0; i < n; ++i)
            p[i] = z[i] + beta * p[i];
        const double last_residual = residual;
        residual = std::sqrt(std::max(rz, 0.0)) / rhs_norm;
        // At the last iteration's rate the solve would end after k + ln(tol / r_k) / ln(r_k / r_k-1)
        // iterations. The last rate, not the mean: CG speeds up as it works through the spectrum (a
        // preconditioner off by three factors converges in three iterations, the first two slow). A residual
        // that did not fall predicts no end at all.
        if (inLongIterations > 0 && result.mIterations >= 2 && residual > inTolerance)
        {
            const double rate = residual / last_residual;
            if (!(rate < 1.0) ||
                result.mIterations + std::log(inTolerance / residual) / std::log(rate) > inLongIterations)
            {
                result.mPredictedLong = true;
                break;
            }
        }
    }
    result.mRelativeResidual = residual;
    result.mConverged = residual <= inTolerance;
    return result;
}

} // namespace crumple::fem
