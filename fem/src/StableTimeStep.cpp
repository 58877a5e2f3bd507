// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/StableTimeStep.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>

namespace crumple::fem
{

double StableTimeStep(std::span<const TetElementRest> inRest, const FemMaterial& inMaterial,
                      double inSafetyFactor)
{
    // Largest lambda_max(sum_a g_a g_a^T) over the elements: g_1..g_3 are the rows of D_m^-1,
    // g_0 = -(g_1 + g_2 + g_3).
    double max_gradient = 0.0;
    for (const TetElementRest& rest : inRest)
    {
        const Mat3& g = rest.mRestEdgeInverse; // rows are grad N_1..3
        const Vec3 g0 = -(g.row(0) + g.row(1) + g.row(2)).transpose();
        const Mat3 gram = g.transpose() * g + g0 * g0.transpose();
        Eigen::SelfAdjointEigenSolver<Mat3> eigen;
        eigen.computeDirect(gram, Eigen::EigenvaluesOnly);
        max_gradient = std::max(max_gradient, eigen.eigenvalues()[2]);
    }
    if (!(max_gradient > 0.0))
        return std::numeric_limits<double>::infinity();

    // omega_max bound, then the (damped) symplectic Euler limit.
    const double lambda = inMaterial.GetLambda();
    const double mu = inMaterial.GetShearModulus();
    const double modulus = std::max(3.0 * lambda + 2.0 * mu, 2.0 * mu); // lambda < 0 for nu < 0
    const double omega = std::sqrt(4.0 * modulus * max_gradient / inMaterial.GetSettings().mDensity);
    const double zeta = 0.5 * inMaterial.GetSettings().mStiffnessDamping * omega;
    const double limit = (2.0 / omega) * (std::sqrt(1.0 + zeta * zeta) - zeta);
    return inSafetyFactor * limit;
}

} // namespace crumple::fem
