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

// The system's operator A.
LinearOperator3 Operator(const SpreadSystem& inSystem)
{
    return [&inSystem](std::span<const Vec3> inX, std::span<Vec3> outY)
    {
        for (std::size_t node = 0; node < inX.size(); ++node)
            outY[node] = inSystem.mDiagonal[node].cwiseProduct(inX[node]);
    };
}

// The inverse of a diagonal, as a preconditioner (the system's own: exact; ones: none).
LinearOperator3 InverseOf(const std::vector<Vec3>& inDiagonal)
{
    return [&inDiagonal](std::span<const Vec3> inX, std::span<Vec3> outY)
    {
        for (std::size_t node = 0; node < inX.size(); ++node)
            outY[node] = inX[node].cwiseQuotient(inDiagonal[node]);
    };
}

// The system solved to 1e-6 from zero with P = inPreconditionerDiagonal^-1 and inLongIterations; the
// solution in outX.
ConjugateGradientResult Solve(const SpreadSystem& inSystem, const std::vector<Vec3>& inPreconditionerDiagonal,
                              int inLongIterations, std::vector<Vec3>& outX)
{
    ConjugateGradientScratch scratch;
    outX.assign(inSystem.mDiagonal.size(), Vec3::Zero());
    return ConjugateGradient(Operator(inSystem), InverseOf(inPreconditionerDiagonal), inSystem.mRhs, 1.0e-6,
                             1000, outX, scratch, inLongIterations);
}

} // namespace

TEST_CASE("Conjugate gradient: a solve predicted to take longer than asked stops after two iterations",
          "[fem]")
{
    const SpreadSystem system = MakeSpreadSystem();
    const std::vector<Vec3> ones(system.mDiagonal.size(), Vec3::Ones());
    std::vector<Vec3> x;

    // No preconditioner, a limit of 6: the rate of the first two iterations predicts far more.
    const ConjugateGradientResult given_up = Solve(system, ones, 6, x);
    CHECK(given_up.mPredictedLong);
    CHECK_FALSE(given_up.mConverged);
    CHECK(given_up.mIterations == 2);

    // Without the limit the same solve runs to convergence, in more than 6 iterations: the prediction was
    // right.
    const ConjugateGradientResult full = Solve(system, ones, 0, x);
    CHECK(full.mConverged);
    CHECK_FALSE(full.mPredictedLong);
    CHECK(full.mIterations > 6);

    // The exact inverse converges in one iteration, below any prediction.
    const ConjugateGradientResult exact = Solve(system, system.mDiagonal, 6, x);
    CHECK(exact.mConverged);
    CHECK_FALSE(exact.mPredictedLong);
    CHECK(exact.mIterations == 1);
    for (std::size_t node = 0; node < x.size(); ++node)
        CHECK((system.mDiagonal[node].cwiseProduct(x[node]) - system.mRhs[node]).norm() <= 1.0e-12);
}

TEST_CASE("Conjugate gradient: a preconditioner that fits well enough is not given up", "[fem]")
{
    // The diagonal off by 30, -20 and 10 % per axis: three distinct eigenvalues, so CG ends in three
    // iterations although the first two are slow (0.22, then 0.012): the mean rate after two predicts 6.2
    // iterations and would give it up, the last iteration's (0.052) predicts 5.2 and lets it finish.
    const SpreadSystem system = MakeSpreadSystem();
    std::vector<Vec3> rough = system.mDiagonal;
    for (std::size_t node = 0; node < rough.size(); ++node)
        rough[node] = rough[node].cwiseProduct(Vec3(1.3, 0.8, 1.1));
    std::vector<Vec3> x;
    const ConjugateGradientResult result = Solve(system, rough, 6, x);
    CHECK(result.mConverged);
    CHECK_FALSE(result.mPredictedLong);
    CHECK(result.mIterations <= 6);
}
