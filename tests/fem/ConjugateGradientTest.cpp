// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// Conjugate gradient's early stop on a predicted long solve (inLongIterations): a poor preconditioner is
// given up after two iterations, a fitting one converges, and without the limit the solve runs to the end.
#include "ConjugateGradient.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

using namespace crumple;
using namespace crumple::fem;

namespace
{

// A diagonal SPD system over 40 nodes whose 120 entries spread from 1 to 1e4 (120 distinct eigenvalues:
// unpreconditioned CG needs many iterations), and a right-hand side that excites all of them.
struct SpreadSystem
{
    std::vector<Vec3> mDiagonal;
    std::vector<Vec3> mRhs;
};

SpreadSystem MakeSpreadSystem()
{
    SpreadSystem system;
    for (int node = 0; node < 40; ++node)
    {
        Vec3 entries;
        for (int axis = 0; axis < 3; ++axis)
            entries[axis] = std::pow(1.0e4, (3.0 * node + axis) / 119.0);
        system.mDiagonal.push_back(entries);
        system.mRhs.push_back(Vec3(1.0, -0.5, 0.25) + 0.01 * node * Vec3::Ones());
    }
    return system;
}

// The system's operator, and P = (the diagonal scaled by inScale per entry)^-1 (inScale = 1: the exact
// inverse; ones: no preconditioner).
LinearOperator3 Operator(const SpreadSystem& inSystem)
{
    return [&inSystem](std::span<const Vec3> inX, std::span<Vec3> outY)
    {
        for (std::size_t node = 0; node < inX.size(); ++node)
            outY[node] = inSystem.mDiagonal[node].cwiseProduct(inX[node]);
    };
}

LinearOperator3 InverseOf(const std::vector<Vec3>& inDiagonal)
{
    return [&inDiagonal](std::span<const Vec3> inX, std::span<Vec3> outY)
    {
        for (std::size_t node = 0; node < inX.size(); ++node)
            outY[node] = inX[node].cwiseQuotient(inDiagonal[node]);
    };
}

} // namespace

TEST_CASE("Conjugate gradient: a solve predicted to take longer than asked stops after two iterations",
          "[fem]")
{
    const SpreadSystem system = MakeSpreadSystem();
    const std::vector<Vec3> ones(system.mDiagonal.size(), Vec3::Ones());
    ConjugateGradientScratch scratch;
    std::vector<Vec3> x(system.mDiagonal.size(), Vec3::Zero());

    // No preconditioner, a limit of 6: the rate of the first two iterations predicts far more.
    const ConjugateGradientResult given_up =
        ConjugateGradient(Operator(system), InverseOf(ones), system.mRhs, 1.0e-6, 1000, x, scratch, 6);
    CHECK(given_up.mPredictedLong);
    CHECK_FALSE(given_up.mConverged);
    CHECK(given_up.mIterations == 2);

    // Without the limit the same solve runs to convergence, in more than 6 iterations: the prediction was
    // right.
    std::fill(x.begin(), x.end(), Vec3::Zero());
    const ConjugateGradientResult full =
        ConjugateGradient(Operator(system), InverseOf(ones), system.mRhs, 1.0e-6, 1000, x, scratch, 0);
    CHECK(full.mConverged);
    CHECK_FALSE(full.mPredictedLong);
    CHECK(full.mIterations > 6);

    // The exact inverse converges in one iteration, below any prediction.
    std::fill(x.begin(), x.end(), Vec3::Zero());
    const ConjugateGradientResult exact = ConjugateGradient(Operator(system), InverseOf(system.mDiagonal),
                                                            system.mRhs, 1.0e-6, 1000, x, scratch, 6);
    CHECK(exact.mConverged);
    CHECK_FALSE(exact.mPredictedLong);
    CHECK(exact.mIterations == 1);
    for (std::size_t node = 0; node < x.size(); ++node)
        CHECK((system.mDiagonal[node].cwiseProduct(x[node]) - system.mRhs[node]).norm() <= 1.0e-12);
}

TEST_CASE("Conjugate gradient: a preconditioner that fits well enough is not given up", "[fem]")
{
    // The diagonal off by up to 30 % per entry: a few iterations, each cutting the residual well below the
    // rate that a 6-iteration solve to 1e-6 needs (1e-1 per iteration).
    const SpreadSystem system = MakeSpreadSystem();
    std::vector<Vec3> rough = system.mDiagonal;
    for (std::size_t node = 0; node < rough.size(); ++node)
        rough[node] = rough[node].cwiseProduct(Vec3(1.3, 0.8, 1.1));
    ConjugateGradientScratch scratch;
    std::vector<Vec3> x(system.mDiagonal.size(), Vec3::Zero());
    const ConjugateGradientResult result =
        ConjugateGradient(Operator(system), InverseOf(rough), system.mRhs, 1.0e-6, 1000, x, scratch, 6);
    CHECK(result.mConverged);
    CHECK_FALSE(result.mPredictedLong);
    CHECK(result.mIterations <= 6);
}
